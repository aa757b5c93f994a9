-- expect: 2: lesson: moment 2 needs a name first, as in { "sticking", at = 0.5 }
lesson { title = "Broken", question = "What goes wrong?", moments = { { "sticking", at = 0.5 }, { at = 1 } } }
