-- expect: 3: box takes a table
lesson { title = "Broken", question = "What goes wrong?" }
table.sort({ 1, 2, 3 }, box)
