-- expect: 8: predict declares part of the lesson; call it at the top level of the script
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "resting height", unit = "m", predicted = 0.1, measured = function() return block.y end, tolerance = 0.001 }
expect { "moves or stays", predicted = "stays", measured = function() return "stays" end }
every_step(function() predict { "resting height", question = "How high?" } end)
