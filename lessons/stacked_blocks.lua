-- stacked_blocks: a block on a block, the bottom one pulled harder and harder (the
-- friction-situations article's pitfalls). Two surfaces, two coefficients, two friction forces:
-- the floor holds the pair back, while the bottom block's top face is what drags the top block
-- along, so the friction on the top block points forward, the way it moves. The pair stays
-- put until the pull beats the floor's mu_s·(m_top + m_bottom)·g; then both move as one while
-- the top block needs no more than mu_s(top_on_bottom)·m_top·g to keep up, that is up to a pull
-- of (mu_s(top_on_bottom) + mu_k(bottom_on_floor))·(m_top + m_bottom)·g; past it the top block
-- slips back along the bottom one, carried forward at mu_k(top_on_bottom)·g only.

local ending  -- when the run ends, worked out below from the closed form

lesson {
  title = "A block on a block, pulled harder and harder",
  question = "Which way does friction push the top block, and when does it stop keeping up?",
  duration = function() return ending() end,
  order = 15,
  -- Two blocks, two contacts: 4 passes of the contact solver a step, not the default 8, at
  -- 84 % of the cost. Every row stays within its tolerance at every control's ends and in every
  -- test case; what it costs most: the friction on the top block halfway, at mu_s 0.15 and
  -- 50 N/s, is off by 38 % of its tolerance (1 % with 8 passes; with 3 passes 98 %, with 2 it
  -- fails).
  velocity_iterations = 4,
  moments = {
    { "together", at = 3,
      shows = function() return value_at("floor_slipping", time()) == 1 and value_at("top_slipping", time()) == 0 end },
    { "top_slips", at = 4.2, readme = true, shows = function() return value_at("top_slipping", time()) == 1 end },
    -- A heavy top block gripped hard: the pair's front lifts before the top block slips.
    { "front_lifts", at = 2.27, set = { top_mass = 5, bottom_mass = 1, pull_rate = 50, ["top_on_bottom.mu_s"] = 1.8 },
      shows = function() return value_at("tilt", time()) > 2 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
-- At most five times heavier on top: a light body under a heavy one is where Box2D's solver
-- stops converging in its passes (at 5 kg on 0.5 kg, with the default 8, the top block's
-- friction stays a hair under mu_s·N while it creeps back, and it is never seen to slip).
local top_mass = parameter { "top_mass", 1, min = 0.2, max = 5, unit = "kg", text = "mass of the top block" }
local bottom_mass = parameter { "bottom_mass", 2, min = 1, max = 10, unit = "kg", text = "mass of the bottom block" }
local pull_rate = parameter { "pull_rate", 5, min = 0.5, max = 50, unit = "N/s", text = "how fast the pull on the bottom block grows" }

-- A wooden block on an aluminium one (the spring article's pair), which slides on a stone floor.
pair { "wood", "aluminium", name = "top_on_bottom", mu_s = 0.45, mu_k = 0.35, sliders = { "mu_s", "mu_k" } }
pair { "aluminium", "stone", name = "bottom_on_floor", mu_s = 0.3, mu_k = 0.2, sliders = { "mu_s", "mu_k" } }
pair { "wood", "stone", mu_s = 0.5, mu_k = 0.4, sliders = false }  -- only if the top block falls off
pair { "wood", "wood", sliders = false }  -- the preset values; no wooden body meets another

-- Theory ----------------------------------------------------------------------------------
local function pairs_now()
  return { mu_s = param["top_on_bottom.mu_s"], mu_k = param["top_on_bottom.mu_k"] },
         { mu_s = param["bottom_on_floor.mu_s"], mu_k = param["bottom_on_floor.mu_k"] }
end
-- The closed form asks mu_k <= mu_s of both pairs: with mu_k above mu_s a surface pushed past
-- mu_s·N would at once be held back harder, and which block then does what has no closed form.
local function no_theory()
  local between, floor = pairs_now()
  if between.mu_k > between.mu_s then return "no closed form (μk > μs)" end
  if floor.mu_k > floor.mu_s then return "no closed form (μk > μs)" end
end
local function stack(push)
  local between, floor = pairs_now()
  return theory.stacked_blocks { top_mass = param.top_mass, bottom_mass = param.bottom_mass,
                                 between = between, ground = floor, push = push }
end
local function total_weight() return (param.top_mass + param.bottom_mass) * g end
-- The pulls at which the pair starts to slide, and at which the top block starts to slip (at
-- once, if the floor's kinetic friction leaves the top block more to keep up with than its
-- static friction can give).
local function start_pull() return math.max(param["bottom_on_floor.mu_s"], param["bottom_on_floor.mu_k"]) * total_weight() end
local function slip_pull()
  if no_theory() then return start_pull() end
  return math.max(stack(0).max_push_together, start_pull())
end
-- Whether the pair moves together for at least two steps before the top block slips.
local function together_phase() return slip_pull() - start_pull() > 2 * param.pull_rate * step_length() end
local function top_acceleration_after() return param["top_on_bottom.mu_k"] * g end
local function bottom_acceleration(t)
  return (param.pull_rate * t - param["top_on_bottom.mu_k"] * param.top_mass * g
          - param["bottom_on_floor.mu_k"] * total_weight()) / param.bottom_mass
end

-- How long after the pair starts to slide it has slid x metres together, pulled by rate·t:
-- x = rate·τ³/(6·M) + (mu_s − mu_k)·g·τ²/2 on the floor, solved by bisection. The floor ends
-- 200 m from where the pair stands; a run that would take it past 150 m is cut short there.
local floor_room = 150
local function together_time_to(x)
  local M = param.top_mass + param.bottom_mass
  local a0 = math.max(param["bottom_on_floor.mu_s"] - param["bottom_on_floor.mu_k"], 0) * g
  local function slid(tau) return param.pull_rate * tau ^ 3 / (6 * M) + a0 * tau * tau / 2 end
  local low, high = 0, 1
  while slid(high) < x do high = 2 * high end
  for _ = 1, 60 do
    local middle = (low + high) / 2
    if slid(middle) < x then low = middle else high = middle end
  end
  return high
end

-- The run ends once the top block has slipped 0.15 m back along the bottom one (0.25 m would
-- take it to the back edge), or 2 s after it started to slip, or as the front would lift
-- (below); half a second after the front lifts, if it lifts before the top block slips;
-- without a closed form, 8 s after the pair would start to slide, or sooner near the floor's
-- end.
local slip_room = 0.15

-- Friction can tip the pair backwards. In the frame of the accelerating pair each block is
-- pushed back by m·a at its centre, and about the bottom block's back edge only the weights
-- hold the pair down: the pull and the floor's push act at the floor, at the edge's height. A
-- heavy top block on a light bottom one, gripped hard (top_mass 5, bottom_mass 1, mu_s above
-- 1.38), lifts the pair's front before the top block slips; a light bottom block pulled fast
-- from under a slipping top one rears up by itself. The closed form has both blocks flat on
-- the floor. Heights are of the blocks' centres above the floor.
local bottom_width, bottom_height = 0.8, 0.25
local top_width, top_height = 0.3, 0.1
local top_centre = bottom_height + top_height / 2
local bottom_centre = bottom_height / 2
-- Positive when the pair's front lifts, the top block slid `top_back_by` back from the middle.
local function tipping_moment(top_acceleration, bottom_acceleration_now, top_back_by)
  local lifting = param.bottom_mass * bottom_acceleration_now * bottom_centre + param.top_mass * top_acceleration * top_centre
  local holding = g * (param.bottom_mass * bottom_width / 2 + param.top_mass * (bottom_width / 2 - top_back_by))
  return lifting - holding
end
-- When the pair, moving as one, would start to tip, and at what pull, whether or not the top
-- block slips first. The moment is a straight line in the common acceleration a: zero at
-- a = −M(0)/(M(1) − M(0)).
local function lift_as_one()
  local M, dragged = param.top_mass + param.bottom_mass, param["bottom_on_floor.mu_k"] * total_weight()
  local at_rest = tipping_moment(0, 0, 0)
  local a = -at_rest / (tipping_moment(1, 1, 0) - at_rest)
  local pull = math.max(start_pull(), a * M + dragged)
  return pull / param.pull_rate, pull
end
-- When the pair, moving as one, starts to tip (nil: the top block slips first).
local function tipping_time()
  if no_theory() or not together_phase() then return nil end
  local t, pull = lift_as_one()
  if slip_pull() < pull then return nil end
  return t
end
-- Whether the pair reaches the floor's end before the top block slips or the pair tips.
local function off_the_floor()
  if no_theory() then return nil end
  local next_event = math.min(slip_pull() / param.pull_rate, tipping_time() or math.huge)
  if next_event - start_pull() / param.pull_rate > together_time_to(floor_room) then
    return "runs off the floor first"
  end
end
-- The floor's breakaway as the stepped world takes it: the stick-slip treatment owes the pair
-- the (mu_s − mu_k)·N·s kinetic friction would have taken off within the step it broke away
-- in (s up to a step), and pays it at the next step's start as one impulse at the floor's
-- height. Below the pair's centre of mass it turns the pair front up about its back edge (which
-- the floor can only push up on): an angular impulse J·y about that edge, y the centre's height
-- for the two blocks moving as one in that step (the top block held by its static friction, as
-- the world holds it; a top block slipping within it takes less, so this is the most). Where
-- the top block slips at once (the same step), theory's moment may still hold the front down
-- by only a little: 0.58 N·m of 14.8 at 2.7 kg on 1.08 kg, both mu_s 2, and the world's front
-- was kicked up at the slip and never came down (its load 0 from then on, the top block's
-- friction 2 % short of mu_k·N as the pair pitched). J for s one step, N·s:
local function breakaway_impulse()
  return math.max(param["bottom_on_floor.mu_s"] - param["bottom_on_floor.mu_k"], 0) * total_weight() * step_length()
end
-- The angular impulse, N·m·s:
local function breakaway_kick()
  local centre = (param.bottom_mass * bottom_centre + param.top_mass * top_centre) / (param.top_mass + param.bottom_mass)
  return breakaway_impulse() * centre
end
-- The pair's moment of inertia about its back edge, the top block `top_back_by` back from the
-- middle, kg·m².
local function inertia_about_back_edge(top_back_by)
  local bottom = param.bottom_mass * ((bottom_width ^ 2 + bottom_height ^ 2) / 12 + (bottom_width / 2) ^ 2 + bottom_centre ^ 2)
  local top = param.top_mass * ((top_width ^ 2 + top_height ^ 2) / 12 + (bottom_width / 2 - top_back_by) ^ 2 + top_centre ^ 2)
  return bottom + top
end
-- After the top block slips: when it has slid slip_room back, or (first) when the bottom block
-- racing ahead would lift the front; which of the two came first; and, where the top block
-- slipped at once, whether the breakaway's kick still has the front up then: the front rises
-- at kick / inertia and the moment's deficit (−tipping_moment) brings it down, stepped with it.
-- Also the soonest the world's front can lift while the top block slips: a top block slipping at
-- once takes only mu_k of its weight, so the breakaway's impulse, paid at the next step's start,
-- drives the bottom block alone ahead of it. The stick-slip treatment pays (mu_s − mu_k)·N·s
-- with s from half a step to a step and a half (the crossing's place in its step, and the half
-- step of Box2D's mid-step velocities), so the top block lags by more from the start: at 3.65 kg
-- under 2.17 kg, floor mu_s 2 and mu_k 0, top mu 2, 25.53 N/s, the bottom block drew ahead at
-- 0.077 m/s (s = 0.59 of a step; 0.195 m/s at the most) and the front lifted at 4.67 s, where
-- the lag from rest has it lift at 4.71 s.
local function slipping_from_scratch()
  local t, lag, lag_speed = slip_pull() / param.pull_rate, 0, 0
  local step = 1e-3
  local kicked = not together_phase()
  local pitch, pitch_speed = 0, kicked and breakaway_kick() / inertia_about_back_edge(0) or 0
  local lag_most, lag_most_speed = 0, kicked and 1.5 * breakaway_impulse() / param.bottom_mass or 0
  local soonest
  for _ = 1, 2000 do
    if lag >= slip_room then break end
    local moment = tipping_moment(top_acceleration_after(), bottom_acceleration(t), lag)
    if not soonest and tipping_moment(top_acceleration_after(), bottom_acceleration(t), lag_most) >= 0 then soonest = t end
    if moment >= 0 then return t, true, kicked and pitch > 0, soonest or t end
    if pitch > 0 or pitch_speed > 0 then
      pitch_speed = pitch_speed + moment / inertia_about_back_edge(lag) * step
      pitch = pitch + pitch_speed * step
    end
    lag_speed = lag_speed + (bottom_acceleration(t) - top_acceleration_after()) * step
    lag = lag + lag_speed * step
    lag_most_speed = lag_most_speed + (bottom_acceleration(t) - top_acceleration_after()) * step
    lag_most = lag_most + lag_most_speed * step
    t = t + step
  end
  return t, false, false, nil
end
local slipping_known = {}  -- the last answer, and the values it was worked out for
local function slipping_until()
  -- Asked many times over by the rows and the run's end: worked out again only when a value
  -- changed (the pairs' sliders change the running lesson; the step sets the breakaway's kick).
  local values = string.format(string.rep("%.17g ", 8), param.top_mass, param.bottom_mass, param.pull_rate,
    param["top_on_bottom.mu_s"], param["top_on_bottom.mu_k"], param["bottom_on_floor.mu_s"], param["bottom_on_floor.mu_k"],
    step_length())
  local known = slipping_known
  if known.values == values then return known.t, known.lifts, known.kicked, known.soonest end
  local t, lifts, kicked, soonest = slipping_from_scratch()
  slipping_known = { values = values, t = t, lifts = lifts, kicked = kicked, soonest = soonest }
  return t, lifts, kicked, soonest
end
-- When the front lifts while the theory still has something to show (nil: it does not). Moving
-- as one on the floor; or right as the top block slips, before its slipping can be read (3
-- steps), or while the breakaway's kick still has it up. A front that would lift later, while
-- the top block slips, ends the run there, as it starts to lift (at the first millisecond of
-- the integration past the moment's zero).
local function tips_at()
  if no_theory() or off_the_floor() then return nil end
  local together = tipping_time()
  if together then return together end
  local t, lifts, kicked = slipping_until()
  if lifts and (kicked or t < slip_pull() / param.pull_rate + 3 * step_length()) then return t end
end
-- Which comes first while the pair moves as one, the front lifting or the top block slipping,
-- can be told only if theory has them further apart than the world can place each: the slip
-- within its row's tolerance (1 % of its pull and the step's growth of the pull, in time over
-- the rate), the lift within the step it shows in (the floor's load on the front edge is
-- solved exactly each step, Box2D's block solver taking a face's two points together, and
-- drops to zero in the step the moment changes sign). Closer than that, from the earlier of
-- the two on, the rows say so. (nil: not a close race.)
local function close_race_from()
  if no_theory() or not together_phase() or off_the_floor() then return nil end
  local slips, lifts = slip_pull() / param.pull_rate, lift_as_one()
  local apart_at_least = (0.01 * slip_pull() + param.pull_rate * step_length()) / param.pull_rate + step_length()
  if math.abs(slips - lifts) <= apart_at_least then return math.min(slips, lifts) - apart_at_least end
end
local too_close_words = "lift or slip first: too close to call at this step"
-- The words for a row read at t when the pair has tipped by then (nil otherwise).
local tipped_words = "front lifts: no closed form"
local function tipped_by(t)
  local close = close_race_from()
  if close then
    if t >= close then return too_close_words end
    return nil
  end
  local lifts = tips_at()
  if lifts and lifts <= t then return tipped_words end
end
ending = function()
  local start = start_pull() / param.pull_rate
  if no_theory() then return start + math.min(8, together_time_to(floor_room)) end
  if off_the_floor() then return start + together_time_to(floor_room) end
  -- Half a second after the front lifts: long enough to see it rear up.
  local lifts = tips_at()
  if lifts then return lifts + 0.5 end
  return (slipping_until())
end

-- World -----------------------------------------------------------------------------------
local floor = ground { "floor", material = "stone" }
-- The top block is made first, so that the free-body diagram is its own: friction forward.
-- It rests on the bottom block's top face, which rests on the floor (what on = ... would do). Three times as wide as it is tall, it would tip backwards only at an
-- acceleration above g·w/h = 3g, which no mu up to 2 can give it: it slips first.
-- The bottom block is 0.25 m tall, more than the 0.2 m by which Box2D widens every shape's
-- box when it looks for shapes that may touch: so Box2D does not test the top block against
-- the floor every step (3 % of the lesson's time at 0.15 m), until it falls off.
local top = box { "top", material = "wood", width = top_width, height = top_height, x = 0,
                  y = bottom_height + top_height / 2, mass = top_mass }
local bottom = box { "bottom", material = "aluminium", width = bottom_width, height = bottom_height, on = floor,
                     at = 0, mass = bottom_mass }
-- Pulled at the height where the bottom block meets the floor, so the pull itself cannot tip
-- it (the top block's friction, at the bottom block's top face, can: see tipping_moment).
local pull = force { "pull", on = bottom, at = { bottom_width / 2, -bottom_height / 2 },
                     grows = { pull_rate, 0 } }
view { follow = bottom }

-- Probes and plots ------------------------------------------------------------------------
local on_floor, on_bottom = contact(bottom, floor), contact(top, bottom)
probe { "pull", unit = "N", read = { pull, "fx" } }
probe { "friction_on_top", unit = "N", read = { on_bottom, "fx" } }      -- positive: forward
probe { "friction_on_bottom", unit = "N", read = { on_floor, "fx" } }    -- from the floor
probe { "top_acceleration", unit = "m/s²", read = { top, "acceleration", along = { 1, 0 } } }
probe { "bottom_acceleration", unit = "m/s²", read = { bottom, "acceleration", along = { 1, 0 } } }
probe { "floor_slipping", read = { on_floor, "slipping" } }
probe { "top_slipping", read = { on_bottom, "slipping" } }
probe { "tilt", unit = "°", read = { bottom, "angle" } }  -- the front lifting: positive
-- What the floor pushes up on the bottom block's front half with: zero once the front lifts.
probe { "front_load", unit = "N", read = { on_floor, "load_right" } }

-- Each plot shades the slip it is about: the floor's, where the pair breaks away and the friction
-- on the bottom block drops to kinetic; the top block's, where it stops keeping up.
-- The key plot's two levels are the top block's (N its load), as push's are its block's: the most its static
-- friction can give to keep up (forward, so positive here), where the class sees it break away,
-- and the kinetic friction it drops to once it slips. The top block's load is its weight (the
-- pair stays flat until it slips, or the run ends half a second after its front lifts).
local function top_load() return param.top_mass * g end
plot { "Friction on each block", kind = "time", y = { "pull", "friction_on_top", "friction_on_bottom" },
  shade = "floor_slipping",
  levels = {
    { "μs·N (top)", function() return param["top_on_bottom.mu_s"] * top_load() end },
    { "μk·N (top)", function() return param["top_on_bottom.mu_k"] * top_load() end },
  } }
plot { "Acceleration of each block", kind = "time", y = { "top_acceleration", "bottom_acceleration" }, shade = "top_slipping",
  theory = { { "top slipping: μk·g", function(t)
    if not no_theory() and t * param.pull_rate >= slip_pull() and not tipped_by(t) then return top_acceleration_after() end
  end } } }

-- Reading the record ----------------------------------------------------------------------
-- The pull that set a contact slipping: the one recorded the step before it first slipped.
-- The top block slips on the bottom one only once that moves: with no friction between them
-- their contact cannot hold, and reads slipping as soon as the two slide apart at all.
local function first_slip(probe)
  local slipping, floor_slipping, pulls = history(probe), history("floor_slipping"), history("pull")
  for i = 1, #slipping do
    if slipping[i] == 1 and floor_slipping[i] == 1 then return i > 1 and pulls[i - 1] or 0 end
  end
end
-- The bottom block's tilt while both its edges touch the floor is at most one edge sunk by
-- Box2D's whole linear slop (5 mm, b2_linearSlop: the runtime's linear_slop) and the other not
-- at all: atan(5 mm / 0.8 m), 0.36°. Past that its front edge has left the floor.
local flat_tilt_most = math.deg(math.atan(linear_slop / bottom_width))
-- The measured side of a row the theory gives up on because the front lifts, read from the
-- record at the run's end: the front lifted (the floor stopped pushing on the bottom block's
-- front half: the front edge's load is 0), and, where theory has it lift while the pair moves
-- as one, it lifted before the top block slipped. The tilt cannot tell it: a heavy pair lifts
-- slowly under a ramped pull (the moment past its zero grows as the pull does), and at 5 kg on
-- 5.55 kg, both mu_s 2, 50 N/s, the front lifts at 403 N as theory says while the tilt is
-- still under flat_tilt_most (0.30°) when the top block slips, 12 N later.
local function lifted_seen()
  if not reached(ending()) then return nil end
  if close_race_from() then return too_close_words end
  local times, loads, slipping = history("time"), history("front_load"), history("top_slipping")
  local lifted, slipped
  local start = start_pull() / param.pull_rate
  -- The run's end worked out once, not at every sample: ending() works its way through the
  -- theory, and a slow pull on a heavy pair records for minutes (5 kg on 3.76 kg, both mu_s 2,
  -- 0.5 N/s slides at 344 s: 83 000 samples, over the script's budget of a call).
  local last = ending() + 0.5 * step_length()
  for i = 1, #times do
    if times[i] > last then break end
    -- Only once the pair slides: before the first step's contact is found the load reads 0.
    if not lifted and loads[i] <= 0 and times[i] > start then lifted = times[i] end
    if not slipped and slipping[i] == 1 and times[i] > start then slipped = times[i] end
  end
  if not lifted then return "stays flat" end
  if tipping_time() and slipped and slipped < lifted then return "the top block slips first" end
  return tipped_words
end
-- Where the rows about the run's end read the record: at its end, but where the run ends as the
-- front starts to lift while the top block slips, at the world's last sample with its front
-- still loaded, if its front lifted no sooner than the breakaway's impulse at its most lets it
-- (slipping_from_scratch). The closed form holds while both blocks lie flat; a world whose
-- front lifted sooner than that is read at the end, and its rows say it.
local function reading_time()
  local e = ending()
  if not reached(e) or tips_at() then return e end
  local t, lifts, _, soonest = slipping_until()
  if not lifts or math.abs(t - e) > 0.5 * step_length() then return e end
  local times, loads = history("time"), history("front_load")
  local start, last = slip_pull() / param.pull_rate, e + 0.5 * step_length()
  for i = 2, #times do
    if times[i] > last then break end
    if loads[i] <= 0 and times[i] > start then
      if times[i] >= soonest - step_length() then return times[i - 1] end
      return e
    end
  end
  return e
end
local function at_the_end(probe)
  return reached(ending()) and value_at(probe, reading_time()) or nil
end

-- Expectations ----------------------------------------------------------------------------
expect { "the pair starts to slide at a pull of", unit = "N",
  predicted = function() return no_theory() or start_pull() end,
  measured = function() return no_theory() or first_slip("floor_slipping") end,
  -- The pull grows by rate·h in a step, and the slip shows at the end of the step it began in.
  -- (On a smooth floor that is the second step, the first with a pull: the recorded pull is then
  -- rate·h exactly, read from Box2D's float force, so a float's rounding, 2^-24 of it, is let
  -- in too.)
  tolerance = function() return (0.01 * start_pull() + pull_rate * step_length()) * (1 + 2 ^ -23) end }
expect { "the top block starts to slip at a pull of", unit = "N",
  predicted = function() return no_theory() or off_the_floor() or tipped_by(slip_pull() / param.pull_rate) or slip_pull() end,
  measured = function()
    if tipped_by(slip_pull() / param.pull_rate) then return lifted_seen() end
    return no_theory() or off_the_floor() or first_slip("top_slipping")
  end,
  -- As above; and a top block that slips at once is seen a step after the floor's breakaway:
  -- in that step the solver held the pair as one, and the top block slips in the next, as the
  -- breakaway's impulse is paid (5 kg on 5.82 kg, a floor of mu_s 0.058, top mu_s 0.016, 50 N/s:
  -- the floor seen at 6.25 N, the top block at 6.46, theory 6.14 for both).
  tolerance = function()
    local steps = together_phase() and 1 or 2
    return (0.01 * slip_pull() + steps * pull_rate * step_length()) * (1 + 2 ^ -23)
  end }
-- Halfway between the two, the top block keeps up: its friction is m_top·a, forward.
local function halfway()  -- on a step, so that the sample read there is the one meant
  local h = step_length()
  return math.floor((start_pull() + slip_pull()) / (2 * param.pull_rate) / h + 0.5) * h
end
expect { "friction on the top block halfway, forward", unit = "N",
  predicted = function()
    if no_theory() then return no_theory() end
    if not together_phase() then return "slips at once" end
    if off_the_floor() then return off_the_floor() end
    if tipped_by(halfway()) then return tipped_by(halfway()) end
    -- The contact reads the step just taken, which the pull of its start drove.
    return stack(param.pull_rate * (halfway() - step_length())).top_acceleration * param.top_mass
  end,
  measured = function()
    if no_theory() then return no_theory() end
    if not together_phase() then return "slips at once" end
    if off_the_floor() then return off_the_floor() end
    if tipped_by(halfway()) then return lifted_seen() end
    return time() >= halfway() and value_at("friction_on_top", halfway()) or nil
  end,
  tolerance = function() return 0.01 * slip_pull() * param.top_mass / (param.top_mass + param.bottom_mass) end }
expect { "top block's acceleration, slipping", unit = "m/s²",
  predicted = function() return no_theory() or off_the_floor() or tipped_by(ending()) or top_acceleration_after() end,
  measured = function()
    if tipped_by(ending()) then return lifted_seen() end
    return no_theory() or off_the_floor() or at_the_end("top_acceleration")
  end,
  -- 1 % and 1 mm/s². And the bottom block's tilt: theory has it flat, but the world lets a
  -- contact sink into another by up to Box2D's linear slop (5 mm), and the floor's load
  -- shifting to the back edge tips the bottom block by a hair (0.02° at top 2.9 kg on 1.2 kg,
  -- mu 2 on both, a smooth top), down which the top block slides at g·sin(tilt), 4 mm/s²
  -- there. The tilt counted is the world's, but never more than one edge sunk by the whole
  -- slop allows (flat_tilt_most, 0.36°): a world that tilts further is wrong, not excused.
  tolerance = function()
    local tilt = reached(ending()) and value_at("tilt", reading_time()) or 0
    return 0.01 * top_acceleration_after() + 1e-3 + g * math.sin(math.rad(math.min(math.abs(tilt), flat_tilt_most)))
  end }
-- Read where the rows about the end read (reading_time), where the pull was rate·(t − h).
expect { "bottom block's acceleration at the end", unit = "m/s²",
  predicted = function()
    return no_theory() or off_the_floor() or tipped_by(ending()) or bottom_acceleration(reading_time() - step_length())
  end,
  measured = function()
    if tipped_by(ending()) then return lifted_seen() end
    return no_theory() or off_the_floor() or at_the_end("bottom_acceleration")
  end,
  tolerance = function() return 0.01 * math.abs(bottom_acceleration(reading_time())) + 1e-3 end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "friction on the top block halfway, forward", unit = "N",
  question = "Halfway through the time the two slide together, how hard does friction push the top block forward (a minus sign for backward)?" }
predict { "the top block starts to slip at a pull of", unit = "N",
  question = "How hard is the pull when the top block stops keeping up?" }
