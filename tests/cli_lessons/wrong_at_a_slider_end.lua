-- A lesson whose expectation holds at its default and fails only with its slider at the top:
-- check passes, and check --random must find the setting and print the command that shows it.
lesson { title = "Wrong at a slider's end", question = "Does check --random notice?", duration = 0.1 }
local push = parameter { "push", 1, min = 0, max = 5, unit = "N", text = "a push nobody applies" }
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor }
expect { "push below its top",
  predicted = function() return "yes" end,
  measured = function() return push < 5 and "yes" or "no" end }
