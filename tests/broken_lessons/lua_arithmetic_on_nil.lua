-- expect: 4: attempt to perform arithmetic on a nil value (global 'widht')
lesson { title = "Broken", question = "What goes wrong?" }
local width = 0.4
local half = widht / 2
