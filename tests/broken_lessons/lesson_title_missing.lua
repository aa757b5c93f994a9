-- expect: 2: lesson: title must be text, as in lesson{ title = "..." }
lesson { question = "What goes wrong?" }
