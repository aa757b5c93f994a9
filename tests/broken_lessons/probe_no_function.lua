-- expect: 3: probe 'speed': give it a function second, as in probe{ "speed", unit = "N", function() return ... end }, or read = { handle, "field" }; got nil
lesson { title = "Broken", question = "What goes wrong?" }
probe { "speed", unit = "m/s" }
