-- expect: 4: box 'block': angle = 600000 ° is outside the allowed range [-360000, 360000]
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, x = 0, y = 1, angle = 600000 }
