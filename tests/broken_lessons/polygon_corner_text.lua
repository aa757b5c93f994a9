-- expect: 4: polygon 'wedge': points must list 3 to 8 corners, as in points = { {0, 0}, {2, 0}, {2, 1} }; corner 2 is not
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
polygon { "wedge", material = "wood", points = { { 0, 0 }, "1, 0", { 1, 1 } }, x = 0, y = 1 }
