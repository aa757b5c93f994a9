-- expect: 3: unexpected symbol near '='
lesson { title = "Broken", question = "What goes wrong?" }
local width = = 0.4
