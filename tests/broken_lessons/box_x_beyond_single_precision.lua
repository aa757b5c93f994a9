-- expect: 4: box 'block': x = 1e+39 m is outside the allowed range [-100000, 100000]
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, x = 1e39, y = 1 }
