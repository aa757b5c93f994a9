-- expect: 2: moment 'sticking': shows must be a function that returns true when the moment shows what its name says
lesson { title = "Broken", question = "What goes wrong?", moments = { { "sticking", at = 0.5, shows = true } } }
