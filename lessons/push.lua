-- push: a block on a table pushed harder and harder, as the tribology article pushes its book
-- (and as a force-sensor lab does). Static friction answers the push exactly, f = −F, until the
-- push reaches mu_s·N; then the block breaks away, friction drops to mu_k·N, and the push,
-- still growing, speeds the block up: a = (F − mu_k·N)/m.

-- What theory says at time t, with the sliders as they are now.
local function push_theory(t)
  return theory.growing_push { mass = param.mass, rate = param.push_rate, mu_s = param.mu_s, mu_k = param.mu_k,
                               c = param.c, b = param.b, t = t }
end

-- How long the run lasts: past theory's breakaway, as long again as it took to get there, but
-- half a second of sliding at least and a second and a half at most. A second and a half at
-- every rate pushed to 80 N at 50 N/s, and the key plot's push axis ran to 100 N with the
-- breakaway at 3.92 N, squeezed against its left edge (issue 31).
local function run_length()
  local breakaway_time = push_theory(0).breakaway_time
  return breakaway_time + math.min(1.5, math.max(0.5, breakaway_time))
end

lesson {
  title = "Push a block harder and harder",
  question = "How hard must you push before the block moves, and what does friction do once it moves?",
  duration = run_length,
  order = 12,
  moments = {
    { "static_friction_answers", at = 1,
      shows = function() return value_at("slipping", time()) == 0 and value_at("push", time()) > 1 end },
    { "sliding", at = 3, readme = true, shows = function() return value_at("slipping", time()) == 1 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg", text = "mass of the block" }
local push_rate = parameter { "push_rate", 2, min = 0.2, max = 50, unit = "N/s", text = "how fast the push grows" }

-- A wooden block on a wooden table: the tribology article's wood on wood, 0.25 to 0.50.
pair { "wood", "wood", mu_s = 0.4, mu_k = 0.3 }

-- World -----------------------------------------------------------------------------------
local table_top = ground { "table", material = "wood" }
local block = box { "block", material = "wood", width = 0.3, height = 0.1, on = table_top, at = 0, mass = mass }
-- At the block's centre, along the table. Three times as wide as it is tall, it cannot tip
-- about its front edge for any mu up to 3 (friction's moment mu·N·h/2 against N·w/2).
local push = force { "push", on = block, force = function(t) return push_rate * t, 0 end }

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(block, table_top)
probe { "push", unit = "N", read = { push, "fx" } }
probe { "friction_force", unit = "N", read = { touch, "fx" } }  -- negative: it pushes back
probe { "speed", unit = "m/s", read = { block, "vx" } }
probe { "slipping", read = { touch, "slipping" } }  -- 1 while the block slides

-- Friction against the push, over the Coulomb law as the spring article stacks it: stuck,
-- friction answers the push, f = −F, while F ≤ mu_s·N; sliding, it is −mu_k·N. The branch that
-- applies now (the contact's state) is drawn bold. The push is the lesson's alone: while the
-- mouse's hand pulls the block too, friction answers both, and the title says so (the window's
-- force gauge plots the hand's pull and the push together).
local N = mass * g
plot { "Friction against the lesson's push", kind = "xy", x = "push", y = { "friction_force" },
  theory = {
    { "sticking: f = −F, F ≤ μs·N", function(F) if F <= math.max(param.mu_s, param.mu_k) * N then return -F end end,
      active = function() return touch.slipping ~= 1 end },
    { "sliding: f = −μk·N", function(F) if F >= param.mu_k * N then return -param.mu_k * N end end,
      active = function() return touch.slipping == 1 end },
  },
  -- The two levels the class reads off the plot: the most static friction can answer, and what
  -- it drops to once the block slides (negative, as friction is here: it pushes back).
  levels = {
    { "−μs·N", function() return -param.mu_s * N end },
    { "−μk·N", function() return -param.mu_k * N end },
  } }
-- The run over time, after the key plot above (the first page in projector mode).
plot { "Push and friction", kind = "time", y = { "push", "friction_force" } }

-- Reading the record ----------------------------------------------------------------------
-- h is the frame the record samples (step_length()), hs the world's own step (substep_length(),
-- h over --substeps). The push is asked at the start of each world step and held through it,
-- and the probe "push" records it as asked at the end of each frame, for the step after.
local function substeps() return math.floor(step_length() / substep_length() + 0.5) end
-- The push that the record shows was held last, and the first it did not hold. The block
-- broke away in the first frame that ends with the contact slipping, frame i; every world
-- step before that frame held its push, the last of them asked a world step before the frame
-- began; the one that broke it was asked within frame i, at the latest a world step before it
-- ended. The pushes a frame's steps apply lie on the line from the push recorded before it to
-- the push recorded after it (the push at t = 0, before the first record, is 0).
local function breakaway_bracket()
  local slipping, pushes = history("slipping"), history("push")
  for i = 1, #slipping do
    if slipping[i] == 1 then
      local before = i > 1 and pushes[i - 1] or 0
      local after = pushes[i]
      local per_step = (after - before) / substeps()
      return before - per_step, after - per_step
    end
  end
end
-- The world says only that the push that broke the block away lies between those two: the
-- middle of them, one frame's growth of the push apart.
local function breakaway_push()
  local held, broke = breakaway_bracket()
  if held then return (held + broke) / 2 end
end

-- The end of the run at the sliders' values, where the last two rows are read.
local ending = run_length
local function at_the_end(probe)
  return reached(ending()) and value_at(probe, ending()) or nil
end
-- The sample read there: the step nearest the run's length (value_at's, the later of two as
-- near), up to half a step from it.
local function end_sample()
  local h = step_length()
  return math.floor(ending() / h + 0.5) * h
end
-- The instants that sample belongs to in theory's slide. A world step applies the push asked
-- at its start, rate·(t − hs) for the step ending at t, which is the mean of the ramp over the
-- span from t − 3hs/2 to t − hs/2: Box2D's velocity after a step (which moves the body, x(t) =
-- x(t − hs) + hs·v) is the continuous slide's hs/2 before the step's end, exactly while the
-- forces change linearly (the midpoint rule). The contact's friction is its last world
-- step's, the drag on the speed that step begins with, hs/2 before its start: 3hs/2 back. (Read
-- at the frame's mean it was off by (h − hs)/2 of the drag's change: 0.002 N at 60 Hz and 8
-- sub-steps, 0.0007 allowed.)
local function speed_instant() return end_sample() - substep_length() / 2 end
local function friction_instant() return end_sample() - 1.5 * substep_length() end

-- Where the run cannot show the end theory describes, the last two rows say so: the block has
-- slid off the table's end (200 m from where it stood, less its half width: past every slider's
-- reach, 29 m at most, at μs 2 and μk 0 breaking away at 1.5 s, but not past a script's edits
-- to the run's length), or it moves more
-- than Box2D lets a body move in one step (b2_maxTranslation, 2 m), which caps its speed (the
-- fastest push at 20 Hz).
local function out_of_reach()
  local final = push_theory(ending())
  if final.distance > 200 - 0.15 then return "off the table's end before the run ends" end
  if final.speed * substep_length() > 2 then return "faster than Box2D's 2 m a step" end
end

-- The drag's step term. The drag is taken off before each step and the push's impulse added
-- after it, so each step's push escapes that step's drag: the step is forward Euler with the
-- drag's rate Γ = f'(v)/m (f = c·v + b·v²) replaced by (1 − e^(−Γh))/h, and the speed the drag
-- holds the block to runs high by (f/f')·(q − 1), q = Γh/(1 − e^(−Γh)) ≈ 1 + Γh/2 (at c = 10,
-- mass 0.1: Γh = 0.42, 22 %). Past Γh = 1 that is over half the drag's share of the speed:
-- the row then says the step is too long rather than compare. (h here is the world's step.)
local function drag_step(t)
  local v = push_theory(t or speed_instant()).speed
  local gamma_h = (param.c + 2 * param.b * v) / mass * substep_length()
  if gamma_h == 0 then return 0, 0 end
  local share = (param.c * v + param.b * v * v) / (param.c + 2 * param.b * v)  -- f/f'
  return share * (gamma_h / (1 - math.exp(-gamma_h)) - 1), gamma_h
end
local function step_too_long()
  local _, gamma_h = drag_step()
  if gamma_h > 1 then return string.format("step too long for this drag: Γ·h = %.3g > 1", gamma_h) end
end

-- What the drag's step term does to the friction, N. On a level table the friction the contact
-- reads over a world step is the push less m times the block's change of speed over it, exactly
-- (momentum), and theory's is the push less m·a: the friction is off by m times the rate the
-- speed's error changes at, not by the error. The step term, y = drag_step(t), is where the
-- error settles while the drag holds the block; the error x follows it at the drag's rate
-- Γ = f'(v)/m, x' = Γ·(y − x), from 0 at the breakaway (where y is 0 too), so m·x' = m·Γ·(y − x),
-- never more than m·Γ·y (x lies between 0 and y). That rate, z = Γ·(y − x), itself moves as
-- z' = Γ·y' − (Γ − Γ'/Γ)·z: while Γ' < Γ² it is drawn to y'/(1 − Γ'/Γ²) and stays under the
-- larger of that and where it started. With Γ steady that is y's steepest rate; with Γ growing
-- (b: Γ' = 2b·a/m) it is more. So, at 16 instants of the slide from a world step past the
-- breakaway to the reading: where Γ grows fast (Γ' ≥ Γ²/2; b alone just past the breakaway,
-- where Γ is still near 0) the bound starts again from Γ·y there, and from then on takes the
-- largest y'/(1 − Γ'/Γ²), y' over a world step. (At b 389, c 979, 8.87 kg, 28 N/s the speed ran
-- 0.037 m/s high at the end and the friction 0.005 N off, where f'(v) times the step term
-- allowed 42 N; this allows 0.06 N.)
local function drag_step_friction()
  local hs = substep_length()
  local start, finish = push_theory(0).breakaway_time, speed_instant()
  local samples, steepest = 16, 0
  for i = 0, samples do
    local t = start + (finish - start) * i / samples
    if t - hs >= start then
      local state = push_theory(t)
      local gamma = (param.c + 2 * param.b * state.speed) / mass
      local gamma_rate = 2 * param.b * math.abs(state.acceleration) / mass
      if gamma_rate >= gamma * gamma / 2 then
        steepest = gamma * math.abs(drag_step(t))
      else
        local rate = math.abs(drag_step(t) - drag_step(t - hs)) / hs
        steepest = math.max(steepest, rate / (1 - gamma_rate / (gamma * gamma)))
      end
    end
  end
  return mass * steepest
end

-- What the rows allow (issue 29: derived, not a flat share). With the push's and the readings'
-- instants matched above, what is left:
-- * The step. The breakaway push is known only to the bracket above, one frame's growth of the
--   push, rate·h: the middle is within half of it. The breakaway itself: the crossing of
--   mu_s·N falls δ into its world step (0 < δ ≤ hs); the treatment holds that step, then gives
--   back the impulse the solver held past the limit and (mu_s − mu_k)·N·(δ + hs/2), kinetic
--   friction since the crossing on Box2D's mid-step velocities, δ found exactly by
--   interpolating the push's margin between the two steps (it grows by rate·hs a step). Against
--   the continuous slide from the crossing, the world's speed then runs behind by
--   rate·(δ − hs/2)²/(2m), at most rate·hs²/(8m), and keeps that while the forces are linear
--   (on a smooth table, from t = 0, just that). No drag: the friction at the end is mu_k·N
--   exactly, in every step.
-- * The drag (c, b), whose splitting from the push leaves the speed high by up to drag_step()
--   (above). The friction is the drag's mean over each world step on the speed the step begins
--   with, which is the speed's error off theory's, and the drag's decay within the step takes
--   f'(v)·f·hs/(2m) off it, f'(v)·drag_step() to first order: the friction is off by f'(v)
--   times the rest of the speed's allowance at most (with b = 4.7, 10 kg at 0.2 N/s, 0.28 m/s:
--   the speed 2.3e-4 m/s behind from the breakaway, the friction 8.4e-4 N short), and by the
--   step term's share, drag_step_friction() (above), or f'(v)·drag_step() if less. And with b the
--   mean of b·v² over a frame whose speed changes by (|a| + f/m)·h exceeds b·v² at its middle
--   by b·((|a| + f/m)·h)²/12.
-- * The listener's breakaway tolerance: friction within 1e-5 of mu_s·N is friction at the
--   limit (physics/treatment_stick_slip.cpp), so a push up to that much past mu_s·N may be held
--   a step more: the bracket moves by up to 1e-5 of the breakaway push, and the slide keeps up to
--   1e-5·mu_s·N·hs of impulse held and loses kinetic friction's excess, (mu_s − mu_k)·N, for
--   the time the push takes to grow by it.
-- * The solver: none. On a level table each iteration's normal impulse is the block's weight,
--   and the friction at its clamp, sliding, is mu_k times it; stuck at rest, the friction
--   answers the push alone.
-- * Single precision (floats, 2^-24 of the magnitudes per operation; theory is double). The
--   limit the breakaway is judged by, mu_s·N, is the normal impulse of the block's two contact
--   points after the warm start and 8 iterations (1 + 9·2 = 19 operations), compared with a
--   push and a friction that are floats too: 21·2^-24 of the breakaway push and of the pushes
--   recorded around it (on a smooth table, 0 and rate·h as floats); the friction read
--   at the end, the same share of itself. The speed keeps every world step's rounding: sliding
--   at the clamp, the integration and the two points' warm start round the speed (3 a step, 4
--   with the drag's step), and the 21 operations round no more than the step's change of it.
local operations = 21
local function allowed()
  local h, hs = step_length(), substep_length()
  local start, final = push_theory(0), push_theory(speed_instant())
  local N = mass * g
  -- At rest the speed is 0 and rounds to 0: only the slide's steps count.
  local steps = math.floor((speed_instant() - start.breakaway_time) / hs + 0.5) + 1
  local drag = param.c * final.speed + param.b * final.speed * final.speed
  local change = (final.push + param.mu_k * N + drag) / mass * hs
  local roundings = (param.c > 0 or param.b > 0) and 4 or 3
  local held_longer = 1e-5 * start.breakaway_push
  -- A creep the drag takes away within each step looks, to the listener, like the solver's
  -- leftover: a first step past mu_s·N within its hold band is then watched a step, and the
  -- block breaks away at the next (physics/treatment_stick_slip.cpp): the bracket a step later.
  -- A steady push with no drag leaves a creep as fast at a step's end as at its start, never
  -- watched. (10 kg, c 131, mu_s 0.19, 0.2 N/s: 0.0007 N past theory's, 0.00063 allowed.)
  local watched = (param.c > 0 or param.b > 0) and push_rate * h or 0
  local speed = push_rate * hs * hs / (8 * mass)
                + held_longer * (hs + (start.breakaway_push - param.mu_k * N) / push_rate) / mass
                + steps * 2 ^ -24 * (roundings * final.speed + operations * change)
                + drag_step()
  local slope = param.c + 2 * param.b * final.speed  -- f'(v)
  local swing = (math.abs(final.acceleration) + drag / mass) * h
  local step_term = drag_step()
  local split = math.min(slope * step_term, drag_step_friction())
  return {
    breakaway = push_rate * h / 2 + held_longer + watched + operations * 2 ^ -24 * (start.breakaway_push + push_rate * h),
    friction = operations * 2 ^ -24 * final.friction + slope * (speed - step_term) + split + param.b * swing * swing / 12,
    speed = speed,
  }
end

-- Expectations ----------------------------------------------------------------------------
expect { "breakaway push", unit = "N",
  predicted = function() return push_theory(0).breakaway_push end,
  measured = breakaway_push,
  tolerance = function() return allowed().breakaway end }

-- Friction includes the drag c·v + b·v² when a slider sets them: the table's whole answer.
expect { "friction at the end", unit = "N",
  -- Signed as the probe is (to the right positive): theory's size, pointing back.
  predicted = function() return out_of_reach() or -push_theory(friction_instant()).friction end,
  measured = function()
    if out_of_reach() then return out_of_reach() end
    return at_the_end("friction_force")
  end,
  tolerance = function() return allowed().friction end }

-- Whether friction, once the block slides, is smaller than the push that broke it away, the same,
-- or larger: the two rows above set side by side, as a class compares them. At the defaults
-- kinetic friction is a quarter below static (mu_k·N against mu_s·N): smaller. A strong drag can
-- make it larger by the end. The world's difference of the two lies within `band` (the two rows'
-- tolerances together) of theory's, so no one threshold gives both sides the same word near it:
-- theory says "the same" within the band, and the world within twice it; from one band to three
-- either word may come, and both sides say which two (a class that answered either is right).
-- At mu_s 1.076 and mu_k 1.068 (0.1 kg, 9.34 N/s) theory's difference was 0.0075 N within a band
-- of 0.019, the world's breakaway read 0.015 N high: 0.022 N, "smaller" against "the same".
local function compared(difference, band)
  if math.abs(difference) <= band then return "the same" end
  return difference < 0 and "smaller" or "larger"
