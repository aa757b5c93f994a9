-- expect: 4: box 'block': mass = 0 kg is outside the allowed range [1e-06, 1e+06]
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0, mass = 0 }
