-- expect: 6: unknown probe
-- when: expectations
lesson { title = "Broken", question = "What goes wrong?" }
probe { "height", unit = "m", function() return 1 end }
expect { "highest", unit = "m", predicted = 1, tolerance = 0.1,
  measured = function() return history("hieght")[1] end }
