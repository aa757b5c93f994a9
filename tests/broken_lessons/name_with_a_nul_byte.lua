-- expect: 4: box 'left\0...': a name cannot hold a NUL byte (\0)
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "left\0right", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
