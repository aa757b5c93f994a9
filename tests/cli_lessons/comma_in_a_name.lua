-- A probe whose name holds a comma and a quote: its CSV column is a quoted field.
lesson { title = "Names with commas", question = "Does the CSV keep one column per value?", duration = 0.05 }
local floor = ground { material = "wood" }
local block = box { "left,right", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { 'say "hi", twice', function() return 1 end }
expect { "runs", predicted = "yes", measured = "yes" }
