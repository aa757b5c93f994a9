-- expect: 6: contact(a, b, k): k is a foot's number from the left, 1 to 3; got the number 4
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "wood" }
local floor = ground { material = "wood" }
local tripod = box { "tripod", material = "wood", width = 0.4, height = 0.1, feet = 3, on = floor, at = 0 }
local fourth = contact(tripod, floor, 4)
