-- expect: 5: plot 'Motion': theory curve 'law': unknown field 'activ'
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", function(t) return t end, activ = function() return true end } } }
