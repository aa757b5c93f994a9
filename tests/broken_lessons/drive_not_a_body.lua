-- expect: 3: drive's first entry (the body to move, as in drive{ belt, position = ... }) must be a body
lesson { title = "Broken", question = "What goes wrong?" }
drive { "belt", position = function(t) return 0.1 * t, 0.05 end }
