-- expect: 7: pair wood/wood: mu_k returned 2.01667 at t = 0.479167 s; it must be in [0, 2]
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
-- The error names the function's line, not the pair's: mu_k = 0.1 + 4·t passes the slider's 2
-- at t = 0.475 s, and the first step to start after that starts at 115/240 s.
pair { "wood", "wood", sliders = false, mu_s = 2,
  mu_k = function(t) return 0.1 + 4 * t end }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
