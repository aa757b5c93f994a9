-- expect: 6: set_velocity: vx = inf m/s is outside the allowed range [-10000, 10000]
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
every_step(function(t) block:set_velocity(math.huge, 0) end)
