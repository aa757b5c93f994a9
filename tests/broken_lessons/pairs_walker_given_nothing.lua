-- expect: 4: the function pairs returns walks the table pairs was given, and is called by for ... in pairs(t); it was given nil
lesson { title = "Broken", question = "What goes wrong?" }
local walk = pairs({ a = 1 })
walk()
