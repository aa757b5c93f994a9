-- expect: 3: 'io' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local file = io.open("results.csv", "w")
