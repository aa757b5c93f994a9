-- expect: 5: rope 'line': from and to are the same body; a rope joins two bodies
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local a = box { "a", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
rope { "line", from = a, at = { -0.2, 0 }, over = { 0, 2 }, to = a, to_at = { 0.2, 0 } }
