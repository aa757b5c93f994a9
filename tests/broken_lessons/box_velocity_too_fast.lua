-- expect: 4: box 'block': velocity = {3e+08, 0} must be within ±10000 m/s
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0, velocity = { 3e8, 0 } }
