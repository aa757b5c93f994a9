-- expect: 2: moment 'sticking': at = -1 s is outside the allowed range [0, 86400]
lesson { title = "Broken", question = "What goes wrong?", moments = { { "sticking", at = -1 } } }
