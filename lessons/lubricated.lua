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

-- Each stretch's start and end: dry again ends where the block stops, if it does (read over the
-- whole run, the middle of a slide that stops a second before the end is the stop itself:
-- 2.16 m/s² read where theory's 2.26 held until then).
local function stops_dry_again()
  local after = slide(oil_gone)
  local a = (param.pull - param.mu_k * mass * g) / mass
  if after.speed > 0 and a < 0 then return math.min(oil_gone + after.speed / -a, run_length()) end
end
local stretches = {
  { "dry, before the oil", function() return 0, oil_from end },
  { "oiled", function() return oil_from, oil_gone end },
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
    tolerance = function() return 0.01 * math.abs(slide(middle()).acceleration) + 1e-3 end }
end

local function at_the_end(probe)
  return reached(run_length()) and value_at(probe, run_length()) or nil
end
-- 1 % and 1 mm/s or 1 mm: with theory given the instants the run switches at, what is left
-- is the breakaway within a step (the listener's correction makes it second order).
expect { "speed at the end", unit = "m/s",
  predicted = function() return word(run_length()) or slide(run_length()).speed end,
  measured = function() return word(run_length()) or at_the_end("speed") end,
  tolerance = function() return 0.01 * slide(run_length()).speed + 1e-3 end }
expect { "distance at the end", unit = "m",
  predicted = function() return word(run_length()) or slide(run_length()).distance end,
  measured = function() return word(run_length()) or at_the_end("distance") end,
  tolerance = function() return 0.01 * slide(run_length()).distance + 1e-3 end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "acceleration, oiled", unit = "m/s²",
  question = "While the table is oiled, how fast does the block speed up under the same pull?" }
predict { "speed at the end", unit = "m/s",
  question = "The oil is gone again. How fast is the block going at the end?" }
