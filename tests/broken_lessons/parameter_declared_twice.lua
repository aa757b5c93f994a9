-- expect: 4: parameter 'mass' is declared twice (first at
lesson { title = "Broken", question = "What goes wrong?" }
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg" }
local heavy = parameter { "mass", 5.0, min = 1, max = 50, unit = "kg" }
