-- expect: 6: cannot negate a string: a string (text in quotes) takes part in arithmetic only if it reads as a number
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
force { "push", on = block, force = function(t) return -"hard", 0 end }
