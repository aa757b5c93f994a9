-- expect: 3: probe 'p': give a function written in the script
lesson { title = "Broken", question = "What goes wrong?" }
probe { "p", unit = "m", math.sin }
