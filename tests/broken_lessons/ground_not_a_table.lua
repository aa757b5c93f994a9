-- expect: 3: ground takes a table, as in ground{ ... }; got the text "wood"
lesson { title = "Broken", question = "What goes wrong?" }
ground("wood")
