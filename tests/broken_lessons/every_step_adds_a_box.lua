-- expect: 6: box adds to the world; call it at the top level of the script, not from a function that runs during the lesson
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
every_step(function(t)
  box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = t }
end)
