-- expect: 5: plot 'Motion': levels must be a list of levels
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, levels = function() return 1 end }
