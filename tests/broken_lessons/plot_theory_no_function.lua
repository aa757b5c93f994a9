-- expect: 5: plot 'Motion': theory curve 'law' needs a function of t second, returning y or nil where it does not apply; got the number 3
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", 3 } } }
