-- expect: 3: 'dofile' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
dofile("lessons/incline.lua")
