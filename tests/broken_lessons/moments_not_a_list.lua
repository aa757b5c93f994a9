-- expect: 2: lesson: moments must be a list of moments, as in moments = { { "sticking", at = 0.5 } }; got the text
lesson { title = "Broken", question = "What goes wrong?", moments = "sticking" }
