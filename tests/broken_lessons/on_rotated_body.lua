-- expect: 5: box 'top': on = bottom is turned (angle ≠ 0); on = a body needs it level; place this one with x, y and angle
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local bottom = box { "bottom", material = "wood", kind = "static", width = 1, height = 0.5, x = 0, y = 1, angle = 10 }
box { "top", material = "wood", width = 0.4, height = 0.2, on = bottom }
