-- expect: 7: plot 'Friction': x lists 1 probes and y 2; a list of x pairs each y with its own x, so give as many
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
probe { "friction", unit = "N", function() return 0 end }
probe { "drag", unit = "N", function() return 0 end }
plot { "Friction", kind = "xy", x = { "speed" }, y = { "friction", "drag" } }
