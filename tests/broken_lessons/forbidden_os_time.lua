-- expect: 3: attempt to index a nil value (global 'os')
lesson { title = "Broken", question = "What goes wrong?" }
local seed = os.time()
