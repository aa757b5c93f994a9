-- lubricated: the friction-situations article's changing coefficient. A block on a table is
-- pulled by a constant force; for a while the table is oiled (lubricated intermittently), so
-- its coefficients drop and then come back. In each stretch they are constant, and the block
-- does what Coulomb's law says with the values of that stretch: held while the pull is at most
-- mu_s·N, sliding at a = (pull − mu_k·N)/m otherwise, and, slowed on the dry table again, it
-- stops and sticks. The pair's coefficients here change with time (a schedule of values), read
-- at the start of every step.

-- When the oil comes and goes (no oil if lubricated_until is not after lubricated_from): set
-- below from the parameters, which restart the lesson when they change, so the pair's
-- schedules and theory read the same two numbers.
local oil_from, oil_gone
local function oiled(t) return t >= oil_from and t < oil_gone end
-- The coefficients change at the start of the first world step at or after each instant: the
-- instants theory is given, so that it describes the run as stepped.
local function on_a_step(t)
  local h = substep_length()
  return math.ceil(t / h - 1e-9) * h
end

local mass = 1  -- kg: the pull sets the story, and six sliders fit a projector's column
local function slide(t)
  return theory.intermittent_slide { mass = mass, pull = param.pull,
    dry = { mu_s = param.mu_s, mu_k = param.mu_k },
    lubricated = { mu_s = param.lubricated_mu, mu_k = param.lubricated_mu },
    from = on_a_step(oil_from), ["until"] = on_a_step(oil_gone), t = t }
end
-- Theory holds a block whose pull is exactly mu·m·g; the solver starts a contact slipping once
-- friction is within 10⁻⁵ of its limit, so it cannot tell equality from a hair past it. Within
-- 10⁻⁴ of either surface's limit the rows say so.
local function on_threshold()
  for _, limit in ipairs { math.max(param.mu_s, param.mu_k), param.lubricated_mu } do
    local force = limit * mass * g
    if force > 0 and math.abs(param.pull - force) <= 1e-4 * force then return "on the threshold: either" end
  end
end
-- Until a second after the block has stopped on the dry table again (at most 8 s after the oil
-- is gone), or 2 s after the oil if it never stops.
local function run_length()
  local after = slide(oil_gone)
  local a = (param.pull - param.mu_k * mass * g) / mass
  if after.speed > 0 and a < 0 then return oil_gone + math.min(after.speed / -a + 1, 8) end
  return oil_gone + 2
end

