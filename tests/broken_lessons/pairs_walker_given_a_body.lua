-- expect: 6: the function pairs returns walks the table pairs was given, and is called by for ... in pairs(t); it was given a body handle
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
local walk = pairs({ a = 1 })
walk(block)
