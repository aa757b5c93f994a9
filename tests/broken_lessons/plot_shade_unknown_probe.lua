-- expect: 5: plot 'Speed': shade names no probe 'slipping'; probes: speed (a contact's slipping, say)
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
plot { "Speed", kind = "time", y = { "speed" }, shade = "slipping" }
probe { "speed", unit = "m/s", read = { block, "vx" } }
