-- A body and a probe whose names hold a comma and a quote: their CSV columns are quoted fields.
lesson { title = "Names with commas", question = "Does the CSV keep one column per value?", duration = 0.05 }
local floor = ground { material = "wood" }
local block = box { "left,right", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
probe { 'say "hi", twice', function() return 1 end }
expect { "runs", predicted = "yes", measured = "yes" }
