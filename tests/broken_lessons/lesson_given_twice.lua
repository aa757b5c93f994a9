-- expect: 4: lesson{} is given twice (first at
lesson { title = "Broken", question = "What goes wrong?", duration = 2 }
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg" }
lesson { title = "Another", question = "Which one counts?" }
