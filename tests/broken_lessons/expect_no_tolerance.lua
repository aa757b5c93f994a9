-- expect: 6: expect 'resting height': a number needs a tolerance >= 0 in its unit, as in tolerance = 0.05; got nil
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "resting height", unit = "m", predicted = 0.1, measured = function() return block.y end }
