-- expect: 5: box 'block': at = 7 m is outside the allowed range [0, 5]
lesson { title = "Broken", question = "What goes wrong?" }
local slope = incline { "slope", material = "wood", angle = 30, length = 5 }
-- 7 m up a 5 m slope would leave the block in mid-air.
box { "block", material = "wood", width = 0.4, height = 0.2, on = slope, at = 7 }
