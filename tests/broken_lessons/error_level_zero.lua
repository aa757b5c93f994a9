-- expect: 3: no place given
lesson { title = "Broken", question = "What goes wrong?" }
error("no place given", 0)
