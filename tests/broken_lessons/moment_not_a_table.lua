-- expect: 2: lesson: moment 1 must be a table such as { "sticking", at = 0.5 }; got the text
lesson { title = "Broken", question = "What goes wrong?", moments = { "sticking", at = 0.5 } }
