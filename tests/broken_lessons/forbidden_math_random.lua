-- expect: 3: attempt to call a nil value (field 'random')
lesson { title = "Broken", question = "What goes wrong?" }
local mu_s = 0.3 + 0.4 * math.random()
