-- expect: 4: 'bx' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
bx { "block", material = "wood", width = 0.4, height = 0.2, x = 0, y = 1 }
