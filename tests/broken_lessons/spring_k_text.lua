-- expect: 5: spring 'pull': k must be a number (N/m), got the text "stiff"
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
spring { "pull", from = block, k = "stiff", to = function(t) return 1 + 0.1 * t, 0.1 end }
