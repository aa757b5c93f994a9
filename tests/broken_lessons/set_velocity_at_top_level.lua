-- expect: 5: set_velocity works only inside an every_step function, between frames; a body's starting velocity is given where it is made, as in velocity = { 2, 0 }
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
block:set_velocity(2, 0)
