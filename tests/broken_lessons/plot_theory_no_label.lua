-- expect: 5: plot 'Motion': theory curve 1 needs its label first
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { function(t) return t end } } }
