-- expect: 2: lesson: velocity_iterations = 0 is outside the allowed range [1, 1000]
lesson { title = "Broken", question = "What goes wrong?", duration = 2, velocity_iterations = 0 }
