-- expect: 5: plot 'Motion': kind = "xy" needs x, the probe along the bottom, as in x = "push"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", kind = "xy", y = { "speed" } }
