-- expect: 5: force 'push': at = {0, 1e+39} must be within ±10000 m
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
force { "push", on = block, at = { 0, 1e39 }, force = { 1, 0 } }
