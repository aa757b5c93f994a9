-- expect: 7: view takes one of follow = body, window = { left, bottom, right, top } or lanes = { body, ... }; it got none
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "wood" }
local a = box { "a", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, mass = 1 }
local b = box { "b", material = "wood", width = 0.2, height = 0.1, on = floor, at = 1, mass = 1 }
view { follow = nil }
