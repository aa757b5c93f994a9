-- expect: 3: 'io' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
local file = io.open("results.csv", "w")
