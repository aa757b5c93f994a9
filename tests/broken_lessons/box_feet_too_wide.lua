-- expect: 3: box 'tripod': foot_width = 0.2 m is outside the allowed range [0.02, 0.1333
lesson { title = "Broken", question = "What goes wrong?" }
box { "tripod", material = "wood", width = 0.4, height = 0.1, feet = 3, foot_width = 0.2 }
