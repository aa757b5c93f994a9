-- expect: 2: moment 'sticking' is given twice
lesson { title = "Broken", question = "What goes wrong?",
  moments = { { "sticking", at = 0.5 }, { "slipping", at = 1 }, { "sticking", at = 2 } } }
