-- expect: 5: plot 'Speed': no probe is named 'slipping'; probes: speed, and x may also be "time"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
plot { "Speed", kind = "time", y = { "speed" }, shade = "slipping" }
probe { "speed", unit = "m/s", read = { block, "vx" } }
