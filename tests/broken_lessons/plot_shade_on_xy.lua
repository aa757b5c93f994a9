-- expect: 6: plot 'Friction against speed': shade marks stretches of time; an X–Y plot colours its line by whether a contact slips instead, so leave shade out
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "speed", unit = "m/s", read = { block, "vx" } }
plot { "Friction against speed", kind = "xy", x = "speed", y = { "speed" }, shade = "speed" }
