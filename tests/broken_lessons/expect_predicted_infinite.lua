-- expect: 7: expect 'stopping distance': predicted gave infinity (as 1/0 gives); where theory has no number at these values, say why in words, as in predicted = "never slides"
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
local mu_k = 0
expect { "stopping distance", unit = "m", predicted = function() return 1 / (2 * mu_k * 9.81) end, measured = 0, tolerance = 0.01 }
