-- expect: 5: plot 'Motion': level 'top' needs a function second
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, levels = { { "top", 1 } } }
