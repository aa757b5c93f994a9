-- expect: 2: lesson: moment 'steep': set angel: no such parameter; parameters: angle
lesson { title = "Broken", question = "What goes wrong?", moments = { { "steep", at = 1, set = { angel = 40 } } } }
parameter { "angle", 20, min = 2, max = 60, unit = "°" }
