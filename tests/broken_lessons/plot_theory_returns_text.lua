-- expect: 6: plot 'Motion': theory curve 'law' gave the text "fast" at t = 0; it must give y (a number), two numbers (a vertical segment) or nil
-- when: load
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
plot { "Motion", y = { "speed" }, theory = { { "law", function(t)
  return "fast" end } } }
