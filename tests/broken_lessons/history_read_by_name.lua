-- expect: 6: a history is read by step number, as in h[1] to h[#h]; got the text "last"
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
probe { "height", unit = "m", function() return 1 end }
expect { "height", unit = "m", predicted = 1, tolerance = 0.1,
  measured = function() return history("height")["last"] end }
