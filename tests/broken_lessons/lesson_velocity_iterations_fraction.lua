-- expect: 4: lesson: velocity_iterations must be a whole number, from 1 to 1000
-- The contact solver passes a step whole times: 2.5 is a slip of the finger.
local g = 9.81
lesson { title = "Broken", question = "What goes wrong?", duration = 2, velocity_iterations = 2.5 }
