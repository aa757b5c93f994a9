-- expect: 4: box 'block': width must be a number (m), got the text "0.4 m"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = "0.4 m", height = 0.2, on = floor, at = 0 }
