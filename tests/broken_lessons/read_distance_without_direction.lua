-- expect: 5: probe 'distance': distance needs along = { dx, dy }, the direction it is measured in
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "distance", unit = "m", read = { block, "distance" } }
