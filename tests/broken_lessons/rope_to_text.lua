-- expect: 5: rope 'line': to must be a body (what box{}, circle{}, ground{} and the others return), got the text "b"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local a = box { "a", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
rope { "line", from = a, to = "b", over = { 1, 1 } }
