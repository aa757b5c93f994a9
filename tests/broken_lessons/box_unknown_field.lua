-- expect: 4: box 'block': unknown field 'widht'; it takes material, width, height, x, y
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", widht = 0.4, height = 0.2, on = floor, at = 0 }
