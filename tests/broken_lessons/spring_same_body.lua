-- expect: 5: spring 'coil': from and to are the same body; a spring joins two bodies, or a body and a hand (to = function(t) ... end)
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
local a = box { "a", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
spring { "coil", from = a, at = { -0.2, 0 }, to = a, to_at = { 0.2, 0 }, k = 50 }
