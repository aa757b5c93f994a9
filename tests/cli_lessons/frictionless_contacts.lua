-- Contacts with no friction (mu_s = mu_k = 0) neither stick nor slip: a box standing still on a
-- smooth floor is never probed as slipping, a box sliding along it is, and both contacts say
-- "frictionless". The listener's own state called both "slipping" from the first step.
lesson { title = "Frictionless contacts", question = "Is a box at rest on ice slipping?", duration = 0.5 }
pair { "ice", "ice", mu_s = 0, mu_k = 0 }
local floor = ground { material = "ice" }
local still = box { "still", material = "ice", width = 0.4, height = 0.2, on = floor, at = -2 }
local moving = box { "moving", material = "ice", width = 0.4, height = 0.2, on = floor, at = 2, velocity = { 1, 0 } }
local at_rest, sliding = contact(still, floor), contact(moving, floor)
probe { "still_slipping", read = { at_rest, "slipping" } }
probe { "moving_slipping", read = { sliding, "slipping" } }
local states = {}
every_step(function() states[at_rest.state .. " " .. sliding.state] = true end)
local function ever(name)
  local most = 0
  for _, v in ipairs(history(name)) do most = math.max(most, v) end
  return most
end
local function all_steps(name)
  local least = 1
  for _, v in ipairs(history(name)) do least = math.min(least, v) end
  return least
end
expect { "the box at rest slips at some step", predicted = function() return 0 end,
  measured = function() return ever("still_slipping") end, tolerance = 0 }
expect { "the sliding box slips at every step", predicted = function() return 1 end,
  measured = function() return all_steps("moving_slipping") end, tolerance = 0 }
expect { "what both contacts say", predicted = function() return "frictionless frictionless" end,
  measured = function()
    local seen = {}
    for k in pairs(states) do seen[#seen + 1] = k end
    return #seen == 1 and seen[1] or table.concat(seen, ", ")
  end }
