-- expect: 7: spring 'pull': the hand function (t -> x, y in m) returned the number 10000000000 as its first number at t = 0.5 s; it must return 2 finite numbers within ±1e9
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
spring { "pull", from = block, k = 50,
         to = function(t)
           if t < 0.5 then return 1, 0.1 end
           return 1e10, 0.1  -- meant 1e-10
         end }
