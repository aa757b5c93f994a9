-- expect: 5: plot 'Motion': level 'top': unknown field 'colour'
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, levels = { { "top", function() return 1 end, colour = "red" } } }
