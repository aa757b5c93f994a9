-- expect: 8: predict 'resting height': the row is predicted twice (first at
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "resting height", unit = "m", predicted = 0.1, measured = function() return block.y end, tolerance = 0.001 }
expect { "moves or stays", predicted = "stays", measured = function() return "stays" end }
predict { "resting height", question = "How high?" }
predict { "resting height", question = "How high, again?" }
