-- friction_models: the spring article's three friction models side by side. Three identical
-- blocks are launched together on three lanes and slide to rest. On the first lane friction is
-- Coulomb's, mu_k·N whatever the speed; on the second the engineering model adds viscous drag
-- c·v; on the third a quadratic term b·v². Each block traces its law's friction against speed
-- from the launch speed down to 0, where all three meet Coulomb's jump: at v = 0 friction can
-- be anything from −mu_s·N to +mu_s·N.

-- Theory for one lane: the slide to rest under mu_k·N + c·v + b·v².
local function rest(c, b)
  return theory.slide_to_rest { v0 = param.launch_speed, mass = param.mass, mu_s = param.mu_s, mu_k = param.mu_k,
                                c = c, b = b }
end

lesson {
  title = "Three friction models, one launch",
  question = "Coulomb, Coulomb + c·v, Coulomb + b·v²: which block stops first, and how does each law slow it?",
  -- Half a second after the last block has stopped (Coulomb's, which has no drag to help).
  -- (At most 15 s, which the slowest slide allowed, mu_k = 0.05 at 5 m/s (10.2 s), fits.)
  duration = function() return math.min(rest(0, 0).time + 0.5, 15) end,
  order = 16,
  moments = {
    { "all_sliding", at = 0.2, readme = true,
      shows = function() return value_at("coulomb_slipping", time()) == 1 and value_at("quadratic_slipping", time()) == 1 end },
    { "drag_stopped_first", at = 0.6,
      shows = function() return value_at("engineering_slipping", time()) == 0 and value_at("coulomb_slipping", time()) == 1 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local launch_speed = parameter { "launch_speed", 2, min = 0.2, max = 5, unit = "m/s", text = "launch speed" }
local mass = parameter { "mass", 1, min = 0.1, max = 10, unit = "kg", text = "mass of each block" }
-- One mu_s and one mu_k for all three lanes, so only the drag differs. They are the lesson's own
-- parameters, handed to the three pairs below, so moving one restarts the launch.
local mu_s = parameter { "mu_s", 0.5, min = 0, max = 2, text = "static friction coefficient (all lanes)" }
-- From 0.05: with no kinetic friction the Coulomb block would never stop, and nothing would be compared.
local mu_k = parameter { "mu_k", 0.3, min = 0.05, max = 2, text = "kinetic friction coefficient (all lanes)" }
local c = parameter { "c", 4, min = 0, max = 50, unit = "N·s/m", text = "viscous drag c (engineering lane)" }
local b = parameter { "b", 4, min = 0, max = 50, unit = "N·s²/m²", text = "quadratic drag b (quadratic lane)" }

material { "block", density = 500, note = "the mass is set on each block" }
material { "coulomb_lane", density = 1000, note = "fixed, so its density plays no part" }
material { "engineering_lane", density = 1000, note = "fixed" }
material { "quadratic_lane", density = 1000, note = "fixed" }
-- sliders = false: the pairs take the lesson's own mu_s, mu_k, c and b instead of making four
-- sliders each. The blocks ride separate lanes and never meet, but block on block needs values.
pair { "block", "coulomb_lane", mu_s = mu_s, mu_k = mu_k, sliders = false }
pair { "block", "engineering_lane", mu_s = mu_s, mu_k = mu_k, c = c, sliders = false }
pair { "block", "quadratic_lane", mu_s = mu_s, mu_k = mu_k, b = b, sliders = false }
pair { "block", "block", mu_s = mu_s, mu_k = mu_k, sliders = false }

-- World -----------------------------------------------------------------------------------
-- Three lanes 0.45 m apart, each floor 0.2 m thick, so the block below clears the floor above.
-- The blocks are three times as wide as tall: up to mu_k = 2 they cannot pitch over their front
-- edge as friction slows them (friction's moment mu_k·N·h/2 against N·w/2).
local lanes, blocks = {}, {}
for i, model in ipairs { "coulomb", "engineering", "quadratic" } do
  local floor = ground { model .. "_floor", material = model .. "_lane", y = 0.9 - 0.45 * (i - 1), thickness = 0.2 }
  local block = box { model, material = "block", width = 0.3, height = 0.1, on = floor, at = 0, mass = mass,
                      velocity = { launch_speed, 0 } }
  lanes[model], blocks[i] = contact(block, floor), block
  probe { model .. "_speed", unit = "m/s", read = { block, "vx" } }
  probe { model .. "_friction", unit = "N", read = { lanes[model], "fx" } }  -- dry and drag: all the floor does
  probe { model .. "_distance", unit = "m", read = { block, "distance", along = { 1, 0 } } }
  probe { model .. "_slipping", read = { lanes[model], "slipping" } }
end

-- A strip per lane, each on its block, all with one scale and one stretch of floor.
view { lanes = blocks }

-- Probes and plots ------------------------------------------------------------------------
plot { "Speed of each block", kind = "time", y = { "coulomb_speed", "engineering_speed", "quadratic_speed" } }
-- Friction against speed over each lane's law: −(mu_k·N + c·v + b·v²) while it slides, and at
-- v = 0 anything from −mu_s·N to +mu_s·N (the vertical line): Coulomb's jump.
local N = mass * g
local function law(drag_c, drag_b)
  return function(v)
    if v > 0 then return -(mu_k * N + drag_c * v + drag_b * v * v) end
    if v == 0 then return -mu_s * N, mu_s * N end
  end
end
plot { "Friction against speed", kind = "xy",
  x = { "coulomb_speed", "engineering_speed", "quadratic_speed" },  -- each block against its own speed
  y = { "coulomb_friction", "engineering_friction", "quadratic_friction" },
  theory = { { "Coulomb: −μk·N", law(0, 0) }, { "engineering: −μk·N − c·v", law(c, 0) },
             { "quadratic: −μk·N − b·v²", law(0, b) } } }

-- Reading the record ----------------------------------------------------------------------
-- A block stopped during the first step that ends with its floor gripping it; that step began
-- one step_length() earlier. Nothing yet while it still slides.
local function stop(model)
  local times, slipping, distances = history("time"), history(model .. "_slipping"), history(model .. "_distance")
  for i = 1, #times do
    if slipping[i] == 0 then return { time = times[i] - step_length(), distance = distances[i] } end
  end
  return {}
end

-- Expectations ----------------------------------------------------------------------------
-- The drag's rate at the launch, Γ = (c + 2b·v0)/m: how fast it takes the speed away there.
local function launch_rate(drag_c, drag_b) return (drag_c + 2 * drag_b * launch_speed) / mass end
local function too_coarse(drag_c, drag_b)
  local gamma_h = launch_rate(drag_c, drag_b) * step_length()
  if gamma_h > 1 then return string.format("step too long for this drag: Γ·h = %.3g > 1", gamma_h) end
end
-- The slide with dry friction q = Γh/(1 − e^(−Γh)) times stronger: over a step the world's dry
-- friction takes off mu_k·g·h where the exact motion under drag takes mu_k·g·(1 − e^(−Γh))/Γ
-- (the drag is taken off before each step, so the speed friction removes escapes that step's
-- drag). The stopping time's allowance.
local function harder(drag_c, drag_b)
  local gamma_h = launch_rate(drag_c, drag_b) * step_length()
  local q = gamma_h > 0 and gamma_h / (1 - math.exp(-gamma_h)) or 1
  return theory.slide_to_rest { v0 = launch_speed, mass = mass, mu_k = q * mu_k, c = drag_c, b = drag_b }
end
-- The slide the world's steps make, taken as the world takes them (h the sub-step): the scene
-- starts the leapfrog at 2·v0 less a trial half step from v0; each step then takes the drag
-- off by its exact solution over the step (physics' damped_velocity: v·e^(−c·h/m), or
-- v/(1 + b·v·h/m)), then dry friction's mu_k·g·h, which stops the block where it would turn
-- it back; and moves the block by h times the speed it ends the step with. Kept for the
-- values it was worked out at: a tolerance is read often.
local function dragged(v, drag_c, drag_b, dt)
  if drag_c > 0 then return v * math.exp(-drag_c * dt / mass) end
  return v / (1 + drag_b * v * dt / mass)
end
local stepped_slides = {}
local function stepped(drag_c, drag_b)
  local h = substep_length()
  local key = table.concat({ launch_speed, mass, mu_k, drag_c, drag_b, h }, " ")
  if stepped_slides[key] then return stepped_slides[key] end
  local trial = math.max(0, dragged(launch_speed, drag_c, drag_b, h / 2) - mu_k * g * h / 2)
  local v, distance = 2 * launch_speed - trial, 0
  -- At most the run's 15 s of steps: mu_k >= 0.05 stops every launch the sliders allow in it.
  for _ = 1, math.ceil(15 / h) do
    v = dragged(v, drag_c, drag_b, h) - mu_k * g * h
    if v <= 0 then break end
    distance = distance + h * v
  end
  stepped_slides[key] = distance
  return distance
end
for _, lane in ipairs { { "coulomb", 0, 0 }, { "engineering", c, 0 }, { "quadratic", 0, b } } do
  local model, drag_c, drag_b = lane[1], lane[2], lane[3]
  expect { model .. ": stopping distance", unit = "m",
    predicted = function() return too_coarse(drag_c, drag_b) or rest(drag_c, drag_b).distance end,
    measured = function() return too_coarse(drag_c, drag_b) or stop(model).distance end,
    -- The step: the world's slide is the stepped one above (its own discrete process, start,
    -- drag, dry friction and the stop in its last step), so the step's term is that slide's
    -- distance against theory's, whatever Γ·h is: the first-order terms this row had (dry
    -- friction's q = Γh/(1 − e^(−Γh)) and the leapfrog start's Γ·h²·v0/4) and the (Γh)² of the
    -- slide it added for what they left (issue 29: a coefficient not derived) are all in it.
    -- (What they left is the midpoint rule's, each step moving the block by h times its
    -- mid-step speed, h³·v''/24 a step, Γ·h²·v0/24 over the slide, and the start's next order.)
    -- The solver: while the block slides, none (friction is clamped at mu_k times the normal
    -- impulse, the block's weight on a level floor). The step it stops in is the exception: the
    -- map ends it at rest, the world where the solver's iterations leave friction short of its
    -- clamp, a velocity under what the step's friction can take, mu_k·g·h, either way (the block
    -- brings less than that into the step, and friction only slows it): h times that, mu_k·g·h²
    -- (seen: up to 3e-8 m on a 1 mm slide, 6e-7 m/s left on a 10 kg block at mu_k 2).
    -- And single precision (floats, 2^-24 of the magnitudes per operation;
    -- theory is double), in place of the 1 % this row had (issue 29): each step rounds the
    -- block's position by 2^-24 of its distance from where it started (the world's x = 0), and
    -- its speed in the drag's exact step and the two contact points' warm start (the iterations
    -- leave a friction at its clamp as it is), 3 operations of 2^-24 of the speed, carried on:
    -- the distance by up to their sum over the slide, n·t/2 times a step's.
    tolerance = function()
      local distance = rest(drag_c, drag_b).distance
      local steps = math.ceil(rest(drag_c, drag_b).time / substep_length())
      local rounding = steps * 2 ^ -24 * distance + 3 * 2 ^ -24 * launch_speed * steps * rest(drag_c, drag_b).time / 2
      return math.abs(stepped(drag_c, drag_b) - distance) + mu_k * g * substep_length() ^ 2 + rounding
    end }
  expect { model .. ": stopping time", unit = "s",
    predicted = function() return too_coarse(drag_c, drag_b) or rest(drag_c, drag_b).time end,
    measured = function() return too_coarse(drag_c, drag_b) or stop(model).time end,
    -- A stop is placed to within a step, and on a drag lane dry friction's q-fold strength
    -- (above) ends the slide sooner. And single precision: the speed's rounding carried over
    -- the slide (3 operations of 2^-24 of the speed a step, as above) moves the stop by that
    -- over the deceleration there, mu_k·g (a 10 s slide at mu_k 0.05 and 1000 Hz: 2 ms early).
    tolerance = function()
      local steps = math.ceil(rest(drag_c, drag_b).time / substep_length())
      local speed_rounding = 3 * 2 ^ -24 * launch_speed * steps
      return step_length() + rest(drag_c, drag_b).time - harder(drag_c, drag_b).time + speed_rounding / (mu_k * g)
    end }
end

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "coulomb: stopping time", unit = "s",
  question = "How long does the block with dry friction only (Coulomb) take to stop?" }
predict { "quadratic: stopping time", unit = "s",
  question = "And the block that also feels drag growing with its speed squared?" }
