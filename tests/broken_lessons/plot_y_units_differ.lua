-- expect: 7: plot 'Motion': its y probes distance (m) and speed (m/s) differ in unit, and one axis has one scale; give each unit a plot of its own
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "distance", unit = "m", read = { block, "distance", along = { 1, 0 } } }
probe { "speed", unit = "m/s", read = { block, "vx" } }
plot { "Motion", y = { "distance", "speed" } }