end
-- Near the line: the two words either side may give, and the row's word for both.
local function either_near(difference, band)
  if math.abs(difference) <= band or math.abs(difference) > 3 * band then return nil end
  if difference < 0 then return "smaller or the same", "smaller", "the same" end
  return "the same or larger", "the same", "larger"
end
local function same_band()
  local allows = allowed()
  return allows.breakaway + allows.friction
end
-- Friction while the block slides: at the end of the run once it is there; before that the
-- latest step's, from the second step of the slide on (the step the slip is seen in still
-- holds the static friction that gave way, as large as the push: "the same" for one frame).
-- So the row answers as soon as the class sees the block slide (a teacher's trial: it said
-- "not yet" mid-slide); a drag strong enough to make the end "larger" changes it as it grows.
local function sliding_friction()
  local at_end = at_the_end("friction_force")
  if at_end ~= nil then return at_end end
  local slipping, friction = history("slipping"), history("friction_force")
  for i = 1, #slipping do
    if slipping[i] == 1 then
      if #slipping > i and slipping[#slipping] == 1 then return friction[#friction] end
      return nil
    end
  end
end

-- A word has no tolerance for the drag's step term: where the step is too long for the drag
-- (see "speed at the end") the row says so instead.
expect { "sliding vs breakaway",
  predicted = function()
    if out_of_reach() or step_too_long() then return out_of_reach() or step_too_long() end
    local difference, band = push_theory(friction_instant()).friction - push_theory(0).breakaway_push, same_band()
    return (either_near(difference, band)) or compared(difference, band)
  end,
  measured = function()
    if out_of_reach() or step_too_long() then return out_of_reach() or step_too_long() end
    local f, breakaway = sliding_friction(), breakaway_push()
    if f == nil or breakaway == nil then return nil end
    local band = same_band()
    local word = compared(-f - breakaway, 2 * band)
    local either, one, other = either_near(push_theory(friction_instant()).friction - push_theory(0).breakaway_push, band)
    if either and (word == one or word == other) then return either end
    return word
  end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "breakaway push", unit = "N",
  question = "The push grows steadily. How hard is it when the block starts to move?" }
predict { "sliding vs breakaway", choices = { "smaller", "the same", "larger" },
  question = "Once it slides, is friction smaller than the push that started it, the same, or larger?" }

expect { "speed at the end", unit = "m/s",
  predicted = function() return out_of_reach() or step_too_long() or push_theory(speed_instant()).speed end,
  measured = function() return out_of_reach() or step_too_long() or at_the_end("speed") end,
  tolerance = function() return allowed().speed end }
