-- expect: 3: parameter takes a table, as in parameter{ ... }; got the text "mass"
lesson { title = "Broken", question = "What goes wrong?" }
local mass = parameter("mass", 1.0)
