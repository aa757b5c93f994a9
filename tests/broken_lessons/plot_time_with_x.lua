-- expect: 6: plot 'Motion': a time plot's x is the time; leave x out, or say kind = "xy" to plot against push
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
probe { "push", unit = "N", function() return 0 end }
plot { "Motion", kind = "time", x = "push", y = { "speed" } }
