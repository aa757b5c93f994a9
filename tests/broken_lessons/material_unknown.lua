-- expect: 4: unknown material 'woood'
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
box { "block", material = "woood", width = 0.4, height = 0.2, x = 0, y = 1 }
