-- expect: 4: box 'block': velocity x = 3e+08 m/s is outside the allowed range [-10000, 10000]
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0, velocity = { 3e8, 0 } }
