-- expect: 6: set_velocity: vy must be a number, got the text "fast"
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
every_step(function(t) block:set_velocity(1, "fast") end)
