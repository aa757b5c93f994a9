-- expect: 3: 'dofile' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
dofile("lessons/incline.lua")
