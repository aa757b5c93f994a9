-- wedge: the friction-situations article's advanced example. A block rests on a plank (the
-- "wedge") whose surface swings about a pivot, θ(t) = θ0·sin(ω·t), while the pivot is driven
-- sideways with a(t) = a_x·cos(ω_a·t) (ω_a = 0: a constant a_x). In the wedge's frame the
-- block feels gravity and the pseudo-force −m·a, so the article writes
--   down the slope  F = m·(g·sin θ + a·cos θ),   pressing  N = m·(g·cos θ − a·sin θ),
-- and lets static friction hold the block while |F| <= μs·N. That reduction leaves out that the
-- surface turns: a block a distance ρ from the pivot is also flung outwards (θ'²·ρ) and pressed
-- or lifted as the turn speeds up (θ''·ρ) and as it slides across the turning surface (2θ'·s').
-- Beside the Box2D block on the driven plank this lesson solves both: the article's reduction
-- (slide_reduced) and the same with the turning terms put back (the dashed "with the turn"),
-- which is what the Box2D block should follow. Where they part is what the article left out.
-- With a large a_x the wedge falls away faster than gravity can follow (N < 0): the block
-- flies, and lands again.
--
-- A plank shaken hard while the block slides back and forth on it: the driven plank's velocity
-- changes once a step, so the block's sliding may reverse between two steps, and the friction
-- listener weighs the shake too when it asks whether static friction holds it there
-- (treatment_stick_slip.cpp; it used to drag the block to the plank's speed at every such
-- reversal, 0.31 m off the exact 1.79 m at a_x = 30, a_x_omega = 5, ω = 0). Now the slide ends
-- 0.20 m off at 240 Hz (0.19 with --substeps 8), within the row's 0.35 m, and halves with the
-- step (0.098, 0.049, 0.025 m at 480, 960, 1920 Hz): 0.11 m of it is the world's start (below),
-- (a_x − μk·g)·h/2 carried until the block first sticks at 1.85 s; the rest is not explained yet. A
-- reversal inside a step is placed within it with the drive spread over the step (0.028 m off
-- at a_x = 14.62, a_x_omega = 10, μs 0.9692, μk 0.7089, ω = 0, where each reversal left the
-- sliding up to μk·g·h off; 0.0032 m now, the start's). Where the solver stops the sliding inside a step and the drive carries the
-- block past the stop, the listener decides it there, kinetic friction acting the new way for
-- the rest of the step (it used to hold the block for a step at μs·N and read the breakaway's
-- span from the last hold: a level plank shaken at −30 m/s², a_x_omega 7.371, μs 1.761,
-- μk 1.247 ended 0.069 m off the exact slide at 240 Hz, now 0.00004).

local y0 = 2.4       -- m: the pivot's height; the plank's surface passes through it
-- m: half the plank's length. Long enough for the article's first example, which slides 10 m
-- in 5 s; so there is no floor: the plank's ends swing down by up to 7.7 m.
local half = 12.0
local block_width, block_height = 0.3, 0.15

local duration = 5  -- s: the article's worked example looks 5 s ahead

lesson {
  title = "A block on a swinging, accelerating wedge",
  question = "The wedge swings and is shaken sideways: when does the block slip, where does it end up, and what did the article's reduced model leave out?",
  duration = duration,
  order = 38,
  -- Box2D's default 8 passes of the contact solver a step, not 4: with 4, a block held at
  -- 98.75 % of its static limit, on the edge of rocking, slipped in its third step (μk = 2,
  -- a_x = 19.37 m/s²), the model's 0.62 s later; with 5 or more it slips when the model does.
  -- The solver's share of the lesson's time is small: 200 s of it run in 0.17 s with 4 passes
  -- and 0.19 s with 8.
  velocity_iterations = 8,
  moments = {
    { "held", at = 0.05, shows = function() return value_at("slipping", time()) == 0 end },
    { "slipping", at = 0.6, readme = true, shows = function() return value_at("slipping", time()) == 1 end },
    { "flight", at = 0.5, set = { theta0 = 30, a_x = 25, a_x_omega = 3, omega = 2 },
      shows = function() return value_at("normal_force", time()) == 0 end },
    { "turning_matters", at = 4.5, set = { theta0 = 20 }, theme = "dark",
      shows = function() return math.abs(value_at("slide", time()) - value_at("slide_reduced", time())) > 0.05 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
-- The defaults are the article's complete worked example: 1.5 kg, θ = 10°·sin 3t,
-- a = 2·cos 2t m/s², μs 0.25, μk 0.18.
local mass = parameter { "mass", 1.5, min = 0.1, max = 10, unit = "kg", text = "mass of the block" }
parameter { "theta0", 10, min = 0, max = 40, unit = "°", text = "how far the surface swings each way" }
parameter { "omega", 3, min = 0, max = 10, unit = "rad/s", text = "how fast it swings (0: it stays level)" }
parameter { "a_x", 2, min = -30, max = 30, unit = "m/s²", text = "the wedge's sideways acceleration" }
parameter { "a_x_omega", 2, min = 0, max = 10, unit = "rad/s", text = "how fast that acceleration swings (0: constant)" }
pair { "wood", "wood", mu_s = 0.25, mu_k = 0.18, sliders = { "mu_s", "mu_k" } }

-- Every parameter rebuilds the lesson when it changes (the models below read them all), so
-- they are copied once here. The plots' theory curves call the functions below for every point
-- they draw, and a local is cheaper to read than param.NAME or math.sin, which go through tables.
local sin, floor = math.sin, math.floor
-- The way a signed quantity points along the surface: −1 or 1 (0 counts as forward).
local function direction_of(x) return x < 0 and -1 or 1 end
local theta0, omega = math.rad(param.theta0), param.omega
local a_x, a_x_omega = param.a_x, param.a_x_omega
local function theta(t) return theta0 * sin(omega * t) end
-- How much harder or softer the turning surface presses a block that stands `gap` (m) off
-- another along it at t and moves `gap_speed` (m/s) faster: m·(|θ''|·δs + 2·|θ'|·δs'), the
-- turn's push across the surface on the offset and the Coriolis push on the speed (N).
local function turn_press(t, gap, gap_speed)
  local spin_up = theta0 * omega * omega * math.abs(sin(omega * t))
  local turn_rate = theta0 * omega * math.abs(math.cos(omega * t))
  return mass * (spin_up * math.abs(gap) + 2 * turn_rate * math.abs(gap_speed))
end
-- The pivot starts at rest at x = 0: x'' = a_x·cos(ω_a·t).
local function wedge_x(t)
  if a_x_omega == 0 then return 0.5 * a_x * t * t end
  local half_turn = sin(0.5 * a_x_omega * t) / a_x_omega
  return 2 * a_x * half_turn * half_turn
end
local function pivot_acceleration(t) return a_x_omega == 0 and a_x or a_x * math.cos(a_x_omega * t) end
-- The article's drive down the slope on a block held on the plank, m·(g·sin θ + a·cos θ).
local function drive_along(t) return mass * (g * sin(theta(t)) + pivot_acceleration(t) * math.cos(theta(t))) end
-- The same on a block held at the pivot, as it starts, with the turn's push along the surface
-- put back: its centre, e above the pivot, is carried round it, which takes m·θ''·e along the
-- surface (theory.wedge's turning term at ρ = 0). Zero at t = 0, but not a step later on a
-- fast swing: at θ0 22.8°, ω 8.267 rad/s, 9.849 kg it is 0.69 N of the 53 N the drive asks
-- at t = h, more than the 1 % by which the drive alone passed the limit there.
local function drive_at_the_pivot(t)
  return drive_along(t) + mass * theta0 * omega * omega * sin(omega * t) * 0.5 * block_height
end

-- World -----------------------------------------------------------------------------------
-- The plank's top face runs through its own origin, the pivot, so turning it about the origin
-- swings the surface about the pivot, as the article's wedge does.
local wedge = polygon { "wedge", material = "wood", kind = "kinematic", x = 0, y = y0,
                        points = { { -half, -0.12 }, { half, -0.12 }, { half, 0 }, { -half, 0 } } }
-- The plank's path as numbers, which the runtime works out itself each step (a function of time
-- would be a call into the script, four a step): θ0·sin(ω·t), and x = ½·a_x·t², or for a
-- swinging a_x, (a_x/ω_a²)·(1 − cos ω_a·t) = a_x/ω_a² + (a_x/ω_a²)·sin(ω_a·t − π/2).
local sway = a_x_omega == 0 and { acceleration = a_x }
  or { offset = a_x / a_x_omega ^ 2, swing = a_x / a_x_omega ^ 2, omega = a_x_omega, phase = -math.pi / 2 }
drive { wedge, position = { x = sway, y = y0 }, angle = { swing = param.theta0, omega = omega } }
-- The models start the block at rest on the surface. The driven plank moves through its first
-- step at the mean velocities of that step, so the block starts with them too: turning with
-- the surface (θ0·ω at first), its centre carried round the pivot and along with it. Started
-- still, it would begin by slipping on the moving plank, and with mu_k = 0 never stop. The
-- first step is the world's own, a sub-step with --substeps: the plank moves through that at
-- its mean velocities (a block started with the whole frame's, a_x·h/2, slid 0.0349 m/s off the
-- plank at a_x −16.73, 2 sub-steps at 240 Hz, μk 0, where the sub-step's start gives 0.0305,
-- and ended 0.17 m off the model's, the row's whole tolerance).
local first = substep_length()
local start_turn = theta(first) / first
local centre_height = 0.5 * block_height
local block = box { "block", material = "wood", width = block_width, height = block_height, on = wedge, at = 0, mass = mass,
                    spin = start_turn, velocity = { wedge_x(first) / first - start_turn * centre_height, 0 } }
view { follow = block, width = 3.2 }

-- The two models, solved once for the whole run at the world's step: the article's reduction,
-- and the same with the turning surface's terms for this block (its centre rests half its
-- height above the surface, and starts at the pivot).
-- The models are sampled every world step (every few steps at rates past 6000 Hz, where the
-- lesson's 5 s would take more than 30 000 samples; a probe then reads the nearest sample).
local h = step_length()
-- How late the record may say "slipping" after the demand passed the limit: three and a half
-- steps (the first slip row says why). The rows that read the world's record for a breakaway
-- or a stop read it that far either side.
local record_lag = 3.5 * h
local spacing = h * math.max(1, math.ceil((duration + 0.1) / (29999 * h)))
local function model(turning, horizon)
  return theory.wedge { mass = mass, theta0 = param.theta0, omega = omega, a_x = a_x, a_x_omega = a_x_omega,
    mu_s = param.mu_s, mu_k = param.mu_k, duration = horizon, step = spacing, rotation = turning,
    centre_height = centre_height, start = 0, world_step = turning and substep_length() or nil }
end
-- Solved to a little past the lesson's end, and again twice as far whenever a longer run (the
-- window running on, or --duration) gets there: the same steps give the same answers. At most
-- 30 000 samples (125 s at 240 Hz): the two models' lists then take 12 MB of the script's 64,
-- with room for the old ones while the new are made. Past that the models' probes hold their
-- last values.
local longest = 29999 * spacing
local reduced, turning, horizon
local function solve(until_t)
  horizon = math.min(until_t, longest)
  reduced, turning = nil, nil  -- the old lists may go while the new are made
  reduced, turning = model(false, horizon), model(true, horizon)
end
solve(duration + 0.1)
local function sample(t)
  if t > horizon - 2 * spacing and horizon < longest then solve(math.max(2 * horizon, t + 1)) end
  return math.min(floor(t / spacing + 0.5) + 1, #reduced.slide)
end
-- The reduced model solved at least to t: what the probes below read their lists from.
local function reduced_to(t)
  sample(t)
  return reduced
end
-- A contact's force is the mean over the step just taken: the models' at the middle of it.
local function mid_step(turned, field, t)
  local k = sample(t)  -- first: it may solve further
  local list = (turned and turning or reduced)[field]
  return 0.5 * (list[k] + list[math.max(k - 1, 1)])
end

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(block, wedge)
-- Every probe here is read by the runtime without running a line of the script: this lesson
-- must keep up with 2000 times real time, and each call into the script costs as much as a few
-- dozen lines of it. The slide is how far the block's centre has moved down the slope, in the
-- plank's own axes (its x axis runs up the surface from the pivot); the models' lists are
-- read at the probe's time.
probe { "slide", unit = "m", read = { block, "distance", along = { -1, 0 }, relative_to = wedge } }
probe { "slide_reduced", unit = "m", samples = function(t) return reduced_to(t).slide end, every = spacing }
-- The lift is how far the block's centre has moved off the surface, along the plank's own y
-- axis: 0 to within the contact's slop while it rests or slides, its height in a flight.
probe { "lift", unit = "m", read = { block, "distance", along = { 0, 1 }, relative_to = wedge } }
probe { "normal_force", unit = "N", read = { touch, "normal" } }
-- A contact's force is the mean over the step just taken: the model's at the middle of it.
probe { "normal_reduced", unit = "N", samples = function(t) return reduced_to(t).normal end, every = spacing,
        delay = 0.5 * h }
probe { "slipping", read = { touch, "slipping" } }
probe { "tilt", unit = "°", read = { block, "angle" } }

plot { "Slide along the surface", kind = "time", y = { "slide", "slide_reduced" },
  theory = { { "with the turn", function(t)
    local k = sample(t)
    return turning.slide[k]
  end } } }
plot { "Normal force on the block", kind = "time", y = { "normal_force", "normal_reduced" },
  theory = { { "with the turn", function(t) return mid_step(true, "normal", t) end } } }
-- The article's books for its own reduced model: the kinetic energy gained, ΔK, and the work of
-- the pseudo-force −m·a, of gravity and of friction; their sum (with what landings took, if
-- the block flew) lies on ΔK.
for _, book in ipairs { { "kinetic_gained", "kinetic" }, { "work_pseudo", "work_pseudo" },
                        { "work_gravity", "work_gravity" }, { "work_friction", "work_friction" } } do
  local field = book[2]
  probe { book[1], unit = "J", samples = function(t) return reduced_to(t)[field] end, every = spacing }
end
plot { "Energy books (the article's model)", kind = "time",
  y = { "kinetic_gained", "work_pseudo", "work_gravity", "work_friction" },
  theory = { { "work pseudo + gravity + friction", function(t)
    local k = sample(t)
    return reduced.work_pseudo[k] + reduced.work_gravity[k] + reduced.work_friction[k] + reduced.work_landings[k]
  end } } }

-- Reading the record ----------------------------------------------------------------------
-- Where no model describes the run, the rows say so in words: the block has slid off the
-- plank's end (the turning model says when), or it has tumbled (turned more than 3° against
-- the surface), which neither model allows.
-- When the block leaves the plank, as the turning model has it; worked out once for each
-- solution of the model (the rows below ask many times), which its horizon names: each new
-- solution reaches further. A number, so that the old solution's lists can go.
local left_for, left_at
local function left_the_plank()
  if left_for ~= horizon then
    left_for, left_at = horizon, nil
    for k, s in ipairs(turning.slide) do
      if math.abs(s) > half - 0.5 * block_width then
        left_at = (k - 1) * spacing
        break
      end
    end
  end
  return left_at
end
-- Tumbled before t (turned more than 3° against the surface while on the plank). The record
-- only grows while this script runs (going back in the window replays the run in a fresh one),
-- so each recorded step is looked at once: the first whose tilt is 3° off the surface's.
local tumbling_tilt = 3  -- °
local twist_checked, first_twist = 0, nil  -- steps looked at; when the first such step was
local function tumbled(t)
  if not first_twist then
    local times, tilts = history("time"), history("tilt")
    for i = twist_checked + 1, #tilts do
      if math.abs(tilts[i] - math.deg(theta(times[i]))) > tumbling_tilt then
        first_twist = times[i]
        break
      end
      twist_checked = i
    end
  end
  return first_twist ~= nil and first_twist <= t and first_twist < (left_the_plank() or math.huge)
end
-- The models carry the block turning with the surface. The contact can turn it only as far as
-- its normal force's moment reaches: the surface's angular acceleration θ'' needs I·θ'' about
-- the centre, and friction, e below it, adds −e·f. Past N·w/2 the block rocks onto an edge.
local inertia = mass * (block_width ^ 2 + block_height ^ 2) / 12
-- A stuck contact asked for up to 2 % past μ·N may be held a step while the listener tells the
-- solver's leftover from a real excess (its hold band).
local hold_band = stick_slip_hold_band  -- the listener's (physics/friction_laws.h)
-- Whether the contact's moment falls short of turning the block with the surface at time_t,
-- with that friction and normal force on it.
local start_speed, start_drift, drift_step  -- the world's start off the models' block (below)
local function must_rock(time_t, friction, normal)
  local spin_up = -theta0 * omega * omega * sin(omega * time_t)
  -- At μ = w/h (2, the sliders' end) a block that slips, or is held at μ·N, needs exactly
  -- the most N·w/2 can give: balanced on its front edge, Box2D's single-precision solver
  -- (a few parts in 10^7 a sum, over the step's dozens of sums) decides which way it goes,
  -- so within a part in 10^6 of the edge no model can say either.
  return math.abs(inertia * spin_up + centre_height * friction) > (1 - 1e-6) * 0.5 * block_width * normal
end
-- The first sample at which it would rock, once for each solution of the model; or, if it
-- would at a breakaway between two samples, the sample nearest that.
local pivot_of  -- the pivot on an edge that ends a lift-off's approach (below, by the lift-off's row)
local rocks_for, rocks_from
local function rocks_by(t)
  local last = sample(t)  -- first: it may solve further
  if rocks_for ~= horizon then
    rocks_for, rocks_from = horizon, nil
    local breakaways = {}
    for _, event in ipairs(turning.events) do
      if event.kind == "breakaway" then breakaways[#breakaways + 1] = event.t end
    end
    -- Whether the model's N falls on from sample k into a lift-off (the flight's first sample):
    -- that approach is the lift-off's, whose row allows for the start's press and for the edge.
    local function into_lift_off(k)
      local j = k + 1
      while j <= #turning.normal and turning.contact[j] ~= "flying" and turning.normal[j] < turning.normal[j - 1] do
        j = j + 1
      end
      return j <= #turning.normal and turning.contact[j] == "flying" and j or nil
    end
    -- Rocking on that approach is the pivot the lift-off row's edge follows (see lift_off below),
    -- and no block escapes it: N·w/2 goes to 0 while I·θ'' does not. So it is no "rocks" where
    -- θ'' rocks the block (friction's moment alone, e·|f|, would not) and the pivot, from the
    -- sample before k to the edge letting go, cannot turn the block by the tilt that counts as
    -- tumbling. Read at the samples alone it was "rocks" wherever a sample fell between the rock
    -- and the lift-off: at θ0 38.42°, ω 10 rad/s, 0.1 kg, frictionless (3.3 ms between them), at
    -- 480 Hz and up but not at 240, where the row was checked against an edge that let go 21 ms
    -- before the world's (0.0334 s against 0.0542). (A lift-off whose edge never lets go in the
    -- model's flight, or pulls away by less than the row's uncertainty, only grazes (only_grazes),
    -- and its row says so: there only the start's press is the lift-off's, as before.)
    -- (Friction's moment against the model's N: a block pressed less has less friction too.)
    local function the_lift_offs_pivot(k, friction, pressed_less)
      local flight = into_lift_off(k)
      if not flight then return false end
      local pivot = pivot_of(flight)
      if not pivot then return pressed_less end
      return centre_height * math.abs(friction) < (1 - 1e-6) * 0.5 * block_width * turning.normal[k]
             and pivot.tilt_from(k - 1) <= math.rad(tumbling_tilt)
    end
    local next_breakaway = 1
    -- The world's block runs δs off the models' from its start (start_drift), and there the turn
    -- presses it by m·(θ''·δs + 2θ'·δs') less or more: where N is small, less may be too little
    -- to turn it with the surface. Frictionless, shaken at −21.96 m/s² on a plank swinging 8.3°
    -- at 10 rad/s (0.1 kg), the world's block was 0.27 m off by 2.45 s, pressed 0.2 N less, and
    -- rocked (N 0.011 N, the model's 0.22, which needs 0.056 to turn it); at 960 and 3840 Hz,
    -- closer, it did not. Followed here a sample at a time, at the world's step.
    local gap, gap_speed = 0, turning.contact[1] ~= "sticking" and start_speed() or 0
    local parts = math.max(1, floor(spacing / h + 0.5))
    for k = 1, #turning.slide do
      local time_k = (k - 1) * spacing
      if k > 1 then
        for i = 1, parts do
          gap, gap_speed = drift_step(gap, gap_speed, time_k - spacing + (i - 0.5) * spacing / parts, spacing / parts)
        end
      end
      local press = turn_press(time_k, gap, gap_speed)
      -- A breakaway since the last sample: the friction there is all the limit, μ·N, the way
      -- it held; at μ = w/h that alone needs N·w/2, and the surface's θ'' may add to it (μ = 2,
      -- θ0 = 40°: the model broke away at 0.0061 s and would rock by the next sample, 0.0083 s;
      -- the world's block rocked in its third step and slid only from the sixth). And the world
      -- holds its breakaway step with up to the hold band past μ·N, so from μ = (w/h)/1.02 it
      -- may rock there (μs 1.998: the block turned 0.001° off the surface in that step).
      while breakaways[next_breakaway] and breakaways[next_breakaway] <= time_k do
        local at = breakaways[next_breakaway]
        next_breakaway = next_breakaway + 1
        if k > 1 and turning.contact[k - 1] ~= "flying" then
          local share = (at - (k - 2) * spacing) / spacing
          local normal = turning.normal[k - 1] + share * (turning.normal[k] - turning.normal[k - 1])
          local way = turning.friction[k - 1] ~= 0 and turning.friction[k - 1] or turning.friction[k]
          local limit = math.max(param.mu_s, param.mu_k) * (1 + hold_band) * math.max(normal, 0)
          if way ~= 0 and must_rock(at, direction_of(way) * limit, normal) then
            rocks_from = floor(at / spacing + 0.5) + 1
            break
          end
        end
      end
      if rocks_from then break end
      local friction = turning.friction[k]
      -- A block that must slip from the start is held through the world's first step (see
      -- "first slip" below): the friction then is all the drive along the surface, F = m·a·cos θ
      -- + m·g·sin θ at t = 0, up to max(mu_s, mu_k)·N and the hold band past it, as at any
      -- breakaway (μk 1.999 over μs 0.65, shaken at −21.63 m/s² on a plank swinging 27.09° at
      -- 0.6 rad/s: the drive 10 % past μk·N at t = 0, held at 1.02·μk·N past the block's w/h = 2,
      -- the world's block tilted 2.7° through its 0.2 s slide and slid 5.5 mm short of the model's
      -- at 240 Hz, 1.9 at 480).
      if k == 1 and turning.contact[1] == "slipping" then
        local most = math.max(param.mu_s, param.mu_k) * (1 + hold_band) * turning.normal[1]
        friction = math.max(-most, math.min(most, -drive_along(0)))
      end
      local normal = turning.normal[k]
      if turning.contact[k] ~= "flying"
          and ((must_rock(time_k, friction, normal) and not the_lift_offs_pivot(k, friction, false))
               or (press > 0 and must_rock(time_k, friction, normal - press)
                   and not the_lift_offs_pivot(k, friction, true))) then
        rocks_from = k
        break
      end
    end
  end
  return rocks_from ~= nil and rocks_from <= last
end
-- Box2D moves the block's centre along a straight line each step while the plank turns its
-- surface on an arc, so a block carried round drifts off the surface a little every step:
-- e·Δθ²/2 (e: how far its centre is above the surface), and Δθ·Δs as it slides across the
-- turn (s: the slide), the step's Coriolis term. Nothing pulls it back (Box2D's position
-- solver only pushes bodies apart, past its 5 mm linear slop), so the drift eats into the
-- skins' 5 mm overlap, and when that is gone the contact is lost for a step: the block falls
-- free, and touches down again as a new contact, sliding. At θ0 = 22.67°, ω = 10 rad/s the
-- 5 mm is gone after 4.01 s at 240 Hz. Pressed in instead (a drift inwards), the overlap
-- grows no further than the slop. A landing after a flight starts it afresh, from how deep
-- the landing's last step sank it (below). Summed from the
-- model, the drift comes within 2 % of the world's (the loss at 4.09 s against 4.01 s there;
-- two to three steps early on a sliding block, where the Δθ·Δs term's sign was checked
-- against the world: the other sign is 0.7 s off), so the model calls the contact lost with a
-- tenth of the overlap left. (linear_slop: Box2D's b2_linearSlop, 5 mm, from the runtime.)
-- How far the drift has raised the block's centre off the surface by each sample (linear_slop
-- less the overlap left), kept as a list for the normal force's row.
local lost_for, lost_at, raised
local function follow_the_drift()
  if lost_for ~= horizon then
    lost_for, lost_at, raised = horizon, nil, { 0 }
    local overlap, steps_per_sample = linear_slop, spacing / h
    for k = 2, #turning.slide do
      raised[k] = linear_slop - overlap
      if turning.contact[k] == "flying" then
        -- Landing, the block sinks into the skins for as long as it falls before a step's
        -- start finds the touch, up to a step's fall, and keeps it (only what is past the slop
        -- is pushed out): falling at v, up to v·h, not the slop (a landing at 0.26 m/s, 1.1 mm
        -- at 240 Hz: the world's block, 10 kg on a plank swinging 11.5° at 5 rad/s, shaken at
        -- −30 m/s², lost its contact 0.26 s later, where the slop would have lasted 0.8 s).
        -- The deepest it may be (a world step's fall: a sub-step's under --substeps); the
        -- drift is then followed from there.
        local falling = k > 2 and (turning.height[k - 1] - turning.height[k]) / spacing or 0
        overlap = math.min(linear_slop, math.max(falling, 0) * substep_length())
      else
        local turn = theta((k - 1) * spacing) - theta((k - 2) * spacing)
        local slid = turning.slide[k] - turning.slide[k - 1]
        overlap = math.min(linear_slop, overlap - (centre_height * turn * turn / 2 + turn * slid) / steps_per_sample)
        if overlap < 0.1 * linear_slop then
          lost_at = k
          break
        end
      end
    end
  end
end
local function contact_lost_by(t)
  local last = sample(t)  -- first: it may solve further
  follow_the_drift()
  return lost_at ~= nil and lost_at <= last
end
-- The raise at sample k, from the drift worked out for the model's whole solution.
local function raised_at(k)
  follow_the_drift()
  return raised[math.min(k, #raised)] or 0
end
-- The turn's share of the normal force in the model with the turn: what it has beyond the
-- article's m·(g·cos θ − a·sin θ), which does not depend on where the block is.
local function turn_share(k)
  local t = (k - 1) * spacing
  return turning.normal[k] - mass * (g * math.cos(theta(t)) - pivot_acceleration(t) * sin(theta(t)))
end
-- Box2D solves each step's contact along the normal the step began with, so the turn's share
-- of N reaches the world's normal force a step late: the world's N is the model's less how much
-- that share changed in the last step (and the first step presses with none of it: 44.10 N = m·g
-- at θ0 = 10.94°, ω = 10 rad/s, 4.495 kg, where the model has 42.86 N).
local function late_share(k)
  if k <= 1 then return math.abs(turn_share(1)) end
  return math.abs(turn_share(k) - turn_share(k - 1)) * h / spacing
end
-- A start that slips by less than that: the model's block, lightened by the turn, slips at
-- once, where the world's first step, with the whole weight, holds it; and if the drive a step
-- later still asks no more than the model's limit then, the world may hold on for good (4.495
-- kg, a_x = -9.329 m/s², θ0 = 10.94°, ω = 10, μs 0.9638: 1.5 % over the model's limit at t = 0,
-- 1.3 % under the world's, and the world held on till 0.23 s). Neither model says which way
-- such a start goes. (The drive here is the one on a block at the pivot, the turn's push
-- along the surface, θ''·e, included: drive_at_the_pivot.)
-- Both limits with the listener's hold band: a stuck contact asked for up to 2 % past μ·N may be
-- held a step while the listener tells the solver's leftover from a real excess, and a start
-- holds where the drive falls back under the limit by then (μk 1.65, θ0 19.45°, ω 10: 1.8 %
-- over the model's limit a step in, under it the step after; the world held on till 0.95 s).
-- How far over the limit the drive is at t = 0 does not count: the world's first step asks
-- nothing of the contact (the block starts with the plank's velocities over it), so a step in
-- is the first the world can slip at. On a plank swinging 40° at 6.45 rad/s, shaken at
-- −1 m/s² (μs 0.0987, μk 0, 5.99 kg), the drive is 1.4 % past the model's limit at t = 0 and
-- falls 24 % in a step as the slope turns against it: the model's block slips at once, the
-- world's held on till 0.0375 s, where the sliding model's drive came back past the limit.
local function on_the_edge_at_the_start()
  if turning.contact[1] ~= "slipping" or #turning.normal < 2 then return false end
  local limit = math.max(param.mu_s, param.mu_k) * (1 + hold_band)
  -- The world's first step is a sub-step under --substeps, shorter than the models' samples:
  -- N there from the first two, along the line between them.
  local at = substep_length()
  local normal = turning.normal[1] + (turning.normal[2] - turning.normal[1]) * at / spacing
  return math.abs(drive_at_the_pivot(at)) <= limit * normal
end
-- In a flight the block keeps the spin it left with while the plank's turn changes: by t it is
-- turned φ = θ(t) − θ(t₀) − θ'(t₀)·(t − t₀) against the surface from the lift-off at t₀, which
-- lowers a corner by (w/2)·|sin φ| + (h/2)·(1 − cos φ) below its face.
local function corner_drop(lifted, t)
  local turned = theta(t) - theta(lifted) - theta0 * omega * math.cos(omega * lifted) * (t - lifted)
  return 0.5 * block_width * math.abs(sin(turned)) + 0.5 * block_height * (1 - math.cos(turned))
end
-- A landing of the model's flight where that corner is more than the skins' overlap below the
-- face: the world's block comes down on its corner first and is slapped flat, its impact and
-- friction there none of the model's flat plastic landing (shaken at 19.5 m/s² on a plank
-- swinging 20.8° at 1.38 rad/s, 3.3 kg, μs 1.38, μk 0.12: turned 2.5° in a 0.38 s flight, a
-- corner 6.6 mm down; at 240 Hz the world's block stopped within 0.06 s of landing, under μk
-- where the model's slid on, ΔK 0.39 J against 2.47 J; at 480 Hz it slid on). Looked for
-- once for each solution of the model (its horizon).
local corner_for, corner_at
local function landed_on_a_corner_by(t)
  local last = sample(t)  -- first: it may solve further
  if corner_for ~= horizon then
    corner_for, corner_at = horizon, nil
    local first
    for k = 2, #turning.contact do
      if turning.contact[k] == "flying" and turning.contact[k - 1] ~= "flying" then first = k end
      if first and turning.contact[k] ~= "flying" and turning.contact[k - 1] == "flying" then
        if corner_drop((first - 1) * spacing, (k - 1) * spacing) > linear_slop then
          corner_at = k
          break
        end
      end
    end
  end
  return corner_at ~= nil and corner_at <= last
end
local breakaways_shifted  -- what a breakaway's timing moves the slide by (below, by the rows)
local grazes_by  -- a stuck stretch that only grazes the static limit (below, after start_drift)
local function no_model(t)
  if on_the_edge_at_the_start() then return "on the edge at the start: no model" end
  local left = left_the_plank()
  if left and left <= t then return "off the plank by then" end
  if rocks_by(t) then return "rocks: no model" end
  if contact_lost_by(t) then return "Box2D loses the contact: no model" end
  if tumbled(t) then return "tumbled: no model" end
  if landed_on_a_corner_by(t) then return "landed on a corner: no model" end
  if grazes_by(t) then return "grazes the static limit: no model" end
end
local function recorded(name, t)
  return reached(t) and value_at(name, t) or nil
end
local function first_event(run, kind)
  for _, event in ipairs(run.events) do
    if event.kind == kind and event.t <= duration then return event.t end
  end
end
-- How far apart the world's start (the plank's first-step velocity, a_x·h/2) carries the block
-- from the models' by t, and how fast: until the models' block first sticks, the two slide
-- side by side (after it, 0 fast while it sticks). On a turning plank the gap is flung outwards
-- as the block is, δs'' = θ'²·δs (frictionless at a_x 11.19, θ0 5.3°, ω 4.7 rad/s: 0.15 m in
-- 5 s, where the start's speed alone makes 0.12), and sliding, it also moves N and so kinetic
-- friction, by μk·m·(θ''·δs + 2θ'·δs') (start_drift below).
-- Nor does it follow the world through a reversal the block slides through: Box2D turns a
-- step's friction only at a step's start, so when the reversal falls between steps the world's
-- gap speed is changed by up to 2·μk·(N/m)·h there, while Coulomb's law shrinks any offset at a
-- reversal by (|D| − μk·N)/(|D| + μk·N) (D the drive along the plank). A bound that added the
-- kicks up was tried and made the rows too wide to fail; a level plank shaken hard (a_x −17,
-- a_x_omega 3.1, μk 0.59) is left 0.016 m/s off, beyond the rows' tolerance.
-- Kept for each t and solution of the model: the rows ask it every time they are read.
-- A block that must slip from the start: the world's starts with the plank's first-step
-- velocity, a_x·h/2 ahead of the plank's at t = 0, but in that first step the plank moves at the
-- block's own velocity and asks no friction of it, where the model's block slides with μk·N on
-- it from t = 0. Both together leave the world's block half a step behind the model's slide:
-- the model's own sliding acceleration at the start, (|D| − μk·N)/m, times h/2 (D the drive
-- along the plank). (Taken as |a_x|·h/2 alone, which leaves out the first step's kinetic
-- friction, it overstated the world's offset: 0.042 m/s where the world's was 0.0028 on a level
-- plank shaken at 20 m/s² with μk 1.9 > μs; 0.042 against 0.019 at a_x −20.31, μk 1.067, μs
-- 0.812, θ0 23.8°, ω 2.4 rad/s, 9.9 kg, now 0.021. Across 34 random starts that slip, the
-- world's offset is 0.73 to 1.02 times this, the rest the turn's share of N below.) The
-- world's block is then held through the step that first asks friction of it (the second), at
-- the limit μ·N (and the hold band past it). The
-- breakaway correction then gives back what was held past μ·N, and (μ − μk)·N for a span of
-- late + h/2, where `late` is how long before the step's end the demand crossed μ·N, found as
-- if it had grown evenly through the step from what the step before held, D1: late =
-- h·(D − μ·N)/(D − D1). But this demand D came all at once, with the plank's first change of
-- velocity, so the block keeps (μ − μk)·(N/m)·(h/2 − late) more along the drive than the
-- model's (level plank shaken at 13.87 m/s², μk 0: +0.0171 m/s at μs 1.2, −0.0035 at μs 0.3,
-- as the world's).
function start_speed()
  local h = substep_length()  -- the world's first step, a sub-step with --substeps
  local limit = math.max(param.mu_s, param.mu_k)
  local normal = turning.normal[1]
  local demand = math.abs(drive_at_the_pivot(h))
  local before = mass * g * math.abs(sin(theta(0.5 * h)))
  local late = demand > before and math.max(0, math.min(h, h * (demand - limit * normal) / (demand - before))) or 0
  local held_back = (limit - param.mu_k) * normal / mass * (0.5 * h - late)
  local sliding = math.max(0, math.abs(drive_along(0)) - param.mu_k * normal) / mass
  -- (and the world's kinetic friction in its first sliding step presses with the turn's share
  -- of N a step late: μk·late_share for that step)
  local late_press = #turning.normal >= 2 and param.mu_k * late_share(2) / mass * h or 0
  return math.abs(sliding * 0.5 * h + held_back) + late_press
end
-- One step dt long, at time_i, of the gap between the world's block and the model's and its
-- speed (start_drift says how it moves).
-- Sliding, the world's kinetic friction also presses with the turn's share of N a step late
-- (late_share): μk·(how much that share changes in a world step) less or more than the model's,
-- m·δs'' = σ·μk·(share's rate)·h, which sets the two apart on every slide, even where both start
-- stuck. Left out, μs 0 under μk 0.8462 on a plank swinging 36.82° at 7.228 rad/s (5.084 kg,
-- a_x 0.3985 at 6.863 rad/s): the block slides to and fro from 0.12 s, each slide's Coriolis
-- push 2m·θ'·s' changing by up to 17 N, and the world's block slides up to 0.022 m/s faster by
-- the sixth (0.011 at 480 Hz): 0.69 N off the model's N at 2.5 s (0.36 at 480 Hz, 0.18 at 960),
-- where the row allowed 0.60 and counted no gap at all (both start stuck). Followed here with
-- the turn's drift below, the gap matches the world's over the first slide and stop (0.66 mm
-- against 0.46, then 0.88 against 0.65 after the stop's drift) but grows less from slide to
-- slide than the world's (0.8 mm against 2.0 by 2.3 s; its speed 0.010 m/s at 2.5 s against
-- 0.020): each of the world's slides turns the gap it starts with round a little more than
-- the linearised model does, which is not explained yet.
local function share_rate(k)
  if k < 2 or turning.contact[k] == "flying" or turning.contact[k - 1] == "flying" then return 0 end
  return (turn_share(k) - turn_share(k - 1)) / spacing
end
function drift_step(gap, gap_speed, time_i, dt)
  local k = math.min(floor(time_i / spacing + 0.5) + 1, #turning.contact)
  local state = turning.contact[k]
  if state == "sticking" then
    gap_speed = 0
  else
    local turn_rate = theta0 * omega * math.cos(omega * time_i)
    local spin_up = -theta0 * omega * omega * sin(omega * time_i)
    -- (the drift's raise δe of the centre: the turn's Euler push along the surface, −θ''·δe,
    -- and its fling off it, m·θ'²·δe less N)
    local lift = raised_at(k)
    local pull = turn_rate * turn_rate * gap - spin_up * lift
    if state == "slipping" then
      local way = direction_of(turning.speed[k])
      pull = pull + way * param.mu_k * (spin_up * gap + 2 * turn_rate * gap_speed + turn_rate * turn_rate * lift
                                        + share_rate(k) * substep_length() / mass)
    end
    gap_speed = gap_speed + pull * dt
  end
  -- And the turn's drift (see "slide at the end"): each world step moves the block along a
  -- chord while the plank turns under it, s·(θ'·h)²/2 further out, stuck or sliding.
  local turn_rate = theta0 * omega * math.cos(omega * time_i)
  local drift = turning.slide[k] * turn_rate * turn_rate * 0.5 * substep_length()
  return gap + (gap_speed + drift) * dt, gap_speed
end
local drifts, drifts_for = {}, nil
function start_drift(t)
  if drifts_for ~= horizon then drifts, drifts_for = {}, horizon end
  if drifts[t] then return drifts[t][1], drifts[t][2] end
  local moving = turning.contact[1] ~= "sticking"
  local gap, gap_speed = 0, moving and start_speed() or 0
  -- After the first stop the world's block stays δs from the model's, and where the two slide
  -- again that gap moves the forces on it: the turn flings it by m·θ'²·δs, presses it by
  -- −m·θ''·δs more, and sliding (σ the way it slides, friction −σ·μk·N) both that and the
  -- Coriolis push of a gap speed, −2m·θ'·δs', change kinetic friction. So the gap follows the
  -- model's run's own linearisation, δs'' = θ'²·δs + σ·μk·(θ''·δs + 2θ'·δs'), with δs' = 0
  -- wherever the model's block sticks (both stop). Left out, a block shaken at 19 m/s² with
  -- μs 0 and μk 1.187 on a plank swinging 5.9° at 6.7 rad/s was 0.005 m apart after its first
  -- stop and 0.034 m at the end (0.017, 0.0088, 0.0044 m at 480, 960, 1920 Hz: the start's
  -- first order), pressed up to 1 N harder than the model's on each slide up the slope.
  -- At most 2000 steps of it, whatever the world's rate (a tolerance is read often).
  local count = math.min(math.floor(t / h + 0.5), 2000)
  local dt = count > 0 and t / count or 0
  for i = 1, count do gap, gap_speed = drift_step(gap, gap_speed, (i - 0.5) * dt, dt) end
  drifts[t] = { math.abs(gap), math.abs(gap_speed) }
  return drifts[t][1], drifts[t][2]
end
-- A stuck stretch whose demand only grazes the static limit: it comes within what the world's
-- demand may sit off the model's of μ·N and turns back (the model holds on, the world may break
-- away), or passes the limit by less than that before it would turn back (the model breaks
-- away, the world may hold on). Where the world then takes the other way, the run after it
-- follows that outcome, and no model can say which it would be: μs 1.3103, μk 0.7755, θ0 7.71°,
-- ω 3.428, a_x −16.57 at 4.777 rad/s, 8.022 kg: the model breaks away at 3.914 s with its
-- demand just past μs·N (at μs 1.3105 it holds on, and ends 0.24 m away); the world, stopped
-- at 3.10 s 4.6 mm further along than the model's block (the start's offset), asks at most
-- 0.9994·μs·N at 240 Hz and holds on to 4.44 s (0.987 m against 0.743 at the end). At μs 1.31
-- the same at 240 and 480 Hz (the world's block, 4.6 and 1.9 mm along, holds on to 4.44 s:
-- 0.987 m against 0.731), and at 960 Hz, 1.1 mm along, it breaks away with the model at 3.91 s
-- and the rows are checked: 0.739 m against 0.731. So a grazing
-- is excused only where the world's record shows the other outcome near it; where the world
-- goes the model's way the rows after it stay checked (at μs 1.3105 both hold on, and the
-- slide ends 0.0050 m off the model's at 240 Hz, 0.0014 at 960). The record is read once the run has
-- passed the grazing's reach: a grazing the run ends inside is left checked.
-- What the world's demand may sit off the model's, in N, is bounded from what the rows
-- predict, not from what the world did: stuck, a block δs further along the turning surface is
-- flung along it by m·θ'²·δs more and pressed by m·θ''·δs more, which moves the limit by μ
-- times that, and δs is at most the slide row's own bound there (start_drift's gap, 0.2 % of
-- the path slid and 3 mm, the row's bound so far); the turn's share of N
-- arrives a step late (late_share), moving the limit by μ times it; and the listener takes
-- friction within 1e-5 of μ·N for friction at the limit (its breakaway tolerance); and the
-- impulses round the demand and the limit (impulse_rounding, times 1 + μ). The
-- listener's hold band is no part of it: the band keeps a stuck contact past μ·N only for an
-- excess that looks like the solver's leftover (the block sliding into the step) or that halves
-- each step, and a smooth, lasting excess on a stuck block breaks away at once; allowing the
-- band here would excuse a world that holds on 2 % past μ·N, which the rows exist to catch.
local grazing_for, grazing_scanned, grazing_at, grazing_path
-- The world's record from `from` to `to` (s): whether the block broke away there (a step
-- recorded slipping after one recorded not), whether it was recorded slipping at all, and
-- whether it was recorded stuck (not slipping) at any step.
local function world_between(from, to)
  local times, slipping = history("time"), history("slipping")
  local low, high = 1, #times
  while low < high do
    local middle = (low + high) // 2
    if times[middle] < from then low = middle + 1 else high = middle end
  end
  local broke, slipped, held = false, false, false
  for i = low, #times do
    if times[i] > to then break end
    if slipping[i] == 1 then
      slipped = true
      if i > 1 and slipping[i - 1] == 0 then broke = true end
    else
      held = true
    end
  end
  return broke, slipped, held
end
-- Single precision: a step's contact impulses keep that step's roundings of the block's
-- velocity, (1 + 9·k)·2^-24 of it over h for k = 4 constraints (two points, normal and
-- friction), times m. So much may the world's normal force at sample k sit off the model's,
-- and its friction or its demand on a stuck block, the plank's speed, and the turn's at the
-- block, growing as the step shrinks.
local function impulse_rounding(k)
  local t = (k - 1) * spacing
  local pivot_speed = a_x_omega == 0 and math.abs(a_x) * t or math.abs(a_x * sin(a_x_omega * t) / a_x_omega)
  local turn_rate = theta0 * omega * math.abs(math.cos(omega * t))
  local block_speed = g * substep_length() + pivot_speed + turn_rate * (math.abs(turning.slide[k]) + centre_height)
                      + math.abs(turning.speed[k])
  return (1 + 9 * 4) * 2 ^ -24 * mass * block_speed / substep_length()
end
-- What the world's demand on a stuck block may sit off the model's at sample k (N), where the
-- world's block may stand `gap` (m) off the model's along the plank, with `limit` the static
-- coefficient (see above): the turn presses it by m·θ''·gap and flings it by m·θ'²·gap.
local function demand_uncertainty(k, gap, limit)
  local time_k = (k - 1) * spacing
  local turn_rate = theta0 * omega * math.cos(omega * time_k)
  local spin_up = theta0 * omega * omega * math.abs(sin(omega * time_k))
  return gap * mass * (turn_rate * turn_rate + limit * spin_up) + limit * late_share(k)
         + 1e-5 * limit * turning.normal[k] + (1 + limit) * impulse_rounding(k)
end
-- The world sees the demand at its steps only, where the margin's least may fall between two:
-- the nearest step, up to half a step off it, misses it by |m''|·(h/2)²/2, and the plank, moved
-- through each step at that step's mean velocities, gives a stuck block the second difference
-- of its path over the step, off the acceleration by its second derivative times h²/12. So a
-- margin bending by `bending` a sample² may stand |m''|·(h²/8 + h²/12) higher in the world.
-- (0.1 kg shaken at 2.37 m/s² at 10 rad/s on a plank swinging 6.1° at 0.21 rad/s: the model's
-- demand passes μs·N by 1.3e-4 N for a few milliseconds at 3.139 s and it breaks away; at
-- 240 Hz the world's held, and broke away a shake later, at 3.75 s; at 480 Hz it broke away
-- with the model. This term there: 8.7e-5 N at 240 Hz, two thirds of the excess; the rest of
-- that setting is held_through's, below.)
local function peak_between_steps(bending)
  local step = substep_length() / spacing  -- the world's step in samples
  return math.abs(bending) * (1 / 8 + 1 / 12) * step * step
end
-- And a demand past the limit for less than two of the world's steps, by less than the
-- listener's hold band, may be held through: the listener keeps a stuck contact whose excess
-- looks like the solver's leftover, within the band, and keeps it while the excess dies away
-- from step to step, as a brief peak's does. So the world may hold where the model broke away
-- (the shaken block above: 1.3e-4 N past μs·N, 0.04 % of it, for 1.6 steps at 240 Hz).
local function held_through(least, bending, limit_force)
  if least >= 0 or bending <= 0 or -least > hold_band * limit_force then return false end
  local over_for = 2 * math.sqrt(-2 * least / bending) * spacing  -- s, the margin under 0
  return over_for <= 2 * substep_length()
end
function grazes_by(t)
  local last = sample(t)  -- first: it may solve further
  if grazing_for ~= horizon then
    -- The scan starts at sample 3 (it needs two before it); the path counts from sample 1, as the
    -- slide row's does.
    local first_leg = #turning.slide >= 2 and math.abs(turning.slide[2] - turning.slide[1]) or 0
    grazing_for, grazing_scanned, grazing_at, grazing_path = horizon, 2, nil, first_leg
  end
  local limit = math.max(param.mu_s, param.mu_k)
  local function stuck(k) return turning.contact[k] == "sticking" end
  local function margin(k) return limit * turning.normal[k] - math.abs(turning.friction[k]) end
  -- The block's place is as sure as the slide row's: the start's drift, 0.2 % of the path and 3 mm.
  local function allowed(k, path)
    return demand_uncertainty(k, start_drift((k - 1) * spacing) + 0.002 * path + 3e-3, limit)
  end
  -- (The world's record is read record_lag past the grazing.)
  while not grazing_at and grazing_scanned < math.min(last, #turning.slide - 1) do
    local k = grazing_scanned + 1
    local path = grazing_path + math.abs(turning.slide[k] - turning.slide[k - 1])
    -- Where the world's record must be read to tell which way it went: none, or from, to (s).
    local from, to
    if stuck(k - 2) and stuck(k - 1) and stuck(k) then
      local falling = margin(k) - margin(k - 1)                    -- per sample
      local bending = margin(k) - 2 * margin(k - 1) + margin(k - 2)  -- per sample²
      if stuck(k + 1) then
        -- The margin's least within the stretch: within reach, and it turns back. The world
        -- may slip wherever the model's margin is within reach: the samples around k where it
        -- is, and the crossings between them and the next.
        local reach = falling <= 0 and margin(k + 1) > margin(k) and allowed(k, path) + peak_between_steps(bending)
        if reach and margin(k) < reach then
          local first, final = k, k
          while first > 1 and stuck(first - 1) and margin(first - 1) < reach do first = first - 1 end
          while final < #turning.slide and stuck(final + 1) and margin(final + 1) < reach do final = final + 1 end
          from, to = (first - 2) * spacing, final * spacing + record_lag
        end
      elseif turning.contact[k + 1] == "slipping" and bending > 0 then
        -- It broke away before sample k + 1: the margin carried on as it went (a parabola
        -- through the last three stuck samples, m_k + rate·x + bending·x²/2, x in samples
        -- after k) would bottom out within reach and turn back. The world's
        -- block may break away wherever the model's margin is within reach of the limit: from
        -- the stuck samples before k where it is, up to the parabola's later crossing of it.
        local rate = falling + 0.5 * bending
        if rate < 0 then
          local reach = allowed(k, path) + peak_between_steps(bending)
          local least = margin(k) - rate * rate / (2 * bending)
          if least > -reach or held_through(least, bending, limit * turning.normal[k]) then
            local later = (-rate + math.sqrt(math.max(rate * rate - 2 * bending * (margin(k) - reach), 0))) / bending
            local first = k
            while first > 1 and stuck(first - 1) and margin(first - 1) < reach do first = first - 1 end
            from, to = (first - 2) * spacing, (k - 1 + later) * spacing + record_lag
          end
        end
      end
    end
    if from then
      if time() < to then break end  -- the world has not got there yet: asked again later
      local broke, slipped = world_between(from, to)
      -- The other outcome: the model held on and the world broke away, or the model broke
      -- away and the world was never seen slipping there.
      if (stuck(k + 1) and broke) or (not stuck(k + 1) and not slipped) then grazing_at = k end
    end
    grazing_scanned, grazing_path = k, path
  end
  return grazing_at ~= nil and grazing_at <= last
end
local function first_recorded(name, test)
  local times, values = history("time"), history(name)
  for i = 1, #values do
    if test(values[i]) then return times[i] end
  end
end

-- Where the block breaks away from a stop, the breakaway comes when the demand, growing, meets
-- the limit μs·N, falling. The world's block breaks away where its own margin, μs·N less the
-- friction holding it, runs out; the listener places that crossing inside the step and gives
-- the slide back what the step held past it (breakaway_correction), so the step itself leaves
-- no first-order shift. What moves the world's breakaway off the model's is its margin sitting
-- off the model's, over the rate the margin closes: for that long one block is stuck while the
-- other slides, so their speeds part by (μs − μk)·N/m times it, and that difference carries on
-- until the model's block next stops (both stuck then), where it has moved the block by the
-- speed times that stretch. Shaken at −26.9 m/s² at 4.009 rad/s on a plank swinging 1.769° at
-- 6.867 rad/s (3.649 kg, μs 1.811, μk 0.2014), a stop from 0.7276 s ends at 0.7355 s as the
-- margin closes at 146 N/s, and the block then slides 4.26 s with the speeds 23.1 m/s² apart.
-- Measured there, at 240, 480, 960, 1920, 3840 and 7680 Hz: the speed the world's block leaves
-- with says it broke away 1.23, 1.71, 0.55, 0.63 ms early, 1.22 ms late and 7.3 ms early, and
-- the slide ends 0.15, 0.16, 0.056, 0.056, −0.094 and 0.58 m off the model's 0.366 m. Two
-- causes, one that the model gives and one that it does not:
-- - The world's block stops where the start carried it, start_drift's gap off the model's
--   (0.0465 m at 240 Hz, start_drift 0.0457; 0.0057 m at 1920 Hz, 0.0057), and there the turn
--   presses it by m·θ''·δs and flings it by m·θ'²·δs otherwise; and the turn's share of N reaches
--   it a step late (late_share), with the listener's 1e-5 of μ·N. That is the allowance below:
--   4.5 ms at 240 Hz, 0.58 at 1920, halving with the step. (The grazing's bound,
--   grazes_by, takes δs as the slide row's whole bound, its 0.2 % of the path and 3 mm
--   too, which are the slide's own leeway and not where the block stopped: 5.0 ms at 240 Hz.)
-- - The world's margin from step to step: N alternates between two levels from one step to
--   the next, 0.5 % of it apart at 3840 Hz and over 2 % at 7680 Hz (the world's N 0.13, 0.22
--   and 1.3 N from the model's, standard deviation, at 1920, 3840 and 7680 Hz; nothing in the
--   model's forces moves so), and the listener holds a stuck contact up to its hold band past
--   μs·N while the excess looks like the solver's leftover, which on a driven plank it always
--   does (the plank's change of velocity at the step's start is sliding the way of the excess).
--   So the world breaks away late, stuck until the demand passes N's higher level, or early
--   where N's low level falls past the band, as at 7680 Hz. Only the band bounds it
--   (hold_band·μs·N over the closing rate, 13 ms here, 1.3 m of slide), and that bound is
--   useless where the world keeps to the model: on a level plank shaken at −14.35 m/s² (10 kg,
--   μs 0.9453, μk 0.5916) it would be 0.062 m on a slide of 0.058 m that the world ends 0.010,
--   0.0026 and 0.00062 m off at 240, 960 and 3840 Hz, the first part's halving.
-- So the world's record says which it was, as for a grazing: where the world's block broke away
-- from that stop before the model's less the first part, or later than the model's and the
-- first part and the record's three and a half steps (the first slip row says why), the slide
-- after it has no model and the row says so (slow_breakaway_by); elsewhere the row allows the
-- first part. Here that leaves 240 to 3840 Hz checked (1.23 ms early against 4.5 ms allowed at
-- 240 Hz; 0.63 against 0.58 ms at 1920 Hz, the record one step past the model, within the
-- record's lag: 0.056 m off, 0.15 m allowed; at 3840 Hz recorded 2.0 ms late, inside what the
-- impulses' rounding allows, 0.094 m off, 0.16 allowed), and 7680 Hz (7.3 ms early) in words. A world that slides through the model's stop without
-- stopping has no breakaway there either, and the slide after it no model: at mu_k 0, μs
-- 0.7079 on a plank swinging 12.52° at 1.911 rad/s, shaken at 27.27 m/s² (6.517 kg), the model
-- stops for 0.07 s at 4.2 s and the world's block at 240 Hz slides on, 0.41 m off at the end.
-- (A breakaway from t = 0 is the start's: start_speed.) The sum over the breakaways before t,
-- m, and those breakaways: when the stuck stretch began, when the model breaks away, and the
-- first part over the closing rate (s).
local shifted_for, shifted, shifted_from = nil, {}, {}
function breakaways_shifted(t)
  if shifted_for ~= horizon then shifted_for, shifted, shifted_from = horizon, {}, {} end
  if shifted[t] then return shifted[t], shifted_from[t] end
  local last = sample(t)
  local limit = math.max(param.mu_s, param.mu_k)
  local function stuck(k) return turning.contact[k] == "sticking" end
  local function margin(k) return limit * turning.normal[k] - math.abs(turning.friction[k]) end
  local total, from = 0, {}
  for _, event in ipairs(turning.events) do
    local j = floor(event.t / spacing) + 1  -- the last sample at or before it
    if event.kind == "breakaway" and event.t > 0 and j < last and j > 2 and stuck(j) and stuck(j - 1) then
      local closing = (margin(j - 1) - margin(j)) / spacing
      if closing > 0 then
        local off = demand_uncertainty(j, start_drift((j - 1) * spacing), limit)
        local parting = math.max(limit - param.mu_k, 0) * turning.normal[j] / mass
        local stop = j + 1
        while stop < last and not stuck(stop) do stop = stop + 1 end
        total = total + parting * off / closing * ((stop - 1) * spacing - event.t)
        local first = j
        while first > 1 and stuck(first - 1) do first = first - 1 end
        from[#from + 1] = { stuck_from = (first - 1) * spacing, at = event.t, late = off / closing }
      end
    end
  end
  shifted[t], shifted_from[t] = total, from
  return total, from
end
-- The slide at t where a breakaway from a stop before it leaves it no model (see above): the
-- world's record shows its block breaking away from that stop outside what the first part
-- allows, or not at all by then. Asked before the record gets there, it waits; once it has
-- read the record for every such breakaway before t, the answer is kept.
local slow_for, slow = nil, {}
local function slow_breakaway_by(t)
  local _, breakaways = breakaways_shifted(t)  -- first: it may solve further
  if slow_for ~= horizon then slow_for, slow = horizon, {} end
  if slow[t] ~= nil then return slow[t] or nil end
  local times, slipping = history("time"), history("slipping")
  for _, b in ipairs(breakaways) do
    local to = b.at + b.late + record_lag
    if time() < to then return nil end
    local low, high = 2, #times  -- the first record after the stuck stretch began
    while low < high do
      local middle = (low + high) // 2
      if times[middle] <= b.stuck_from then low = middle + 1 else high = middle end
    end
    local broke_at
    for i = low, #times do
      if times[i] > to then break end
      if slipping[i] == 1 and slipping[i - 1] == 0 then
        broke_at = times[i]
        break
      end
    end
    if not broke_at or broke_at < b.at - b.late then
      slow[t] = "a slow breakaway: no model"
      return slow[t]
    end
  end
  slow[t] = false
end

-- A stop of the model's that the world's block slid through without a stuck step: the model's
-- block stays put while the world's slides on, and nothing after it has a model (slow_breakaway_by
-- finds this where the model breaks away again before t; this, where it is still stuck, or broke
-- away after t). Looked for where the model holds the block for the record's lag (3.5 steps, the
-- first slip row says why) or longer, in the world's record within that lag of the stop. (μs 1.8, μk
-- 0.061, a plank swinging 12.7° at 4.3 rad/s, shaken at 15.7 m/s², 6.26 kg: the model stops
-- at 1.927 s and holds, asked for 91 % of μs·N; at 240 Hz the world's block turned round in
-- that step and slid on, 1 m further up the plank by 2.5 s and pressed 25 N harder there. At
-- 480 Hz and 960 Hz it stops with the model and the rows agree.)
local flew_where_the_model_did_not_by  -- the world's block flew where the model's did not (below, by the lift-off's row)
local through_for, through = nil, {}
local function slid_through_a_stop_by(t)
  if through_for ~= horizon then through_for, through = horizon, {} end
  if through[t] ~= nil then return through[t] or nil end
  for _, event in ipairs(turning.events) do
    if event.kind == "stop" and event.t <= t then
      local after = floor(event.t / spacing) + 2  -- the first sample after the stop
      local held_to = after
      while held_to <= #turning.contact and turning.contact[held_to] == "sticking" do held_to = held_to + 1 end
      local held_until = math.min((held_to - 1) * spacing, t)
      if held_until - event.t >= record_lag then
        local to = event.t + record_lag
        if time() < to then return nil end
        local _, _, held = world_between(event.t - record_lag, to)
        if not held then
          through[t] = "slid through a stop: no model"
          return through[t]
        end
      end
    end
  end
  through[t] = false
end

-- The same equations stepped as the world steps them (theory.wedge's stepped_slide and
-- stepped_speed, given the world's step: physics/wedge_model.h's step_as_the_world says how): the
-- plank's kick once a step, friction decided once a step, a turn inside a step stopped there, a
-- breakaway step held and paid back as the listener does, the block moved at the step's end
-- velocity; following the model's stick and slip, so how far a breakaway's timing moves the slide
-- is breakaways_shifted's. Stepped so, the reduced equations with the turn end off their exact
-- solution by a first-order error of the world's sign, halving with the step as the world's does.
-- On a level plank shaken at 26.49 m/s² (3.254 rad/s) while swinging 2.055° at 6.55 rad/s, 10 kg,
-- μk 0.6437, μs 0.7268, the block sliding to and fro without a stop: −0.117 m at 240 Hz, where the
-- world's slide ends −0.089 m off (−0.044 and −0.022 at 480 and 960 Hz); start_drift carries the
-- start's gap through no reversal, 0.026 m there. A quarter of a second in, this and the world
-- agree to half a millimetre on five of six settings looked at (the sixth, μk 2 over μs 0.65 on a
-- plank swinging 27° at 0.6 rad/s, shaken at 21.6 m/s²: the world 5.3 mm off at once, this 0.9 mm,
-- and faster than first order: 1.9 mm at 480 Hz, 0.15 at 960); by the end it is 0.86 to 1.9 times
-- the world's gap: where the world's block slides a long way its gap grows more slowly than the
-- stepped equations', which is not explained yet (the block's own turn and its two contact points
-- are not in them). start_drift has the turn's drift and the late share of N, which this leaves
-- out. So the slide row takes the larger of this and start_drift with breakaways_shifted. Not
-- followed into a flight (the lists end at its start).
-- How far the stepped equations end off the exact ones at t (m), and how much faster (m/s).
-- Past a flight's start, the gap they had reached there: a flight changes no speed along the
-- surface by friction, and after it both blocks slide with the same kinetic friction, so the
-- speed gap carries on, moving the slide, until the model's block next sticks (both still then).
-- (Taken as it stands: a landing's share is landings_shifted's, and a reversal without a stop
-- scales the gap by the ratio of the sliding accelerations either side, which this leaves out.)
-- (0.1 kg on a plank swinging 18.1° at 7.6 rad/s, shaken at 21.4 m/s², μk 0.72: the stepped
-- equations 0.227 m/s slow at the lift-off at 0.75 s at 240 Hz, and the world's ΔK read in the
-- flight 0.038 J under the model's, m·|v|·δv + ½m·δv² 0.038 J; 0.017 and 0.0092 J at 480 and
-- 960 Hz, this 0.016 and 0.0077.)
local function stepping_gap(t)
  local k = sample(t)
  local last = math.min(k, #turning.stepped_slide)
  if last < 1 then return 0, 0 end
  local gap = math.abs(turning.stepped_slide[last] - turning.slide[last])
  local speed_gap = math.abs(turning.stepped_speed[last] - turning.speed[last])
  local j = last + 1
  while j <= k and turning.contact[j] ~= "sticking" do j = j + 1 end
  gap = gap + speed_gap * (j - 1 - last) * spacing
  return gap, j <= k and 0 or speed_gap
end

-- How far the landings before t put the world's slide off the model's, m: each one's change of
-- the model's sliding speed (from the sample before it to the one after) times a world step (the
-- world meets the surface within its own step, a sub-step under --substeps, not the frame's).
local function landings_shifted(t)
  local total = 0
  for _, event in ipairs(turning.events) do
    local j = floor(event.t / spacing) + 1  -- the last sample at or before it
    if event.kind == "landing" and event.t <= t and j + 1 <= #turning.speed then
      total = total + math.abs(turning.speed[j + 1] - turning.speed[j]) * substep_length()
    end
  end
  return total
end

-- How far the landings before t put the world's sliding speed off the model's, m/s. The model's
-- block lands at an instant, its impact's friction impulse μk times its approach speed across
-- the surface; the world's meets the surface inside a step and is stopped across it at the
-- step's end, its approach speed up to a step's change of it off: the surface's acceleration
-- off the block there (the flight's height's second difference, before the landing) times a
-- step, and μk times that off along it. (0.1 kg, μk 1.84, a plank swinging 40° at 0.9 rad/s,
-- shaken at 15.4 m/s² at 10 rad/s, three landings: the world's speed at 5 s 0.23 m/s over the
-- model's at 240 Hz, 0.07 at 960; this gives 0.26 and 0.067.)
local function landings_speed_shifted(t)
  local total = 0
  for _, event in ipairs(turning.events) do
    local j = floor(event.t / spacing) + 1  -- the last sample at or before it
    if event.kind == "landing" and event.t <= t and j >= 3 then
      local away = (turning.height[j] - 2 * turning.height[j - 1] + turning.height[j - 2]) / (spacing * spacing)
      total = total + param.mu_k * math.abs(away) * substep_length()
    end
  end
  return total
end

-- The mirror of a stop slid through: the model's block slides on where the world's may stop,
-- and stops. Each run then follows its own way, and nothing after it has a model. Two places:
-- - A low of the model's sliding speed that keeps its sign, within what the world's speed may
--   sit off it of 0. That bound is the rows' own: the larger of start_drift's and stepping_gap's
--   speed gaps (as the slide row takes the larger of their gaps), the landings' shift of the
--   speed, and a step's change of the model's speed there (the world decides a stop once a
--   step). (μk 0 under μs 0.8921 on a plank swinging 11.83° at 5.576 rad/s, shaken at 11.44 m/s²
--   at 6.386 rad/s, 7.067 kg: the model's block slows to 0.060 m/s at 1.69 s and slides on; at
--   240 Hz the world's, 0.06 m/s slower there, stuck from 1.683 s to 1.792 s and lifted off
--   0.045 s after the model's; at 480, 960 and 1920 Hz it slid on with the model, its lift-off
--   0.014, 0.0075 and 0.0033 s after it.)
-- - A reversal the model slides through, its demand (the tangential force but friction) past
--   μ·N as the speed passes 0, by less than the world's demand may sit off it there: its
--   demand_uncertainty (with the start's drift as the gap), and the demand's rate times how much
--   earlier or later the world's block may turn round, the speed's bound over the acceleration.
--   (μk 0 under μs 1.301 on a plank swinging 12.12° at 3.131 rad/s, shaken at −30 m/s² at 10
--   rad/s, 7.916 kg: the model's block turns round at 2.55 s with its demand 1.6 to 5.9 N past
--   μs·N, where the world's may sit 9.3 N off; at 240 Hz the world's block, 0.0625 m/s ahead
--   since its first step (μk 0 keeps the start's offset), stuck there for 0.16 s and lifted off
--   0.041 s before the model's; at 960 and 1920 Hz it turned round with the model and lifted off
--   0.0008 and 0.0029 s before it. Three more random settings of 12 200 went so.)
-- The world's record is read over where the model's block may stop, and the record's lag either
-- side: the low's samples within the speed's bound of 0, or the reversal and the time the world's
-- may turn round off it.
-- What the world's sliding speed may sit off the model's at `at` (m/s), and the gap (m) the
-- start's drift leaves there.
local function speed_off(at)
  local gap, drift_speed = start_drift(at)
  local _, stepped_speed = stepping_gap(at)
  return math.max(drift_speed, stepped_speed) + landings_speed_shifted(at), gap
end
local near_for, near = nil, {}
local function stopped_where_the_model_slid_on_by(t)
  if near_for ~= horizon then near_for, near = horizon, {} end
  if near[t] ~= nil then return near[t] or nil end
  local last = math.min(sample(t), #turning.contact - 1)
  local function sliding(k) return turning.contact[k] == "slipping" end
  -- The model's samples may straddle a stop of its own shorter than their spacing (a level plank
  -- shaken at 17.8 m/s², μs 1.76, μk 0.29: 0.7 ms at each reversal, samples 4.2 ms apart): the
  -- world's stop there is the model's.
  local function stops_between(from, to)
    for _, event in ipairs(turning.events) do
      if event.kind == "stop" and event.t >= from and event.t <= to then return true end
    end
    return false
  end
  for k = 2, last do
    local v = turning.speed[k]
    local low = sliding(k - 1) and sliding(k) and sliding(k + 1) and math.abs(v) <= math.abs(turning.speed[k - 1])
                and math.abs(v) < math.abs(turning.speed[k + 1]) and v * turning.speed[k - 1] > 0
                and v * turning.speed[k + 1] > 0
    if low and not stops_between((k - 2) * spacing, k * spacing) then
      local at = (k - 1) * spacing
      local step_change = math.abs(turning.speed[k + 1] - turning.speed[k - 1]) / (2 * spacing) * substep_length()
      local off = speed_off(at) + step_change
      if math.abs(v) <= off then
        local first, final = k, k
        while first > 1 and sliding(first - 1) and math.abs(turning.speed[first - 1]) <= off do first = first - 1 end
        while final < #turning.contact and sliding(final + 1) and math.abs(turning.speed[final + 1]) <= off do
          final = final + 1
        end
        local from, to = (first - 1) * spacing - record_lag, (final - 1) * spacing + record_lag
        if time() < to then return nil end
        local _, _, held = world_between(from, to)
        if held then
          near[t] = "stopped where the model slid on: no model"
          return near[t]
        end
      end
    end
    -- A reversal the model slides through, its demand (the tangential force but friction) past
    -- μ·N there: the world's block turns round up to off_speed/|a| earlier or later, where its
    -- demand differs by the demand's rate times that, besides demand_uncertainty's terms (the gap
    -- at the start's drift); within that of the limit it may stick there instead.
    local v_next = turning.speed[k + 1]
    if k + 2 <= #turning.speed and sliding(k - 1) and sliding(k) and sliding(k + 1) and sliding(k + 2)
       and v * v_next < 0 and not stops_between((k - 1) * spacing, k * spacing) then
      local at = (k - 1 + v / (v - v_next)) * spacing  -- where the speed passes 0
      -- The demand on each side, from that side's acceleration and that side's friction, σ·μk·N.
      local function demand(j, a) return mass * a + direction_of(turning.speed[j]) * param.mu_k * turning.normal[j] end
      local a_before = (turning.speed[k] - turning.speed[k - 1]) / spacing
      local a_after = (turning.speed[k + 2] - turning.speed[k + 1]) / spacing
      local d_before, d_after = demand(k, a_before), demand(k + 1, a_after)
      local share = v / (v - v_next)
      local limit = math.max(param.mu_s, param.mu_k)
      local margin = math.abs(d_before + share * (d_after - d_before))
                     - limit * (turning.normal[k] + share * (turning.normal[k + 1] - turning.normal[k]))
      local off_speed, gap = speed_off(at)
      -- (The speed's mean change across the reversal's step: the larger side's would make the
      -- time too short a bound, the smaller's, near a stop of the drive, too long.)
      local turning_in = math.abs(v_next - v) / spacing
      local off_time = turning_in > 0 and off_speed / turning_in or math.huge
      local rate = math.abs(d_after - d_before) / spacing  -- N/s across the reversal
      local rate_before = k >= 3 and math.abs(d_before - demand(k - 1, (turning.speed[k - 1] - turning.speed[k - 2]) / spacing)) / spacing or 0
      rate = math.max(rate, rate_before)
      if margin <= demand_uncertainty(k, gap, limit) + rate * off_time then
        local from, to = at - off_time - record_lag, at + off_time + record_lag
        if time() < to then return nil end
        local _, _, held = world_between(from, to)
        if held then
          near[t] = "stopped where the model slid on: no model"
          return near[t]
        end
      end
    end
  end
  near[t] = false
end
-- Why the world and the model part for good by t (a stop one of them slid through), nil where
-- they do not.
local function parted_by(t) return slid_through_a_stop_by(t) or stopped_where_the_model_slid_on_by(t) end

-- Expectations ----------------------------------------------------------------------------
-- Against the model with the turn, which is the reduced equations plus exactly the terms a
-- rigid block on a turning plank feels; Box2D steps at 240 Hz with its own contact solver.
expect { "slide at the end", unit = "m",
  predicted = function()
    return no_model(duration) or slow_breakaway_by(duration) or parted_by(duration)
           or flew_where_the_model_did_not_by(duration) or turning.slide[sample(duration)]
  end,
  measured = function()
    return no_model(duration) or slow_breakaway_by(duration) or parted_by(duration)
           or flew_where_the_model_did_not_by(duration) or recorded("slide", duration)
  end,
  -- 0.2 % of the way it slid (back and forth) and 3 mm: each slip's start and stop is found
  -- within a step. And the start: the world's block starts with the plank's velocity over its
  -- first step, a_x·h/2 along the plank, where the models start it at rest (the plank's speed at
  -- t = 0). Sliding, both feel the same kinetic friction, so that difference carries on until
  -- the block first sticks (at once, if it starts stuck): a_x·h/2 times that long.
  -- And the turn's drift: Box2D moves the block a step along its velocity, a straight line,
  -- while the plank turns under it by θ'·h, so seen from the plank the block ends each step
  -- s·(θ'·h)²/2 further out from the pivot than it was, stuck or sliding: s·θ'²·h/2 a second,
  -- which no force in the step answers (the contact only pushes back along the normal). Shaken
  -- at a steady 4 m/s² on a plank swinging 33.7° at 5 rad/s the block stays near 0.3 m out, and
  -- the world's slide ends 0.014 m past the model's at 240 Hz, 0.0067 at 480, 0.0032 at 960.
  -- start_drift follows it (drift_step), at the world's sub-step, with the gap's other sources,
  -- rather than adding up its size apart: 0.020 m allowed there at 240 Hz, 0.012 at 480.
  -- Or, if larger, the stepping's own first-order error through the slide's reversals, stops
  -- and breakaways (stepping_gap): two estimates of the world's gap, each leaving out a part
  -- the other has.
  -- And each landing: the model's block lands in an instant, its sliding changed at once by the
  -- landing's friction impulse; the world's meets the surface inside a step and takes that
  -- impulse at its end, up to a step later, so its slide runs on off the model's by the change
  -- times the step (landings_shifted). The stepped equations are not followed into a flight;
  -- after one, stepping_gap carries on the gap they had reached at its start, and this adds
  -- each landing's part. (Shaken at 21 m/s² on a plank swinging
  -- 40° at 0.46 rad/s, μk 1.9, 9.8 kg, five flights: the world's slide ended 0.024 m short of
  -- the model's at 240 Hz, 0.009 m at 960, where 0.023 m was allowed without it.)
  -- (The 0.2 % of the path and the 3 mm are this row's flat allowances from before; not yet
  -- replaced by named terms.)
  tolerance = function()
    local path = 0
    local last = sample(duration)
    for k = 2, last do path = path + math.abs(turning.slide[k] - turning.slide[k - 1]) end
    return 0.002 * path + 3e-3 + landings_shifted(duration)
           + math.max(start_drift(duration) + (breakaways_shifted(duration)), (stepping_gap(duration)))
  end }
-- The drift (contact_lost_by) raises the block's centre off the surface by up to the slop, and
-- the turn then flings it by m·θ'²·(that) more than the model's block, whose centre stays e
-- above the surface: the world's N is less by that much (a block held at the pivot on a plank
-- swinging 25.3° at 10 rad/s, 10 kg: N 0.95 N under the model's at 2.56 s at 240 Hz, 0.47 at
-- 480, in step with θ'², and 0.17 N off with this term). The overlap's model follows the
-- world's raise only so far: the world's shortfall measured 0.6 to 1.25 times this term (0.1 kg
-- held at the pivot on a plank swinging 22.67° at 10 rad/s: the term 0.0046 N at 2.5 s, 0.0017 N
-- apart from the shortfall, halving with the step). It halves with the step, a stepped world's
-- error rather than physics: the row allows it (1.25 times, a measured share, not a derived
-- one) and the theory stays the model's.
local function raised_by(t)
  contact_lost_by(t)
  return raised[math.min(sample(t), #raised)] or 0
end
-- A landing at the reading: the model's block lands plastically, its impulse taken in an
-- instant, where the world's meets the surface in a step and is pushed out of it over the next,
-- so its N in those steps holds the landing's impulse over h (a 0.1 kg block on a plank
-- swinging 40° at 0.63 rad/s, shaken at 30 m/s²: the model lands 3 ms before the halfway
-- reading; the world's N reads 40 N there and 70 N the step after at 240 Hz, 80 and 137 N at
-- 480 Hz, against the model's 1.1 and 2.2 N). With the world's landing up to three steps either
-- side of the model's (the lift-off row's steps), a reading from five steps after a landing of
-- the model's to three before it may hold the impact, and the row says so.
-- And a reading inside a flight of the model's where the world's block may be down already. The
-- world's block rests up to the skins' overlap (linear_slop) into the surface, so it is down
-- again where its lowest point comes back within that of its resting place; and in flight it
-- keeps the spin it left with, so it lands on a corner (corner_drop). (Shaken at 14.89 m/s²
-- on a plank swinging 40° at 0.75 rad/s, 5.27 kg, μk 1.71: the model's block flew 5.6 mm high
-- from 2.24 s to past the halfway reading; the world's, turned 0.7° from the plank, was down on
-- its back corner from 2.47 s, its N 5.9 N at 2.5 s, at 240, 480 and 960 Hz alike.) Only while
-- that point comes nearer: a block leaving the surface starts within the overlap too.
local function down_in_the_models_flight(t)
  local k = sample(t)
  if turning.contact[k] ~= "flying" then return false end
  local first = k
  while first > 1 and turning.contact[first - 1] == "flying" do first = first - 1 end
  local left = (first - 1) * spacing
  local function clearance(j) return turning.height[j] - corner_drop(left, (j - 1) * spacing) end
  for j = first + 1, k do
    if clearance(j) <= linear_slop and clearance(j) < clearance(j - 1) then return true end
  end
  return false
end
local function landing_at_the_reading(t)
  for _, event in ipairs(turning.events) do
    if event.kind == "landing" and event.t > t - 5 * step_length() and event.t < t + 3 * step_length() then
      return "a landing's impact"
    end
  end
  if down_in_the_models_flight(t) then return "may be down already: no model" end
end
expect { "normal force halfway", unit = "N",
  predicted = function()
    return no_model(duration / 2) or parted_by(duration / 2) or flew_where_the_model_did_not_by(duration / 2)
           or landing_at_the_reading(duration / 2) or mid_step(true, "normal", duration / 2)
  end,
  measured = function()
    return no_model(duration / 2) or parted_by(duration / 2) or flew_where_the_model_did_not_by(duration / 2)
           or landing_at_the_reading(duration / 2) or recorded("normal_force", duration / 2)
  end,
  -- Read where the world reads it (the model's mid-step, as the reading is the step's mean), the
  -- rest is named here:
  -- - The instants inside the step: Box2D solves a step's contact along the normal the step
  --   began with, and the plank's change of velocity is over the step's start, so the article's
  --   part m·(g·cos θ − a·sin θ) is the model's half a (sub)step before the middle; the turn's
  --   share (late_share) comes from the velocity carried through the step before, a whole step
  --   late. Bounded by a whole step's change of each: half a step for the article's part fell
  --   short on the random sweep (errors up to 1.25 times that bound, all halving with the step),
  --   where more than the step's first normal moves it (the plank's velocity, changed once a
  --   step, and the block's own carried velocity); a whole step covers them.
  -- - Where the world's block runs apart from the model's (start_drift and the stepped
  --   equations' (stepping_gap) together: δs off, δs' faster),
  --   the turn presses it differently there, by m·(θ''·δs + 2θ'·δs') (frictionless, shaken at
  --   17 m/s² on a plank swinging 5.6° at 10 rad/s: 0.13 m apart by 2.5 s, N 3.9 N off).
  --   The two are the gap's two sources, the start's speed and the stepping's error, and both
  --   are there at once: sliding freely from the start (μk 0) on a plank swinging 6.1° at 8 rad/s,
  --   shaken at −15.9 m/s², the world's block was 0.318 m off by 2.5 s at 240 Hz (0.180, 0.100,
  --   0.052 at 480, 960, 1920), where start_drift says 0.149 and the stepped equations 0.185;
  --   the larger alone allowed N 16.0 N off where the world's was 16.2.
  --   start_drift follows the gap itself well there (0.0498 m against the world's 0.0502 at
  --   2.5 s, frictionless, shaken at −8.2 m/s² on a plank swinging 3.2° at 10 rad/s), but the
  --   world's N sits 1.4 to 2.3 times this press off the model's over the run, at the swing's
  --   rate, which is not explained yet (the 1 % of the weight below covers it there).
  -- - Single precision: the normal impulse keeps that step's roundings of the block's velocity,
  --   (1 + 9·k)·2^-24 of it over h, k = 4 constraints (two points, normal and friction), times m.
  -- - The raise (raised_by above): the world's N falls short of the model's by 0.6 to 1.25
  --   times m·θ'²·(raise), halving with the step: a stepped world's error, so allowed here, not
  --   taken off the theory, at the largest share measured (1.25: measured, not derived).
  -- - And 1 % of the weight, the flat allowance this row had, kept for what none of the above
  --   bounds: on the article's own example the world's N at 2.5 s is 0.017, 0.0065 and 0.0061 N
  --   over the model's at 240, 480 and 960 Hz, then 0.011 N under it at 2000 Hz and 0.049 N under
  --   at 3840 Hz, growing as the step shrinks (the listener's hold band moving where the block
  --   breaks away, as breakaways_shifted tells, is the likely cause; not followed yet). Without
  --   it the named terms alone passed 2079 of the 2080 random settings of seeds 1 to 25 and 8001
  --   at 240 Hz (the one left, a light block held at the pivot, is the raise's half above), but
  --   not the article's example at 2000 Hz.
  -- The solver is no term: the two points' normal impulses are solved together, exactly, each
  -- iteration (Box2D's block solver), and the errors measured halve with the step.
  tolerance = function()
    local t = duration / 2
    local k = math.max(sample(t), 2)
    -- (The world's block's gap off the model's: start_drift's and the stepped equations'.)
    local drift_gap, drift_speed = start_drift(t)
    local stepped_gap, stepped_speed = stepping_gap(t)
    local gap, gap_speed = drift_gap + stepped_gap, drift_speed + stepped_speed
    local turn_rate = theta0 * omega * math.abs(math.cos(omega * t))
    local steps = h / spacing
    local article_change = math.abs((turning.normal[k] - turn_share(k)) - (turning.normal[k - 1] - turn_share(k - 1)))
                           * steps
    local rounding = impulse_rounding(k)
    local raise = mass * turn_rate * turn_rate * raised_by(t)
    return article_change + late_share(k) + turn_press(t, gap, gap_speed) + rounding
           + 1.25 * raise + 0.01 * mass * g
  end }
-- How far from the model's breakaway at t the world's may come (the first slip row says why):
-- three and a half steps, and the time the gap between the demand and the limit takes to close
-- by μ times the late share of N and the impulses' rounding of the demand and the limit, at the
-- rate it closed in the model's last steps before. (The rounding: a level plank shaken at a
-- steady 14.19 m/s², 25.8 m/s by the breakaway at 1.82 s, the gap closing at 1.69 N/s: the
-- world broke away 3.1 ms before the model at 1920 Hz, 1.8 ms allowed without it.)
local function breakaway_lag(t)
  if t == 0 then return record_lag end
  local k = sample(t)
  if k < 3 then return record_lag + h end
  local limit = math.max(param.mu_s, param.mu_k)
  local function gap(i) return limit * turning.normal[i] - math.abs(turning.friction[i]) end
  local closing = math.abs(gap(k - 2) - gap(k - 1)) / spacing
  local off = limit * late_share(k) + (1 + limit) * impulse_rounding(k)
  return record_lag + (closing > 0 and off / closing or 0)
end
-- An event the model has within its row's lag of the run's end may come after the end in the
-- world's record, where it is "never" (1.414 kg, μk 1.81, μs 0.99, a plank swinging 40° at
-- 0.135 rad/s, shaken at 8 m/s²: the model's first slip at 4.997 s, 3 ms before the end, and
-- the world's block, held a step or more as a breakaway is, had not slipped by 5 s).
-- Only where the world's block has not slipped by then: where it has, the row compares.
local function too_near_the_end(t, lag)
  if t and t <= duration and duration - t < lag and not first_recorded("slipping", function(v) return v == 1 end) then
    return "too near the run's end to be seen: no model"
  end
end
expect { "first slip", unit = "s",
  predicted = function()
    local t = (turning.contact[1] == "slipping" and 0) or first_event(turning, "breakaway")
    return no_model(t or duration) or too_near_the_end(t, breakaway_lag(t or 0)) or t or "never"
  end,
  measured = function()
    local t = (turning.contact[1] == "slipping" and 0) or first_event(turning, "breakaway")
    if no_model(t or duration) then return no_model(t or duration) end
    local too_near = too_near_the_end(t, breakaway_lag(t or 0))
    if too_near then return too_near end
    local seen = first_recorded("slipping", function(v) return v == 1 end)
    if seen and not t then return "slips" end  -- where the model says it never does
    if seen or time() >= duration then return seen or "never" end
  end,
  -- Three and a half steps: the record says "slipping" at the end of a step; the listener
  -- judges a slip from the impulses of the step it began in (a block that must slip from the
  -- start is held through the first step, judged, and shown slipping at the end of the second);
  -- and a contact just past μs·N may be held a step more while the listener tells the
  -- solver's leftover from a real excess (measured: up to 2.9 steps late, at ω = 0.1 rad/s).
  -- The breakaway correction gives the slide back what the late steps held. And the turn's
  -- share of N arriving a step late (late_share) moves the limit μ·N by μ times it: the time
  -- the gap between the demand and the limit takes to close by that much, at the rate it
  -- closed in the model's last steps before the breakaway.
  tolerance = function()
    local t = (turning.contact[1] == "slipping" and 0) or first_event(turning, "breakaway")
    return breakaway_lag(t or 0)
  end }
-- The model lifts the block off when its N reaches 0, turning with the surface to the last. But
-- the surface's angular acceleration θ'' needs I·θ'' of the contact's moment, and N·w/2 goes to
-- 0 with N, so before that the block always rocks onto an edge. That edge leaves the surface
-- when its own free acceleration off the surface turns positive: with no contact force left
-- there is no friction or moment either, so it is the centre's, −N/m, less (w/2)·|θ''| the
-- surface turns towards the edge (N: the model's, carried on past 0, which its flight gives:
-- the height's second difference is −N/m). While the block pivots on that edge, still all but
-- flat on the surface, the edge's push F keeps the edge down:
--   F·(1 + m·(w/2)·(w/2 ± e·μ)/I) = N + m·(w/2)·|θ''|
-- (±e·μ: friction's moment at the edge, if it slides), so F falls as N does, slowed by |θ''|
-- growing, and the edge lets go where N = −m·(w/2)·|θ''| at the θ'' of that moment, whatever the
-- friction. Taken with N falling on at its rate before the lift-off and θ'' held at the
-- lift-off's, that came 21 ms early at θ0 = 38.42°, ω = 10 rad/s, 0.1 kg, frictionless (0.0334 s
-- against the world's 0.0542 at 240 Hz): from the model's lift-off to the edge's (0.0243 to
-- 0.0412 s) |θ''| = θ0·ω²·|sin ω·t| grew by two thirds, and F fell at
-- 4.1 N/s, the world's edge's push at 4.4, where N fell at 26.5. Now the first crossing of
-- N + m·(w/2)·|θ''| through 0 over the model's flight, between two samples, is the lift-off:
-- 0.0412 s there, and the world's 0.0542, 0.0479, 0.0438, 0.0427 s at 240, 480, 960, 1920 Hz,
-- three steps' reading (below) and the late share apart. How fast that sum falls there turns
-- the row's N uncertainty into time. Where it never crosses in that flight, the lift-off only
-- grazes (only_grazes).
-- The model's N at sample j: in contact its normal force, in flight −m times the height's second
-- difference (j and j + 1 flying).
local function carried_normal(j)
  if turning.contact[j] ~= "flying" then return turning.normal[j] end
  return -mass * (turning.height[j + 1] - 2 * turning.height[j] + turning.height[j - 1]) / (spacing * spacing)
end
local function edge_push(j)  -- m·(w/2)·|θ''| at sample j
  return mass * 0.5 * block_width * theta0 * omega * omega * math.abs(sin(omega * (j - 1) * spacing))
end
-- When the edge lets go in the flight whose first sample is `flight`, and how fast
-- N + m·(w/2)·|θ''| falls there (N/s); nil where it does not cross before the landing.
-- The pivot's own friction moves that moment. On its edge the block slides with μk times the
-- edge's push F, not the model's μk·N, and in the model's flight it still slides (the model's
-- has no friction there): the world's block runs δs' faster or slower than the model's, and the
-- turn presses it by −m·(θ''·δs + 2θ'·δs') more (turn_press's terms, signed), which the edge
-- must take too. F is the one above: the edge is the side the contact's moment must turn the
-- block to, I·θ'' + e·f, and sliding friction's moment at it, e·μk·F, adds to or takes from the
-- edge's lever w/2 (L = w/2 + σ·d·e·μk, σ the edge's side, d the way the block slides). Summed
-- from the sample at which the model's block would first rock (issue 29: 8.14 kg, μk 1.9, θ0
-- 40°, ω 8.18 rad/s, shaken at 17.3 m/s²: the block rocks from 0.0125 s with L = 0.0074 m,
-- slides on its edge 0.0125 to 0.05 s, and the press is 6.6 N when the edge lets go, 0.0515 s
-- against 0.0466 without it; the world's block was seen lifted 3 steps after 0.0521 s at 960
-- and at 1920 Hz). Frictionless, nothing changes.
local function pivot_presses(flight)
  local start = flight - 1
  while start > 1 and turning.contact[start - 1] ~= "flying"
        and must_rock((start - 2) * spacing, turning.friction[start - 1], turning.normal[start - 1]) do
    start = start - 1
  end
  local gap, gap_speed, presses = 0, 0, {}
  for j = start, #turning.contact do
    local t = (j - 1) * spacing
    local spin_up = -theta0 * omega * omega * sin(omega * t)
    local turn_rate = theta0 * omega * math.cos(omega * t)
    presses[j] = -mass * (spin_up * gap + 2 * turn_rate * gap_speed)
    if j >= flight and not (j < #turning.contact and turning.contact[j] == "flying" and turning.contact[j + 1] == "flying") then
      break
    end
    local friction = turning.contact[j] ~= "flying" and turning.friction[j] or 0
    -- A model's block held by static friction has no way it slides: the way it would, against
    -- its friction. Where the edge's push holds it with that same friction (up to mu_s·F) the
    -- world's block is held too and no gap opens; past that it slides, kinetic friction against
    -- that way (it used to take the way as forward, and a held block opened a gap of its own).
    local held = turning.contact[j] == "sticking"
    local way = held and -direction_of(friction) or direction_of(turning.speed[j])
    local lever = 0.5 * block_width
                  + direction_of(inertia * spin_up + centre_height * friction) * way * centre_height * param.mu_k
    local push = math.max(0, (carried_normal(j) + presses[j] + edge_push(j)) / (1 + mass * 0.5 * block_width * lever / inertia))
    local world_friction = -way * param.mu_k * push
    if held and math.abs(friction) <= param.mu_s * push then world_friction = friction end
    gap_speed = gap_speed + (world_friction - friction) / mass * spacing
    gap = gap + gap_speed * spacing
  end
  return presses
end
local function edge_lets_go(flight)
  local presses = pivot_presses(flight)
  local function held(j) return carried_normal(j) + edge_push(j) + (presses[j] or 0) end
  local j = flight
  while j < #turning.contact and turning.contact[j] == "flying" and turning.contact[j + 1] == "flying" do
    local before, now = held(j - 1), held(j)
    if now <= 0 and before > now then
      local rate = (before - now) / spacing
      return (j - 2) * spacing + before / rate, rate
    end
    j = j + 1
  end
end
-- How far the world's N at the lift-off may sit off the model's (see the row's tolerance below):
-- 2 % of the weight; what the world's block being δs further along (start_drift) changes, the
-- turn's press m·|θ''|·δs and the Coriolis push 2·m·|θ'|·δs' of its extra speed; and the turn's
-- share of N arriving a step late. (Without the press: shaken at 30 m/s² on a plank swinging
-- 8.3° at 4 rad/s, 5.74 kg, the world's block was up to 0.42 m from the model's at 4.42 s, where
-- |θ''| is 2.2 rad/s²: 5.2 N of press, against the 1.75 N allowed. The model's block lifted off
-- there; the world's N came down to 0.06 N and went back up.)
local function lift_off_uncertainty(t, k)
  local gap, gap_speed = start_drift(t)
  return 0.02 * mass * g + turn_press(t, gap, gap_speed) + late_share(k)
end
-- The most |sin x| for x from a to b.
local function most_abs_sin(a, b)
  if floor((b - 0.5 * math.pi) / math.pi) >= math.ceil((a - 0.5 * math.pi) / math.pi) then return 1 end
  return math.max(math.abs(sin(a)), math.abs(sin(b)))
end
-- The pivot before a lift-off whose flight starts at sample `flight`: when its edge lets go and
-- how fast the sum falls there (above), how far it may tilt the block, and a bound on what the
-- rule above, which takes the block flat on the surface, leaves out. Tilted by φ about its edge
-- (turning at φ'), the block's centre stands (w/2)·φ higher and e·φ along, where the turn
-- flings it by m·θ'²·(w/2)·φ and presses it by m·|θ''|·e·φ otherwise; the edge's lever, w/2, is
-- e·φ shorter, m·|θ''|·e·φ again; the edge swings round the centre, m·e·φ'²; and the centre
-- moves across the turning surface at e·φ', whose Coriolis push is 2·m·|θ'|·e·φ'.
-- φ'' = |θ''| − L·F/I on the edge (L·F: the moment of F and of friction, L = w/2 ± e·f/F), so
-- with F above, φ'' = (|θ''| − L·N/I)/(1 + m·(w/2)·L/I): 0 where the block starts to rock, |θ''|
-- as the edge lets go. Friction, |f| <= μ·F, puts L between w/2 − e·μ and w/2 + e·μ, and φ'' is
-- largest at one of those ends; taken there, with the world's block pressed by up to the row's N
-- uncertainty less than the model's, from the last sample at which that block would not rock to
-- that much after the edge lets go, and summed over the samples, φ and φ' are bounds.
-- Kept for each flight and solution of the model.
local pivots, pivots_for = {}, nil
function pivot_of(flight)
  if pivots_for ~= horizon then pivots, pivots_for = {}, horizon end
  if pivots[flight] ~= nil then return pivots[flight] or nil end
  local at, rate = edge_lets_go(flight)
  if not at then
    pivots[flight] = false
    return nil
  end
  local off = lift_off_uncertainty(math.max(0, (flight - 2) * spacing), math.max(flight - 1, 1))
  local ends = at + off / rate
  local mu = math.max(param.mu_s, param.mu_k)
  local function tilting(j)  -- the most φ'' at sample j (1/s²)
    local spin_up = theta0 * omega * omega * math.abs(sin(omega * (j - 1) * spacing))
    if turning.contact[j] == "flying" and not (j < #turning.contact and turning.contact[j + 1] == "flying") then
      return spin_up  -- past the model's flight: the most it can be
    end
    local normal = carried_normal(j) - off
    local most = 0
    for _, lever in ipairs { 0.5 * block_width - centre_height * mu, 0.5 * block_width + centre_height * mu } do
      most = math.max(most, (spin_up - lever * normal / inertia) / (1 + mass * 0.5 * block_width * lever / inertia))
    end
    return math.min(most, spin_up)
  end
  -- The last sample before the flight at which the world's block would not yet rock.
  local first = flight - 1
  while first >= 1 and turning.contact[first] ~= "flying"
        and must_rock((first - 1) * spacing, turning.friction[first], turning.normal[first] - off) do
    first = first - 1
  end
  first = math.max(first, 1)
  -- From sample `from` to the pivot's end: the tilt, and what it leaves out (N).
  local function bound(from)
    local tilt, tilt_rate = 0, 0
    local last = math.min(math.ceil(ends / spacing) + 1, #turning.contact)
    for j = from, last - 1 do
      local spin = 0.5 * (tilting(j) + tilting(j + 1)) * spacing
      tilt = tilt + (tilt_rate + 0.5 * spin) * spacing
      tilt_rate = tilt_rate + spin
    end
    local begins = (from - 1) * spacing
    local spin_up = theta0 * omega * omega * most_abs_sin(omega * begins, omega * ends)
    local turn_rate = theta0 * omega * most_abs_sin(omega * begins + 0.5 * math.pi, omega * ends + 0.5 * math.pi)
    local left_out = mass * (turn_rate * turn_rate * 0.5 * block_width * tilt + 2 * spin_up * centre_height * tilt
                             + centre_height * tilt_rate * tilt_rate + 2 * turn_rate * centre_height * tilt_rate)
    return tilt, left_out
  end
  local tilt, left_out = bound(first)
  pivots[flight] = { at = at, rate = rate, tilt = tilt, left_out = left_out,
                     tilt_from = function(k) return (bound(math.max(math.min(k, first), 1))) end }
  return pivots[flight]
end
-- The model's first lift-off: its time and sample, how fast the sum falls where the edge lets
-- go, when it does, and what the pivot's tilt may move the push by (N).
local function lift_off()
  local t = first_event(turning, "lift-off")
  if not t then return nil end
  local k = sample(t)
  local pivot = pivot_of(floor(t / spacing) + 2)  -- the first sample after the lift-off
  if pivot then return t, k, pivot.rate, math.max(t, pivot.at), pivot.left_out end
  -- None in the flight: a lift-off that only grazes (only_grazes says so) or one past the
  -- model's lists, placed by N's rate before the lift-off and the θ'' there.
  local rate = math.abs(turning.normal[math.max(k - 1, 1)] - turning.normal[math.max(k - 2, 1)]) / spacing
  local spin_up = theta0 * omega * omega * math.abs(sin(omega * t))
  local on_the_edge = rate > 0 and mass * 0.5 * block_width * spin_up / rate or 0
  return t, k, rate, t + on_the_edge, 0
end
-- A lift-off that only grazes: over the model's first flight the surface never falls away from
-- the block faster than by that uncertainty (over m) and the edge's (w/2)·|θ''|: the model's
-- block rises by a hair and lands, and the world's, pressed that much harder or kept down by
-- its edge, may never leave (μk 0, θ0 34°: the model's block flew 0.9 mm high from 0.087 s,
-- pulled away at most 0.057 N's worth beyond what the edge takes, against 0.42 N allowed; the
-- world's N bottomed out at 0.04 N and came back, and the block first left at 1.03 s). How fast
-- the surface falls away is the flight's height's second difference.
local function only_grazes(t, k)
  local allowed = lift_off_uncertainty(t, k)
  local j = k
  while j <= #turning.contact and turning.contact[j] ~= "flying" do j = j + 1 end
  if j < 2 then return false end
  -- (Up to the last sample before the landing, whose stop is no pull away.)
  while j < #turning.contact and turning.contact[j] == "flying" and turning.contact[j + 1] == "flying" do
    local away = (turning.height[j + 1] - 2 * turning.height[j] + turning.height[j - 1]) / (spacing * spacing)
    local edge = 0.5 * block_width * theta0 * omega * omega * math.abs(sin(omega * (j - 1) * spacing))
    if mass * (away - edge) > allowed then return false end
    j = j + 1
  end
  return true
end
-- A world's block that tumbled on its way to the lift-off: the pivot the row follows tilts the
-- block less than the tilt that counts as tumbling before its edge lets go, but sliding with
-- kinetic friction near μ = w/h, friction's moment about the edge all but cancels what holds
-- the block flat on it, and the world's block tipped over instead (0.1 kg, μk 1.865, a plank
-- swinging 40° at 6.8 rad/s: the model's edge let go at 1.026 s; the world's block was 3° off
-- the plank by 1.054 s and 34° when its N first read 0, at 1.163 s, at every step from 240 to
-- 1920 Hz). Read from the world's record, as a tumble is (tumbled), three steps before its N
-- first read 0, where the reading says it left.
local function tumbled_on_the_way_up()
  local seen = first_recorded("normal_force", function(v) return v == 0 end)
  if seen and tumbled(seen - 3 * step_length()) then return "tumbled: no model" end
end
-- A lift-off that only grazes before t, where the world's block flew: the model's block rises
-- by a hair and lands; the world's N read 0 within the lift-off row's reading (three steps) of
-- that flight, so it flew for a step or more and landed with an impact the model's did not
-- have, and where its block then slides nothing after it has a model. (Shaken at −30 m/s² on a
-- plank swinging 10.6° at 3 rad/s, μk 0.0038, 10 kg: the model's block grazed a lift-off at
-- 3.60 s; the world's flew from 3.6 to 3.7 s and ended 1.3 m further along, 0.62 m allowed.)
-- Where the world's stayed down too, the rows after it are checked.
-- And where the model's block never leaves, the world's may fly from where the model's N is within
-- what the world's may sit off it: the lift-off's own uncertainty, with the turn's press on the
-- gap the world's block has from the model's there, up to what the stepping opens (stepping_gap,
-- which the normal force's row adds to the start's drift too, and which a long slide to and fro
-- on a fast swing grows to metres). Shaken at
-- 30 m/s² on a plank swinging 2.36° at 10 rad/s, μk 0.44, 7.46 kg: at 240 Hz the world's block
-- was 0.28 m off the model's by 3.5 s (0.08 m at 480 Hz) and 1.8 m by 4.575 s, where it flew off
-- the plank, 2.4 m up it, with the model's N at 47.8 N and the stepped equations 1.78 m off
-- (57.5 N of press); at 480 and 960 Hz it stayed down with the model's, and the rows agree.
local function flew_where_the_model_stayed_down_by(t)
  local seen = first_recorded("normal_force", function(v) return v == 0 end)
  if not seen or seen > t then return nil end
  if lift_off() then return nil end  -- a model's lift-off: the lift-off row judges the world's against it
  local k = sample(seen)
  -- The turn presses on the gap the world's block has from the model's, which its record gives;
  -- no more than the stepping's bound of it (a world further off than that is not excused).
  local bound, bound_speed = stepping_gap(seen)
  local h = step_length()
  local world_gap = math.abs(value_at("slide", seen) - turning.slide[k])
  local world_gap_speed = math.abs((value_at("slide", seen) - value_at("slide", math.max(seen - h, 0))) / h - turning.speed[k])
  local off = lift_off_uncertainty(seen, k) + turn_press(seen, math.min(world_gap, bound), math.min(world_gap_speed, bound_speed))
  if turning.contact[k] ~= "flying" and turning.normal[k] <= off then
    return "flew where the model stayed down: no model"
  end
end
function flew_where_the_model_did_not_by(t)
  local lifted, k = lift_off()
  if not lifted or lifted > t or not only_grazes(lifted, k) then return flew_where_the_model_stayed_down_by(t) end
  local landed = duration
  for _, event in ipairs(turning.events) do
    if event.kind == "landing" and event.t > lifted then
      landed = event.t
      break
    end
  end
  local lag = 3 * step_length()
  local times, normals = history("time"), history("normal_force")
  for i = 1, #times do
    if times[i] > landed + lag then break end
    if times[i] >= lifted - lag and normals[i] == 0 then return "flew where the model grazed: no model" end
  end
end
-- Why the row has no model, the same words on both sides, in one order; nil where it has one.
-- A stop of the model's that the world's block slid through parts the two for good, as for the
-- other rows (shaken at 30 m/s² on a plank swinging 9.6° at 3 rad/s, μs 1.93, μk 0: at 240 Hz
-- the world's block was 0.34 m behind the model's by 0.5 s and its N never fell under 7 N,
-- where the model's block lifted off at 1.517 s; at 480 Hz it held at the stop and lifted off
-- at 1.521 s).
local function no_lift_off_model(t, k)
  return no_model(t or duration) or parted_by(t or duration) or tumbled_on_the_way_up()
         or (t and only_grazes(t, k) and "grazes: no model") or flew_where_the_model_stayed_down_by(duration) or nil
end
expect { "first lift-off", unit = "s",
  predicted = function()
    local t, k, _, edge_leaves = lift_off()
    return no_lift_off_model(t, k) or edge_leaves or "never"
  end,
  measured = function()
    local t, k = lift_off()
    local why_none = no_lift_off_model(t, k)
    if why_none then return why_none end
    local seen = first_recorded("normal_force", function(v) return v == 0 end)
    if seen and not t then return "lifts off" end  -- where the model says it never does
    if seen or time() >= duration then return seen or "never" end
  end,
  -- Three steps: the normal force reads 0 only after a whole step without a push, and as N
  -- crosses 0 it passes through the last 1 % of the weight over a step or more. And the time
  -- the model's N takes to change by 2 % of the weight there: sliding fast far out on a fast
  -- turn, Box2D's normal force sits up to 2 % of the weight off the model's (θ0 = 40°, 5.4 m/s,
  -- 4 m from the pivot: 0.26 N at 480 Hz and at 960 Hz alike), which is not explained yet.
  -- And while the world's start still carries the block faster along the plank than the
  -- models' (start_drift's gap speed, a_x·h/2 at first), the Coriolis push 2·m·θ'·(that speed)
  -- it brings, in the time N takes to change by that much (a_x = 24 m/s², θ0 = 40°: 1.6 N,
  -- 2.5 ms). And the turn's share of N arriving a step late (late_share).
  -- And a lift-off the model has within the first frame: the world's block starts with the
  -- plank's mean velocities over its first step (see the block), so that step asks nothing of
  -- the contact and its N is the weight (the plank is level at t = 0), whatever the model's
  -- does; the world's N starts to follow the model's from the next step, and its three steps count
  -- from there, a frame later at the most (10 kg at the pivot of a plank swinging 40° at
  -- 10 rad/s, shaken at 21.79 m/s²: the model lifts off at 0.0137 s, inside the first frame at
  -- 60 Hz; the world's N reads 98.1 N, the weight, at its end, then 36.5, 0.59 and 0 N, seen
  -- lifted 3 frames after the first, 0.053 s after the model and 0.051 after its edge lets go,
  -- where 3 frames allowed 0.050).
  -- And what the pivot's tilt may move the edge's push by (pivot_of), in the same time.
  -- Not allowed for, and not explained yet: from 1920 Hz on, a block sliding far out on the
  -- plank may have its N alternate from one step to the next by about its own size as it nears
  -- the lift-off, and read 0 for single steps before it (a_x 13.05, a_x_omega 0.2318, 0.7594 kg,
  -- μk 0.6676, μs 0, ω 0.5601, θ0 31.69°: 0, 0.39 and 0.76 N from 1.0 s at 1920 Hz, the model's
  -- 0.32 N; first read 0 at 1.033, 1.001, 0.859 s at 960, 1920, 3840 Hz, the edge letting go at
  -- 1.055 s), where the row fails.
  tolerance = function()
    local t, k, rate, _, left_out = lift_off()
    if not t then return 3 * step_length() end
    local first_frame = t < step_length() and step_length() or 0
    return 3 * step_length() + first_frame + (rate > 0 and (lift_off_uncertainty(t, k) + left_out) / rate or 0)
  end }
-- The books over the first swing (or the run, if the swing is longer): the change of kinetic
-- energy in the turning frame, which the model books as gravity's, the pseudo-force's, the
-- turn's and friction's work and what landings took.
local function first_swing() return omega > 0 and math.min(duration, 2 * math.pi / omega) or duration end
predict { "first slip", unit = "s",
  question = "The wedge starts to swing and to be shaken: how long does static friction hold the block?" }
predict { "slide at the end", unit = "m",
  question = "After 5 s, how far down the slope is the block from where it started (up: negative)?" }

-- The block's speed in the surface's frame over the step that ends at t, from the slide and the
-- lift recorded at either end of it, both always: in a flight the lift's rate is the block's
-- rise, in contact the drift off the surface that the world's block does make (contact_lost_by).
-- The models' kinetic energy is ½·m·(slide rate² + height rate²); at a_x 30 m/s², θ0 40°,
-- ω 0.1977 rad/s the block was in its fourth flight at 5 s, and the slide's speed alone read
-- 194.6 J of the 205.4 J the model's block had.
local function speed_before(t)
  local back, now_at = value_at("slide", t - h), value_at("slide", t)
  local lift_back, lift_now = value_at("lift", t - h), value_at("lift", t)
  if not (back and now_at and lift_back and lift_now) then return nil end
  return math.sqrt(((now_at - back) / h) ^ 2 + ((lift_now - lift_back) / h) ^ 2)
end
-- What the world's start (start_speed(), about a step's worth of the drive off the models'
-- block at rest) does to the kinetic energy by time t, worked out by the model with the turn
-- started that fast: its speed until the first stop, and after it the place it stopped at,
-- where the turn flings and presses the block otherwise. That second part start_drift leaves
-- out: at a_x −26.69 m/s², θ0 24.13°, ω 9.184 rad/s the world stopped 3.8 mm short of the
-- model's block, and over the rest of the first swing, pressed less as N fell to 4 N, it ended
-- 0.059 J above the model's ΔK (0.029 at 480 Hz, 0.015 at 960: first order in the step, as the
-- start is). Started either way, since start_speed knows the start's size and not its way:
-- the two models end 0.092 J above and 0.151 J below there, and a frictionless block shaken on
-- a plank swinging 2.5° (a_x 28.42, ω 10) ended above the model's ΔK where the one started
-- against the drive ends below it. Solved only where the models' block slips from the start.
local started, started_for = nil, nil
local function start_energy(t)
  if turning.contact[1] == "sticking" then return 0 end
  local k = sample(t)
  if started_for ~= k then
    started_for, started = k, 0
    for _, way in ipairs { 1, -1 } do
      local kinetic = theory.wedge { mass = mass, theta0 = param.theta0, omega = omega, a_x = a_x, a_x_omega = a_x_omega,
        mu_s = param.mu_s, mu_k = param.mu_k, duration = (k - 1) * spacing, step = spacing, rotation = true,
        centre_height = centre_height, start = 0, start_speed = way * start_speed() }.kinetic[k]
      started = math.max(started, math.abs(kinetic - turning.kinetic[k]))
    end
  end
  return started
end
-- Where the model's block broke away less than the world's lag before t (breakaway_lag), the
-- world's may still be held there, and where it stopped or turned round less than a step
-- before, the world's may still slide or be stopped for the step (a stop or a turn is found
-- inside a step): the kinetic energy the model's block gained or lost since, which the world's
-- then has not. (A level plank shaken at 22 m/s², μs 0, μk 0.52: the model's block turned
-- round 3.1 ms before the reading at 5 s and had 0.0118 J by then; the world's read 0 over
-- its last step, 0.0098 J allowed without the turn.) (Read 2.5 steps after the model's breakaway
-- at 120 Hz, a level plank shaken at 20.44 m/s²: the model's 0.235 J, the world's block still
-- held, where the row allowed 0.16.)
local function held_or_sliding_on(t)
  local k, most = sample(t), 0
  for _, event in ipairs(turning.events) do
    local lag = (event.kind == "breakaway" and event.t > 0 and breakaway_lag(event.t))
                or ((event.kind == "stop" or event.kind == "reversal") and step_length()) or nil
    -- (At a stop, a turn or a breakaway the block's slide is still: all the model's kinetic
    -- energy at the reading came since. Read from the sample nearest the event instead, a turn
    -- in the second half of the last step gave nothing, and one in its first half what the
    -- step's own change already allows.)
    if lag and event.t <= t and event.t > t - lag then most = math.max(most, turning.kinetic[k]) end
  end
  return most
end
expect { "ΔK over the first swing", unit = "J",
  predicted = function()
    local k = sample(first_swing())
    return no_model(first_swing()) or parted_by(first_swing()) or flew_where_the_model_did_not_by(first_swing())
      or turning.work_gravity[k] + turning.work_pseudo[k] + turning.work_friction[k] + turning.work_rotation[k]
      + turning.work_landings[k]
  end,
  measured = function()
    if no_model(first_swing()) then return no_model(first_swing()) end
    local why_none = parted_by(first_swing()) or flew_where_the_model_did_not_by(first_swing())
    if why_none then return why_none end
    local speed = time() >= first_swing() - 0.5 * h and speed_before(first_swing())
    return speed and 0.5 * mass * speed * speed or nil
  end,
  -- 2 % and 1 mJ, and how much the kinetic energy changes in the step the speed is read over;
  -- what the world's start does to it (start_energy); a breakaway or stop of the model's just
  -- before the reading (held_or_sliding_on); and the stepping's own first-order error in the
  -- speed (stepping_gap's δv, which the slide row takes for the gap's speed): ½m·(v ± δv)² is
  -- off ½m·v² by m·|v|·δv + ½m·δv². (0.34 kg on a plank swinging 25.9° at 4.2 rad/s, shaken
  -- at 4.2 m/s²: the world's ΔK 0.0062 J under the model's at 240 Hz, 0.0031 at 480, 0.0015
  -- at 960, where 0.0047 J was allowed without it; δv 0.022 m/s on 0.58 m/s there.) The
  -- stepped equations stop at a flight, whose start's δv carries on (stepping_gap); after a
  -- landing, its share too (landings_speed_shifted).
  tolerance = function()
    local k = sample(first_swing())
    local _, stepped_speed_off = stepping_gap(first_swing())
    stepped_speed_off = stepped_speed_off + landings_speed_shifted(first_swing())
    local speed = math.abs(turning.speed[k])
    return 0.02 * turning.kinetic[k] + math.abs(turning.kinetic[k] - turning.kinetic[k - 1]) + 1e-3
           + start_energy(first_swing()) + held_or_sliding_on(first_swing())
           + mass * (speed + 0.5 * stepped_speed_off) * stepped_speed_off
  end }
