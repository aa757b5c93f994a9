-- expect: 5: block
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 1 }
