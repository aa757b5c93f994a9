-- expect: 7: 'slope' is not defined
-- when: load
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", function(t)
  return slope * t end } } }
