-- expect: 4: 'getmetatable' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
getmetatable(floor).__gc = function() while true do end end
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
