-- expect: 6: plot 'Friction': no probe is named 'sped'
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
probe { "speed", unit = "m/s", function() return 0 end }
probe { "friction", unit = "N", function() return 0 end }
plot { "Friction", kind = "xy", x = { "sped" }, y = { "friction" } }
