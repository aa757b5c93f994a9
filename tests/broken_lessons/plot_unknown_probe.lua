-- expect: 6: plot 'Motion': no probe is named 'sped'; probes: speed, and x may also be "time"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "speed", unit = "m/s", function() return block.vx end }
plot { "Motion", y = { "sped" } }
