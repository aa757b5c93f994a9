-- expect: 4: box 'top': on = ball has no flat top face (only a box or a polygon has one); place this one with x and y
lesson { title = "Broken", question = "What goes wrong?" }
local ball = circle { "ball", material = "wood", radius = 0.3, kind = "static", x = 0, y = 1 }
box { "top", material = "wood", width = 0.4, height = 0.2, on = ball }
