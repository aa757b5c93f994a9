-- expect: 7: predict_number_for_a_word.lua:6) gives "stays"; give choices = { ... } for a row answered in words
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "resting height", unit = "m", predicted = 0.1, measured = function() return block.y end, tolerance = 0.001 }
expect { "moves or stays", predicted = "stays", measured = function() return "stays" end }
predict { "moves or stays", question = "How far does it move?" }
