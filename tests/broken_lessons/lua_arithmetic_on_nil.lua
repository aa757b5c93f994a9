-- expect: 4: 'widht' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local width = 0.4
local half = widht / 2
