-- expect: 4: param is read-only, rawset included: parameters change from the sliders or with --set NAME=VALUE
lesson { title = "Broken", question = "What goes wrong?" }
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg" }
rawset(param, "mass", 2)
