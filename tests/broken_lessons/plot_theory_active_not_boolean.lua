-- expect: 6: plot 'Motion': theory curve 'law': active gave the number 1; it must give true (the branch applies now) or false
-- when: load
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", function(t) return t end, active = function()
  return 1 end } } }
