-- expect: 4: param.mu: no such parameter; parameters: mass
lesson { title = "Broken", question = "What goes wrong?" }
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg" }
local friction = param.mu * mass * g
