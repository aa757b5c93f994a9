-- expect: 5: force 'push': force must be a pair of numbers such as {0.5, 0} (N), got the number 10
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
force { "push", on = block, force = 10 }
