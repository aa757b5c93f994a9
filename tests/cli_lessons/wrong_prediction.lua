-- A lesson whose expectation is wrong on purpose: `check` must exit 1 for it.
lesson { title = "A wrong prediction", question = "Does check notice?", duration = 0.5 }
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor }
expect { "height of the block", unit = "m", predicted = 1.0, measured = function() return block.y end, tolerance = 0.01 }
