-- expect: 4: circle 'wheel': radius must be a number (m), got the text "big"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "rubber" }
circle { "wheel", material = "rubber", radius = "big", on = floor, at = 0 }
