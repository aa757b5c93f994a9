-- expect: 2: lesson: moment 'steep': set angle = 90 ° is outside the allowed range [2, 60]
lesson { title = "Broken", question = "What goes wrong?", moments = { { "steep", at = 1, set = { angle = 90 } } } }
parameter { "angle", 20, min = 2, max = 60, unit = "°" }
