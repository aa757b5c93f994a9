-- expect: 7: 'rate' is not defined
-- when: plots
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", function(t)
  if t > 2 then return rate * t end return 0 end } } }
