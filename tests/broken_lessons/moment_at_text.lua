-- expect: 2: moment 'sticking': at must be a number (s), got
lesson { title = "Broken", question = "What goes wrong?",
  moments = { { "sticking", at = "soon" } } }
