-- expect: 6: contact(a, b, k) reads one foot of a body on feet (box{ ..., feet = n }); neither of these has feet
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "wood" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.1, on = floor, at = 0 }
local touch = contact(block, floor, 1)
