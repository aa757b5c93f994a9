-- expect: 3: 'os' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local seed = os.time()
