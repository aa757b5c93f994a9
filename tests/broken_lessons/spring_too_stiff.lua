-- expect: 5: spring 'pull': stiffness k = 1e+06 N/m is too stiff for the step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0, mass = 1 }
spring { "pull", from = block, k = 1e6, to = function(t) return 1 + 0.1 * t, 0.1 end }
