-- expect: 3: attempt to call a nil value (global 'load')
lesson { title = "Broken", question = "What goes wrong?" }
local f = load("return 1")
