-- expect: 5: box 'top': at
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local bottom = box { "bottom", material = "wood", width = 0.6, height = 0.3, on = floor, at = 0 }
box { "top", material = "wood", width = 0.2, height = 0.1, on = bottom, at = 0.5 }
