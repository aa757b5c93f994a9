-- expect: 4: polygon 'arrow': the corners must go round a convex shape in order, with no three in a line
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
polygon { "arrow", material = "wood", x = 0, y = 1,
          points = { { 0, 0 }, { 1, 0 }, { 0.2, 0.2 }, { 0, 1 } } }
