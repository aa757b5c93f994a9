-- expect: 3: 'load' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
local f = load("return 1")
