-- driven_wheel: friction can act in the direction of motion (the friction-situations article's
-- FAQ). A motor turns a wheel on a road; the wheel pushes back on the road at the contact, and
-- the road's friction pushes the wheel forward: it is the only forward force, and all that
-- speeds the wheel up. Rolling without slipping, friction is m·a (static, as much as rolling
-- needs), up to the traction limit; past it the tyre spins on the road and kinetic friction,
-- mu_k·m·g, still forward, takes over. The motor winds up over the first second, as a driver
-- presses the pedal, so a run that passes the limit shows where.
-- The article's simplest case, torque > mu_s·N·r, is a wheel with no inertia of its own. A real
-- wheel (here a solid disc, I = m·r²/2) needs part of the torque to spin itself up, so it grips
-- up to 1.5 times that: torque = mu_s·g·(I + m·r²)/r.

local function ramp(t) return math.min(math.max(t, 0), 1) end  -- share of the full torque at t
-- The wheel touches the road at its rim: the world is built to the script's sizes (the road's
-- contact point lies r from the axle), so theory takes the wheel's radius as the friction's
-- lever arm, and the disc's inertia, m·r²/2.
local function wheel_theory(torque)
  return theory.driven_wheel { mass = param.mass, radius = param.radius, torque = torque,
                               inertia = 0.5 * param.mass * param.radius ^ 2, mu_s = param.mu_s, mu_k = param.mu_k }
end
local function limit() return wheel_theory(0).traction_limit end
-- When the motor's torque reaches the traction limit (nil if it never does).
local function spin_start()
  if param.torque <= limit() then return nil end
  return limit() / param.torque
end

