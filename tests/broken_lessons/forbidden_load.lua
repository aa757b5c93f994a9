-- expect: 3: 'load' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local f = load("return 1")
