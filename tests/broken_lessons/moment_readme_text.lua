-- expect: 2: moment 'sticking': readme must be true or false, got the text
lesson { title = "Broken", question = "What goes wrong?", moments = { { "sticking", at = 0.5, readme = "yes" } } }
