-- expect: 3: box 'tripod': feet = 20 is outside the allowed range [2, 16]
lesson { title = "Broken", question = "What goes wrong?" }
box { "tripod", material = "wood", width = 0.4, height = 0.1, feet = 20 }
