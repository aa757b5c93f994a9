-- expect: 3: attempt to call a nil value (global 'dofile')
lesson { title = "Broken", question = "What goes wrong?" }
dofile("lessons/incline.lua")
