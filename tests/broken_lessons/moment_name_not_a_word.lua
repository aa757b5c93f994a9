-- expect: 2: moment 'mid slip': a moment's name is one word of letters, digits and _
lesson { title = "Broken", question = "What goes wrong?", moments = { { "mid slip", at = 1.2 } } }
