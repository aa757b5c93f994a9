-- A lesson that breaks half-way through: `run --csv` must exit 2 and leave no CSV behind.
lesson { title = "Breaks while running", question = "Is the CSV left half-written?", duration = 1 }
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor }
probe { "height", unit = "m", function() if time() > 0.5 then return "high" end return block.y end }
