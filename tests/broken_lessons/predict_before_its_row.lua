-- expect: 4: predict 'late row': no expect row above it is named so
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
predict { "late row", question = "Asked too early?" }
expect { "late row", unit = "m", predicted = 0.1, measured = 0.1, tolerance = 0.001 }
