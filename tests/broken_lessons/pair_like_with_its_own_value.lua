-- expect: 6: pair metal/ice: like = takes every value from the other pair; give no c
lesson { title = "Broken", question = "What goes wrong?" }
-- A pair that shares another's values takes all of them, the coefficients (physics/materials.h's
-- table) and the sliders alike; a treatment of its own is still its own.
pair { "metal", "wood", mu_s = 0.5, mu_k = 0.4 }
pair { "metal", "ice", c = 2, like = { "metal", "wood" }, treatment = "regularized" }
local floor = ground { material = "wood" }
box { "block", material = "metal", width = 0.4, height = 0.2, on = floor, at = 0 }
