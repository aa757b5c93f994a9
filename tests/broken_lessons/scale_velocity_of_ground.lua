-- expect: 5: body 'ground': only a body that moves freely (dynamic) has a velocity to set
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
every_step(function(t) floor:scale_velocity(0.5) end)
