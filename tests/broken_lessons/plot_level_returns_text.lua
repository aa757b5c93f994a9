-- expect: 6: plot 'Motion': level 'top' gave the text "high"; it must give y (a number) or nil
-- when: load
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, levels = { { "top", function()
  return "high" end } } }
