-- expect: 6: 'mas' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }
local mass = parameter { "mass", 1, min = 0.1, max = 10, unit = "kg" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0, mass = mas }
