-- expect: 5: contact needs two different bodies, as in contact(block, floor)
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
local touch = contact(block, block)
