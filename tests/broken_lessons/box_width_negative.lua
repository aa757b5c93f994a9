-- expect: 4: width = -0.4 m is outside the allowed range [0.02, 1000]
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = -0.4, height = 0.2, on = floor, at = 0 }
