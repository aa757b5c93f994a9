-- expect: 3: incline 'slope': angle must be a number (°), got the text "30°"
lesson { title = "Broken", question = "What goes wrong?" }
incline { "slope", material = "wood", angle = "30°", length = 4 }