lesson {
  title = "A table oiled for a while",
  question = "A pull too weak to move the block: what happens while the table is oiled, and after?",
  duration = run_length,
  order = 18,
  moments = {
    { "held_dry", at = 0.8, shows = function() return value_at("slipping", time()) == 0 end },
    { "sliding_on_oil", at = 1.8, readme = true, shows = function() return value_at("slipping", time()) == 1 end },
    { "stopped_dry_again", at = 4.2,
      shows = function() return value_at("slipping", time()) == 0 and value_at("distance", time()) > 0.1 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local pull = parameter { "pull", 3, min = 0, max = 50, unit = "N", text = "the constant pull on the 1 kg block" }
-- Wood on wood, dry (the tribology article's 0.25 to 0.50) and with a film of oil.
local mu_s = parameter { "mu_s", 0.5, min = 0, max = 2, text = "dry: static coefficient" }
local mu_k = parameter { "mu_k", 0.45, min = 0, max = 2, text = "dry: kinetic coefficient" }
-- A film of oil carries the load: what little friction is left hardly tells starting from
-- sliding, so one coefficient serves for both while oiled.
local lubricated_mu = parameter { "lubricated_mu", 0.1, min = 0, max = 2, text = "oiled: static and kinetic coefficient" }
local lubricated_from = parameter { "lubricated_from", 1, min = 0, max = 10, unit = "s", text = "the oil comes at" }
local lubricated_until = parameter { "lubricated_until", 2, min = 0, max = 10, unit = "s",
                                     text = "the oil is gone at (no oil if not after the start)" }

oil_from, oil_gone = lubricated_from, math.max(lubricated_from, lubricated_until)

-- The pair's coefficients change with time: the oiled values while oiled. Each is a schedule,
-- { { time, value }, ... }, from each time on its value: the same as the function
--   function(t) if oiled(t) then return lubricated_mu end return mu_s end
-- which the runtime would call every step, a quarter of this lesson's time; the schedule it
-- reads itself. No sliders of its own (the parameters above set it), and no drag, which the
-- closed form leaves out.
local function while_oiled(dry, oiled_value)
  return { { 0, dry }, { oil_from, oiled_value }, { oil_gone, dry } }
end
pair { "wood", "wood", sliders = false, mu_s = while_oiled(mu_s, lubricated_mu), mu_k = while_oiled(mu_k, lubricated_mu) }

-- World -----------------------------------------------------------------------------------
local table_top = ground { "table", material = "wood" }
-- Pulled at its centre, the pull has no moment about the centre of mass, and friction's
-- mu·N·h/2 about it tips the block only past mu = w/h = 4: it slides for every mu up to 2.
local block = box { "block", material = "wood", width = 0.4, height = 0.1, on = table_top, at = 0, mass = mass }
force { "pull", on = block, force = { pull, 0 } }
view { follow = block }

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(block, table_top)
probe { "friction_force", unit = "N", read = { touch, "fx" } }  -- negative: it holds the block back
probe { "speed", unit = "m/s", read = { block, "vx" } }
probe { "acceleration", unit = "m/s²", read = { block, "acceleration", along = { 1, 0 } } }
probe { "distance", unit = "m", read = { block, "distance", along = { 1, 0 } } }
probe { "slipping", read = { touch, "slipping" } }  -- 1 while the block slides

-- Friction as theory has it: it answers the pull while the block is held, and is −mu_k·N of the
-- moment's surface while it slides.
local function friction_theory(t)
  if not slide(t).sliding then return -param.pull end
  return -(oiled(t) and param.lubricated_mu or param.mu_k) * mass * g
end
plot { "Friction on the block", kind = "time", y = { "friction_force" },
  theory = { { "Coulomb, dry then oiled then dry", friction_theory } } }
plot { "Speed of the block", kind = "time", y = { "speed" },
  theory = { { "piecewise closed form", function(t) return slide(t).speed end } } }

-- Expectations ----------------------------------------------------------------------------
-- Where the run cannot show what theory describes at t, the row says so: the block has slid
-- off the table's end (200 m from where it stood, less its half width), or it moves more than
-- Box2D lets a body move in one step (b2_maxTranslation, 2 m), which caps its speed.
local function out_of_reach(t)
  local state = slide(t)
  if state.distance > 200 - 0.2 then return "off the table by then" end
  if state.speed * step_length() > 2 then return "too fast for Box2D" end
end
local function word(t) return on_threshold() or out_of_reach(t) end

-- The instant the rows read at the end belong to: value_at's sample, the step nearest the
-- run's length (the later of two as near), up to half a step from it. Theory is read there
-- too: at 38.81 N on the dry table with mu_k 0 and the oil gone at 0.3067 s, theory at
-- 2.3067 s was 0.065 m/s short of the world read at 2.3083 s.
local function end_sample()
  local h = step_length()
  return math.floor(run_length() / h + 0.5) * h
end
-- What the rows allow (issue 29: derived, not a flat share). Theory is given the instants the
-- world's coefficients change (on_a_step), so between them both have the same constant
-- acceleration, and the world's velocity at every step's end is theory's. What is left:
-- * The step. Box2D moves the block each step with the velocity it has at the step's end, so
--   where the velocity is theory's at every step boundary and straight between them, the
--   world's distance is the trapezoid sum of theory's plus h·(v(t) − v(0))/2: half a step
--   ahead (v(0) = 0, and stretches start on steps). A stop falls inside a step, which the
--   world ends at rest: it then covers up to d·h²/2 less or more than the exact slide's last
--   part, d the deceleration there (friction_models' `last`).
-- * A breakaway on the dry table: its step is held (at up to mu_s·N) and the next gives back
--   the speed mu_k would have left since the limit was crossed, which the treatment finds by
--   interpolating the margin between two steps. Where the limit jumps (at t = 0, or the oil
--   gone under a block stopped on it) the crossing is only known to a step: the speed may be
--   off by up to that step's change, (pull − mu_k·m·g)/m·h, and the friction held past mu_k·N,
--   (mu_s − mu_k)·g·h, from then on; the distance by that times the time since (and the held
--   step). (mu_s 0 under mu_k 0.55, pull 10.9 N, the oil gone at 3.45 s: 0.023 m/s, a step's
--   change.) On the oil mu_s = mu_k, and a block breaks away there with no held excess.
-- * The solver: none. On a level table friction does not move the block across it, so each
--   iteration's normal impulse is the block's weight and the friction at its clamp is mu_k·m·g.
-- * Single precision (floats, 2^-24 of the magnitudes involved per operation; theory is
--   double). A reading of the acceleration differences two velocities a step apart: only that
--   step's operations on the velocity along the table are left in it, the pull's integration,
--   the two contact points' friction in the warm start and in each of 8 iterations (19), with
--   the mass and pull rounded once, of the speed and of the step's change, over h. Speed and
--   distance keep every step's rounding: sliding at the clamp, the velocity is rounded by the
--   integration and the warm start (3 a step, of the speed; the iterations leave a friction at
--   its clamp as it is, and all 19 round no more than the step's change), each step's position
--   by 2^-24 of the block's distance from where it started (the world's origin), and the
--   speed's rounding carried on moves the distance by up to its sum over the run.
-- With --substeps all of this is per sub-step, h = substep_length(), and theory's instants are
-- on sub-steps too.
local function allowed()
  local h, t_end = substep_length(), end_sample()
  local steps = math.floor(t_end / h + 0.5)
  -- The speed is straight between the stretches' ends, so its largest is at one of them; the
  -- pull never turns the block back, so its farthest is at the end.
  local fastest, far = 0, slide(t_end).distance
  for _, t in ipairs { oil_from, oil_gone, t_end } do fastest = math.max(fastest, slide(math.min(t, t_end)).speed) end
  local dry_limit = math.max(param.mu_s, param.mu_k)
  local breakaway = param.pull > dry_limit * mass * g
                    and ((param.pull - param.mu_k * mass * g) / mass + (dry_limit - param.mu_k) * g) * h or 0
  local slowing = math.max(0, param.mu_k * mass * g - param.pull, param.lubricated_mu * mass * g - param.pull) / mass
  local change = (param.pull + dry_limit * mass * g + param.lubricated_mu * mass * g) / mass * h
  local speed_rounding = steps * 2 ^ -24 * (3 * fastest + 19 * change)
  local at_end = slide(t_end)
  return {
    -- Over a frame of sub-steps each sub-step's rounding is left: over the frame's length, as
    -- one sub-step's over h.
    acceleration = function(t) return 21 * 2 ^ -24 * (slide(t).speed + change) / h end,
    speed = breakaway + speed_rounding,
    distance = h * at_end.speed / 2 + slowing * h * h / 2 + breakaway * (t_end + h)
               + steps * 2 ^ -24 * far + speed_rounding * t_end / 2,
  }
end

-- When a block sliding at `from` stops on a surface of kinetic coefficient `mu` that slows it
-- (nil if it does not).
local function stops_on(from, mu)
  local state = slide(from)
  local a = (param.pull - mu * mass * g) / mass
  if state.speed > 0 and a < 0 then return from + state.speed / -a end
end
-- Each stretch's start and end: dry again ends where the block stops, if it does (read over the
-- whole run, the middle of a slide that stops a second before the end is the stop itself:
-- 2.16 m/s² read where theory's 2.26 held until then).
local function stops_dry_again()
  local stop = stops_on(oil_gone, param.mu_k)
  if stop then return math.min(stop, run_length()) end
end
-- And the oiled stretch where the block stops on the oil, slowed by an oil that grips more than
-- the pull (an oil of mu 1.144 under 4.23 N, the block at 7.2 m/s as the oil came at 7.93 s:
-- stopped at 8.96 s, 0.006 s before the whole stretch's middle, where the step read held the
-- stop and gave −2.03 m/s² against −6.99).
local function stops_oiled()
  local stop = stops_on(oil_from, param.lubricated_mu)
  if stop and stop < oil_gone then return stop end
end
local stretches = {
  { "dry, before the oil", function() return 0, oil_from end },
  { "oiled", function() return oil_from, stops_oiled() or oil_gone end },
  { "dry again", function() return oil_gone, stops_dry_again() or run_length() end },
}
-- Each is read at its middle; the reading at a sample belongs to the step before it. Not the
-- first two steps of a stretch: the coefficients change at its start, a block that breaks away
-- there is held at mu_s·N through that step, and the breakaway's correction comes at the start
-- of the next (0.01 s of dry pull at 32.87 N: 12.86 m/s² read in the second step, 15.11 after).
-- Nor the step a stop falls in. The sample read is the one nearest the middle (value_at's), and
-- it reads the step before it: that step must start two steps or more after the stretch's first
-- step starts (the first step starting at or after its start), and end by the last step that
-- ends within it. A stretch of 4.87 steps from t = 0 has its middle at 2.43 steps, read in the
-- second step (the oil of mu 2 gone at 0.0203 s, pulled at 45.6 N: 26.01 m/s² read, 26.40
-- after the correction); a stretch too short for such a step is too short to read.
local function readable(from, to)
  local h = step_length()
  local sample = math.floor((from + to) / 2 / h + 0.5) * h
  local first_start = math.ceil(from / h - 1e-9) * h
  local last_end = math.floor(to / h + 1e-9) * h
  return sample - h >= first_start + 2 * h - 1e-9 * h and sample <= last_end + 1e-9 * h
end
for _, stretch in ipairs(stretches) do
  local name, ends = stretch[1], stretch[2]
  local function middle()
    local from, to = ends()
    return (from + to) / 2
  end
  local function unread()
    if name == "oiled" and oil_gone <= oil_from then return "no oil" end
    if not readable(ends()) then return "too short to read" end
    return word(middle())
  end
  expect { "acceleration, " .. name, unit = "m/s²",
    predicted = function() return unread() or slide(middle() - step_length()).acceleration end,
    measured = function()
      if unread() then return unread() end
      return time() >= middle() and value_at("acceleration", middle()) or nil
    end,
    tolerance = function() return allowed().acceleration(middle()) end }
end

local function at_the_end(probe)
  return reached(run_length()) and value_at(probe, run_length()) or nil
end
expect { "speed at the end", unit = "m/s",
  predicted = function() return word(run_length()) or slide(end_sample()).speed end,
  measured = function() return word(run_length()) or at_the_end("speed") end,
  tolerance = function() return allowed().speed end }
expect { "distance at the end", unit = "m",
  predicted = function() return word(run_length()) or slide(end_sample()).distance end,
  measured = function() return word(run_length()) or at_the_end("distance") end,
  tolerance = function() return allowed().distance end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "acceleration, oiled", unit = "m/s²",
  question = "While the table is oiled, how fast does the block speed up under the same pull?" }
predict { "speed at the end", unit = "m/s",
  question = "The oil is gone again. How fast is the block going at the end?" }
