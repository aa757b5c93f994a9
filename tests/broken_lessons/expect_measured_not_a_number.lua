-- expect: 6: expect 'resting height': measured gave not a number (NaN, as 0/0 gives); a reading must be a finite number, or a word saying why there is none, as in "still sliding"
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "resting height", unit = "m", predicted = 0.1, measured = function() return block.y * 0 / 0 end, tolerance = 0.001 }
