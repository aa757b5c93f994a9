-- expect: 5: spring 'pull': the hand function (t -> x, y in m) returned the text "1, 0.1" as its first number at t = 0 s; it must return 2 finite numbers within ±1e9
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
spring { "pull", from = block, k = 50, to = function(t) return "1, 0.1" end }
