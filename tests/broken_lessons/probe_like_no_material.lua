-- expect: 5: probe 'distance': like = "gras" is no material of this lesson (yet); its materials: wood
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { "distance", unit = "m", like = "gras", read = { block, "x" } }
