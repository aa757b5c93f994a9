-- expect: 4: polygon 'stick': the corners must go round a convex shape in order, with no three in a line
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
polygon { "stick", material = "wood", points = { { 0, 0 }, { 1, 0 }, { 2, 0 } }, x = 0, y = 1 }
