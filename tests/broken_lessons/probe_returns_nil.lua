-- expect: 7: probe 'speed' returned nil at t = 0.00416667 s; it must return a finite number
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
local speed
probe { "speed", unit = "m/s", function()
  return speed
end }
