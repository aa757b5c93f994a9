-- expect: 3: incline 'slope': angle = 90 ° is outside the allowed range (0, 80]
lesson { title = "Broken", question = "What goes wrong?" }
incline { "slope", material = "wood", angle = 90, length = 4 }
