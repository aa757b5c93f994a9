-- expect: 3: attempt to index a nil value (global 'io')
lesson { title = "Broken", question = "What goes wrong?" }
local file = io.open("results.csv", "w")
