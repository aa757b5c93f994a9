-- expect: 7: attempt to perform arithmetic on a nil value (global 'rate')
-- when: plots
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", function(t)
  if t > 2 then return rate * t end return 0 end } } }
