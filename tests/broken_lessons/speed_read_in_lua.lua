-- expect: 6: a body's speed needs a direction
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "speed", unit = "m/s", function() return block.speed end }
