-- expect: 2: moment 'sticking': unknown field 'when'; it takes at, set, theme, shows, readme
lesson { title = "Broken", question = "What goes wrong?", moments = { { "sticking", at = 0.5, when = 1 } } }
