-- expect: 6: plot 'Speed': shade must be a probe's name, as in shade = "top_slipping"; got the text ""
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "speed", unit = "m/s", read = { block, "vx" } }
plot { "Speed", kind = "time", y = { "speed" }, shade = "" }
