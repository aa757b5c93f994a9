-- expect: 7: 'rate' is not defined
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
local push = force { "push", on = block, force = function(t)
  if t >= 0.5 then return rate * t, 0 end
  return 0, 0
end }
probe { "push", unit = "N", function() return push.fx end }
