-- expect: 2: lesson: order must be a number, got the text
lesson { title = "Broken", question = "What goes wrong?", order = "first" }
