-- expect: 3: 'os' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
local seed = os.time()
