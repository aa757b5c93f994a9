-- expect: 5: plot 'Motion': kind must be "time" (probes against time) or "xy" (probes against the probe x); got "line"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", kind = "line", y = { "speed" } }
