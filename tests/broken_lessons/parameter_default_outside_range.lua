-- expect: 3: parameter 'mass': default = 20 kg is outside the allowed range [0.1, 10]
lesson { title = "Broken", question = "What goes wrong?" }
local mass = parameter { "mass", 20, min = 0.1, max = 10, unit = "kg" }
