-- expect: 3: box 'tripod': foot_width and foot_height go with feet = n
lesson { title = "Broken", question = "What goes wrong?" }
box { "tripod", material = "wood", width = 0.4, height = 0.1, foot_width = 0.03 }
