-- expect: 2: moment 'sticking': theme must be "light" or "dark", got "pink"
lesson { title = "Broken", question = "What goes wrong?", moments = { { "sticking", at = 0.5, theme = "pink" } } }
