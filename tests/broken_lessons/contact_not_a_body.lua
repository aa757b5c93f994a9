-- expect: 5: contact's second argument must be a body (what box{}, circle{}, ground{} and the others return), got the text "floor"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
local touch = contact(block, "floor")
