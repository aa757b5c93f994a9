-- expect: 3: the script raised an error that is not a message (a table)
lesson { title = "Broken", question = "What goes wrong?" }
error({ reason = "a table, not a message" })
