-- expect: 5: plot 'Motion': level 1 needs its label first
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, levels = { { function() return 1 end } } }
