-- expect: 6: expect 'sticks or slides': measured gave the number 0.5 but predicted gave a word
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "sticks or slides", predicted = "sticks", measured = function() return 0.5 end }
