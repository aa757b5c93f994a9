-- expect: 6: expect 'stopping distance': predicted gave nil; it must be a number, a word such as "slides", or true/false
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "stopping distance", unit = "m", predicted = function() end, measured = 0, tolerance = 0.01 }
