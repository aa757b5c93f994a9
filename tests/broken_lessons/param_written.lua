-- expect: 4: param is read-only
lesson { title = "Broken", question = "What goes wrong?" }
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg" }
param.mass = 2
