-- expect: 2: moment 'steep': set angle must be a number or a choice in quotes, got
lesson { title = "Broken", question = "What goes wrong?", moments = { { "steep", at = 1, set = { angle = true } } } }
parameter { "angle", 20, min = 2, max = 60, unit = "°" }
