-- expect: 4: plot 'Motion': y must be a probe's name or a list of them, as in y = { "spring_force" }
lesson { title = "Broken", question = "What goes wrong?" }
probe { "height", unit = "m", function() return 0 end }
plot { "Motion", y = 3 }
