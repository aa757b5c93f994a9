-- expect: 7: box adds to the world; call it at the top level of the script
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
-- spring{} asks for the hand at t = 0 while the script is still being built.
spring { "pull", from = block, k = 50, to = function(t)
  box { "extra", material = "wood", width = 0.4, height = 0.2, x = 3, y = 1 }
  return 1, 0.1
end }
