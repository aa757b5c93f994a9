-- expect: 3: every_step takes a function, as in every_step(function(t) ... end); got a table
lesson { title = "Broken", question = "What goes wrong?" }
every_step { function(t) end }
