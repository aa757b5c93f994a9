-- A row whose measured function says in words why it has no number yet: render draws it
-- before and after the number comes, and check measures it at the end.
lesson { title = "Word before the number", question = "?", duration = 1 }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "time", unit = "s", predicted = 1, tolerance = 0.01,
  measured = function() if time() < 0.9 then return "still waiting" end return time() end }
