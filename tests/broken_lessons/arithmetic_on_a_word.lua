-- expect: 5: cannot multiply a number and a string: a string (text in quotes) takes part in arithmetic only if it reads as a number
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local width = "wide"
box { "block", material = "wood", width = 2 * width, height = 0.2, on = floor, at = 0 }