lesson {
  title = "A motor turns a wheel",
  question = "Which way does the road's friction push a driven wheel, and what happens when the motor is too strong?",
  duration = 2,
  order = 37,
  moments = {
    { "gripping", at = 0.4, shows = function() return value_at("slipping", time()) == 0 end },
    { "spinning", at = 1.5, readme = true, shows = function() return value_at("slipping", time()) == 1 end },
    { "gentle_motor", at = 1.5, set = { torque = 5 }, shows = function() return value_at("slipping", time()) == 0 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local torque = parameter { "torque", 12, min = 0, max = 20, unit = "N·m", text = "the motor's full torque, reached at 1 s" }
local mass = parameter { "mass", 2, min = 0.5, max = 10, unit = "kg", text = "mass of the wheel" }
local radius = parameter { "radius", 0.3, min = 0.1, max = 0.5, unit = "m", text = "radius of the wheel" }

-- A rubber tyre on asphalt, dry.
pair { "rubber", "asphalt", mu_s = 0.9, mu_k = 0.7, sliders = { "mu_s", "mu_k" } }

-- World -----------------------------------------------------------------------------------
local road = ground { "road", material = "asphalt" }
local wheel = circle { "wheel", material = "rubber", radius = radius, on = road, at = 0, mass = mass }
-- Clockwise, the way that rolls it to the right (torques are counter-clockwise positive).
local motor = force { "motor", on = wheel, torque = function(t) return -torque * ramp(t) end }
view { follow = wheel }

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(wheel, road)
probe { "torque", unit = "N·m", read = { motor, "torque", scale = -1 } }
probe { "friction_force", unit = "N", read = { touch, "fx" } }  -- positive: forward
probe { "acceleration", unit = "m/s²", read = { wheel, "acceleration", along = { 1, 0 } } }
probe { "spin", unit = "rad/s", read = { wheel, "omega", scale = -1 } }  -- rolling forward
probe { "speed", unit = "m/s", read = { wheel, "vx" } }
probe { "slipping", read = { touch, "slipping" } }

plot { "The road's friction on the wheel", kind = "xy", x = "torque", y = { "friction_force" },
  theory = {
    { "gripping: m·a", function(T) if T <= limit() then return wheel_theory(T).friction end end,
      active = function() return touch.slipping ~= 1 end },
    { "spinning: μk·m·g", function(T) if T >= limit() then return param.mu_k * param.mass * g end end,
      active = function() return touch.slipping == 1 end },
  } }
-- Gripping, the rim turns as fast as the axle moves (ω·r = v); spinning, it runs ahead.
probe { "rim_speed", unit = "m/s", read = { wheel, "omega", scale = -radius } }
plot { "Speed of the axle and of the tyre's rim", kind = "time", y = { "speed", "rim_speed" } }

-- Reading the record ----------------------------------------------------------------------
-- With no friction at all (mu_s = mu_k = 0) nothing holds the contact, so it neither sticks nor
-- slips: it reads "slipping" only while the tyre slides on the road faster than the contact's
-- threshold; a slip counts once the rim's speed parts from the axle's at all (ahead, under a
-- motor; either way, the comparison does not care), whatever the flag says
-- (10 kg on a 0.1 m wheel at 0.001 N·m: the rim 3.5×10⁻⁸ m/s ahead after the second step, the
-- flag a step later, and the torque read a step of the ramp late).
local function first_slip_torque()
  local slipping, torques = history("slipping"), history("torque")
  local frictionless = param.mu_s == 0 and param.mu_k == 0
  local rims, axles = history("rim_speed"), history("speed")
  for i = 1, #slipping do
    if (frictionless and rims[i] ~= axles[i]) or (not frictionless and slipping[i] == 1) then
      return i > 1 and torques[i - 1] or 0
    end
  end
end
local function at_the_end(probe) return reached(2) and value_at(probe, 2) or nil end
-- ∫ ramp(t) dt from a to b: the torque's time integral in units of the full torque.
local function ramp_integral(a, b)
  local function up_to(t) if t <= 1 then return t * t / 2 end return 0.5 + (t - 1) end
  return up_to(b) - up_to(a)
end
-- The wheel's spin at the end of the run, from theory: rolling, ω = v/r with a in step with the
-- torque; spinning from t_s, ω(t_s) plus (torque − mu_k·m·g·r)/I over the rest of the run.
local function spin_at_end()
  local inertia = 0.5 * param.mass * param.radius ^ 2
  local per_torque = 1 / (inertia + param.mass * param.radius ^ 2)  -- rolling: α per N·m
  local start = spin_start()
  if not start then return per_torque * param.torque * ramp_integral(0, 2) end
  return per_torque * param.torque * ramp_integral(0, start)
         + (param.torque * ramp_integral(start, 2) - param.mu_k * param.mass * g * param.radius * (2 - start)) / inertia
end
-- Box2D turns a body at most a quarter turn a step, which caps its spin at (π/2)/h.
local function too_fast()
  if spin_at_end() > 0.8 * (math.pi / 2) / step_length() then return "too fast for Box2D" end
end

-- Half way to the limit (or at 0.5 s), the wheel grips: the road pushes it forward with m·a.
-- On a step, so that the sample read there is the one meant.
local function gripping_time()
  local h = step_length()
  return math.max(1, math.floor(math.min(0.5, (spin_start() or 2) / 2) / h + 0.5)) * h
end
-- The axle's speed at the end of the run, from theory: rolling, ω·r; spinning from t_s, its
-- speed then plus mu_k·g over the rest of the run.
local function speed_at_end()
  local per_torque = 1 / (1.5 * param.mass * param.radius ^ 2)
  local start = spin_start()
  if not start then return per_torque * param.torque * ramp_integral(0, 2) * param.radius end
  return per_torque * param.torque * ramp_integral(0, start) * param.radius + param.mu_k * g * (2 - start)
end

-- What the rows allow (issue 29: derived, not a flat share).
-- * The step. The motor's torque is asked at the start of each step and held through it, and
--   the contact reads the step's mean: the gripping friction is m·a of the torque asked a step
--   before its reading, as theory is asked, and the accelerations at the end (the change of the
--   velocity over the last step, over h) are exact, the torque full and constant by then. The
--   slip shows at the end of the step it began in, and the row reads the torque that step
--   applied: the first past the limit, so up to one step's growth of the torque, torque·h,
--   above it. And the listener may hold that first step a step more: a stuck contact asked for
--   up to its hold band past mu_s·N (2 %) whose step looks like the solver's leftover is watched
--   for a step, and breaks away at the next, the excess having grown (physics/
--   treatment_stick_slip.cpp): a second step's growth. (7.47 kg, r 0.37 m, mu_s 0.446, mu_k
--   0, 20 N·m: the step whose torque took the friction 9e-5 of mu_s·N past it held, and the
--   slip read 18.25 N·m against 18.17, a step and 0.0017 N·m past; so at 960 Hz.) With --substeps the torque is asked every sub-step: the frame's recorded torque
--   is its first sub-step's, up to a frame's growth below the one that slipped, and the
--   frame's friction is the sub-steps' mean, up to that growth's share of the friction past
--   theory's (0.5 kg, r 0.32 m, 9.86 N·m, mu_s 1.3, 2 sub-steps: 3.164 N read, 3.122 N theory).
-- * The solver: none. A disc's contact normal runs through its centre, so the friction and the
--   normal constraints do not couple: gripping, the one friction constraint stops the contact
--   point in one turn; spinning, it is clamped at mu_k times the normal impulse, the weight.
-- * Single precision (floats, 2^-24 of the magnitudes involved per operation; theory is
--   double). In a step the wheel's velocity and spin are changed by the integration, the
--   contact point's warm start and 8 iterations of friction and normal, 19 operations (1 + 9·k,
--   k = 2), with the mass, radius and torque rounded once each: 22. A rate read as the change
--   over the last step keeps only that step's: 22·2^-24 of the speed (or spin) and of its
--   change, over h. The gripping friction is an impulse over h that stops the contact point,
--   whose speed is the difference of the axle's and the rim's: the mass times that for each,
--   and 22·2^-24 of the forces of the step (the friction and the weight). The slip's decision
--   compares the friction with mu_s·N to as many operations: that share of the limit, and the
--   friction it compares carries the contact point's rounding as the gripping friction does,
--   at the speed the wheel has reached by then. Its torque's worth is that friction times
--   (I + m·r²)/(m·r) = 1.5·r, the torque per newton of friction while gripping. (0.5 kg, r
--   0.423 m, 6.915 N·m, mu_s 0.724, at 7.6 m/s: 1.5e-3 N·m; the world slipped a step after the
--   first past the limit, which that step had passed by 2.7e-5 N·m, over the 7.6e-6 N·m the
--   decision's own share allowed.)
local operations = 22
local function allowed()
  local h = step_length()
  local function rate_rounding(value, rate) return operations * 2 ^ -24 * (math.abs(value) / h + math.abs(rate)) end
  -- The gripping friction's rounding, rolling at `speed` with acceleration `rate`.
  local function grip_rounding(speed, rate) return param.mass * 2 * rate_rounding(speed, rate) end
  local grip_speed = wheel_theory(param.torque * ramp(gripping_time() - h)).acceleration * gripping_time()
  local start = spin_start()
  local speed_at_start = start and wheel_theory(param.torque).acceleration * ramp_integral(0, start) or 0
  local at_the_limit = start and grip_rounding(speed_at_start, wheel_theory(limit()).acceleration) * 1.5 * param.radius or 0
  return {
    -- The recorded torque's rounding is of the torque read, a step's ramp past the limit.
    limit = 2 * param.torque * h + operations * 2 ^ -24 * (limit() + param.torque * h) + at_the_limit,
    friction = grip_rounding(grip_speed, wheel_theory(param.torque).acceleration)
               + operations * 2 ^ -24 * (param.mass * g + wheel_theory(param.torque).friction)
               + (substep_length() < h and wheel_theory(param.torque * h).friction or 0),
    acceleration = rate_rounding(speed_at_end(), wheel_theory(param.torque).acceleration),
    spin_up = rate_rounding(spin_at_end(), wheel_theory(param.torque).angular_acceleration),
  }
end

-- Expectations ----------------------------------------------------------------------------
expect { "traction limit", unit = "N·m",
  predicted = function() return too_fast() or spin_start() and limit() or "not reached" end,
  measured = function()
    -- A spin Box2D cannot reach ends rolling too: the rim slips where the cap holds it back
    -- (8.6 kg, r 0.1 m, 20 N·m, mu_s 2 at 60 Hz: "passed" where theory's wheel never slips).
    if too_fast() then return too_fast() end
    if not spin_start() then
      if first_slip_torque() then return "passed" end
      -- Not reached only once the run is over (before Play: not yet).
      return reached(2) and "not reached" or nil
    end
    return first_slip_torque()
  end,
  tolerance = function() return allowed().limit end }
-- The contact reads the step just taken, which the torque asked at its start drove.
local function short_grip()
  if gripping_time() < 4 * step_length() then return "grips too briefly" end
end
expect { "friction while gripping, forward", unit = "N",
  predicted = function()
    return short_grip() or wheel_theory(param.torque * ramp(gripping_time() - step_length())).friction
  end,
  measured = function()
    if short_grip() then return short_grip() end
    return time() >= gripping_time() and value_at("friction_force", gripping_time()) or nil
  end,
  tolerance = function() return allowed().friction end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "friction while gripping, forward", unit = "N",
  question = "Halfway to the moment the tyre starts to spin (half a second in if it never does), how hard does the road push the wheel forward (a minus sign for backward)?" }
expect { "acceleration at the end", unit = "m/s²",
  predicted = function() return too_fast() or wheel_theory(param.torque).acceleration end,
  measured = function() return too_fast() or at_the_end("acceleration") end,
  tolerance = function() return allowed().acceleration end }
expect { "spin-up at the end", unit = "rad/s²",
  predicted = function() return too_fast() or wheel_theory(param.torque).angular_acceleration end,
  measured = function()
    if too_fast() then return too_fast() end
    if not reached(2) then return nil end
    local spins = history("spin")
    if #spins < 2 then return nil end
    return (spins[#spins] - spins[#spins - 1]) / step_length()
  end,
  tolerance = function() return allowed().spin_up end }
