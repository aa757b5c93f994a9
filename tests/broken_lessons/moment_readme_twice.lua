-- expect: 2: moment 'slipping': readme = true is given to moment 'sticking' already; a lesson has one README frame
lesson { title = "Broken", question = "What goes wrong?",
  moments = { { "sticking", at = 0.5, readme = true }, { "slipping", at = 1, readme = true } } }
