-- where_methods_fail: three blocks on a slope they should stick to, each with its own friction.
-- The tribology article's games replace Coulomb's jump at v = 0 with a steep line: below a
-- threshold speed epsilon, friction = -mu_s·N·v/epsilon. With a large epsilon the block creeps
-- down a slope that should hold it, at epsilon·tan(angle)/mu_s. With a small one the line is so
-- steep that a fixed step overshoots it: it settles only while the step h < 2·epsilon/(mu_s·g·cos
-- angle), and beyond that the block jitters for ever (Box2D steps by semi-implicit Euler, whose
-- boundary this is). FrictionLab's stick-slip treatment (the top block) holds it still, as the
-- exact answer does. `frictionlab bench` draws the map of where each integrator settles or chatters.

local run_length = 3  -- s

lesson {
  title = "Where methods fail",
  question = "Why does a game's block creep down a slope it should stick to, or jitter on it, and what holds it still?",
  duration = run_length,
  order = 40,
  -- Two seconds in: the stick-slip block has not moved while the large threshold has crept
  -- centimetres; with a threshold of 2 cm/s the small one settles to its creep speed instead.
  moments = {
    { "stick_slip_holds", at = 2, readme = true,
      shows = function()
        return math.abs(value_at("stick_slip", time())) < 0.001 and value_at("large_epsilon_distance", time()) > 0.02
      end },
    { "small_epsilon_settles", at = 2, set = { small_epsilon = 0.02 },
      shows = function()
        local creep = param.small_epsilon * math.tan(math.rad(param.angle)) / param.mu_s
        return math.abs(value_at("small_epsilon_speed", time()) - creep) < 0.01 * creep
      end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local angle = parameter { "angle", 20, min = 2, max = 30, unit = "°", text = "slope angle (below atan 0.6 = 31°: it sticks)" }
-- From 2 cm/s up, the large threshold is stable at 240 Hz on any of these slopes (its boundary
-- is 7.8 ms or more), so its creep can be read against the formula.
local large = parameter { "large_epsilon", 0.05, min = 0.02, max = 0.5, unit = "m/s", text = "a large threshold speed" }
local small = parameter { "small_epsilon", 0.002, min = 0.0001, max = 0.05, unit = "m/s", text = "a small threshold speed" }

-- Each block has its own material, so that its pair with the slope can have its own treatment;
-- the two regularized pairs take the stick-slip pair's mu_s and mu_k (one pair of sliders).
material { "block", density = 500, note = "the mass is set on the block itself" }
material { "soft_law_block", density = 500, note = "the mass is set on the block itself" }
material { "stiff_law_block", density = 500, note = "the mass is set on the block itself" }
material { "slope", density = 500, note = "fixed, so its density plays no part" }
pair { "block", "slope", mu_s = 0.6, mu_k = 0.5, treatment = "stick-slip" }
pair { "soft_law_block", "slope", like = { "block", "slope" }, treatment = "regularized", epsilon = large }
pair { "stiff_law_block", "slope", like = { "block", "slope" }, treatment = "regularized", epsilon = small }
-- The blocks stand apart and never touch, but any two that could need values.
pair { "block", "soft_law_block", like = { "block", "slope" } }
pair { "block", "stiff_law_block", like = { "block", "slope" } }
pair { "soft_law_block", "stiff_law_block", like = { "block", "slope" } }
pair { "block", "block", like = { "block", "slope" } }
pair { "soft_law_block", "soft_law_block", like = { "block", "slope" } }
pair { "stiff_law_block", "stiff_law_block", like = { "block", "slope" } }

-- World -----------------------------------------------------------------------------------
ground { material = "slope" }
local slope = incline { "slope", material = "slope", angle = angle, length = 8 }
local block = box { "block", material = "block", width = 0.4, height = 0.2, on = slope, at = 5.6, mass = 1 }
local creeping = box { "creeping", material = "soft_law_block", width = 0.4, height = 0.2, on = slope, at = 4.4, mass = 1 }
-- 1.2 m apart: close enough to be seen together, and the creep (3 cm/s) never closes the gap.
local jittering = box { "jittering", material = "stiff_law_block", width = 0.4, height = 0.2, on = slope, at = 3.2, mass = 1 }
-- A strip each, on its own block: the three methods side by side, each big enough to read.
-- The lanes and plots name each block by its law and threshold, not by what it does: the class
-- predicts that (a lane called "jitters" gave the answer away before Play).
view { lanes = { block, creeping, jittering }, titles = { "stick-slip", "regularized, large threshold ε", "regularized, small threshold ε" } }
local downhill = { -math.cos(math.rad(angle)), -math.sin(math.rad(angle)) }

-- Probes and plots ------------------------------------------------------------------------
probe { "stick_slip", unit = "m", read = { block, "distance", along = downhill } }
probe { "exact", unit = "m", function() return 0 end }  -- Coulomb: it never moves
probe { "large_epsilon_distance", unit = "m", read = { creeping, "distance", along = downhill } }
probe { "large_epsilon_speed", unit = "m/s", read = { creeping, "speed", along = downhill } }
probe { "stick_slip_speed", unit = "m/s", read = { block, "speed", along = downhill } }
probe { "small_epsilon_speed", unit = "m/s", read = { jittering, "speed", along = downhill } }
probe { "small_epsilon_distance", unit = "m", read = { jittering, "distance", along = downhill } }
-- A block that breaks away (both regularized ones can) may catch up with the one below it.
probe { "regularized_blocks_touch", read = { contact(creeping, jittering), "points" } }

plot { "Distance down the slope", y = { "large_epsilon_distance", "stick_slip", "exact" } }
plot { "Speed down the slope", y = { "small_epsilon_speed", "stick_slip_speed" } }

-- Expectations ----------------------------------------------------------------------------
-- Read as the lesson runs, once half a second has shown what each does. Stick-slip holds
-- while max(mu_s, mu_k) > tan(angle). The regularized law's creep speed and jitter boundary
-- exist only while its linear branch can balance the slope, mu_s > tan(angle); elsewhere
-- (mu_s = 0 included) the rows say that theory has no answer there.
local function shown() return time() >= 0.5 end  -- (and the blocks apart that long: see readable())
local tilt = math.tan(math.rad(angle))
local function stick_slip_holds() return math.max(param.mu_s, param.mu_k) > tilt end
local function has_theory() return param.mu_s > tilt end
local no_theory = "no theory: μs ≤ tan θ"
-- The creep as this step takes the law, with the pair's drag c and b too (they slow the creep;
-- with neither it is ε·tan θ/μs at any step), and whether the step settles onto it. The step is
-- the world's own: under --substeps the law acts every sub-step, and its boundary is the
-- sub-step's (given the frame's, 36 of 80 random settings with 2 sub-steps read "jitters" on
-- one side and a creep on the other).
-- The rows ask it several times whenever they are read; it steps the law from rest to now, so
-- each answer is kept until the time or a value changes.
local creeps = {}
local function creep(epsilon)
  local key = string.format("%.17g %.17g %.17g %.17g %.17g %.17g", epsilon, time(), param.mu_s, param.mu_k, param.c, param.b)
  if not creeps[epsilon] or creeps[epsilon].key ~= key then
    creeps[epsilon] = { key = key, answer = theory.regularized_creep {
      angle = angle, mu_s = param.mu_s, mu_k = param.mu_k, epsilon = epsilon, c = param.c, b = param.b, mass = 1,
      step = substep_length(), duration = time() } }
  end
  return creeps[epsilon].answer
end
local no_creep = "jitters: no steady creep at this step"

-- Past the boundary the speed swings about its creep speed at every step and the swing never
-- dies; below it, the swing dies away. (It need not cross zero: the block also creeps.) The
-- swing at the end of the record so far is set against the swing around its middle. Where
-- mu_k < tan(angle) an overshoot past epsilon lets kinetic friction lose its hold, and the
-- block breaks away down the slope: it never settles either, and once it is faster than ε (a
-- creep never is) it is counted as jittering. (A creep at the large threshold's top can cover
-- more than a metre in the run: distance is no sign of breaking away.)
-- The records are read up to the step before the two regularized blocks first touch: after
-- that neither moves by its own law alone.
local function readable()
  local touches = history("regularized_blocks_touch")
  for i = 1, #touches do
    if touches[i] > 0 then return i - 1 end
  end
  return #touches
end

-- The world's sub-steps in one of its frames (1 without sub-steps).
local function substeps_a_frame() return math.floor(step_length() / substep_length() + 0.5) end

-- Under sub-steps a frame ends on every other one (with two), and a swing that flips at every
-- step, a cycle of two, shows the same speed at every frame's end: the record looks settled (at
-- -0.0090 m/s, sub-steps of +0.0232 between). The distance the frame covered tells it: each
-- sub-step moves the block by its length times its end speed, so a block that creeps covers its
-- end speed times the frame, and one in a cycle does not (+0.0071 m/s over the frame there).
-- A cycle that dies away leaves less of that difference at the end than around the middle (on
-- the law's linear branch each step shrinks it by the same factor); one that stays or grows
-- does not. The world keeps positions in single precision on the 8 m slope, and each
-- sub-step's move rounds the position by up to 2^-24·8 m (at a creep of 1.6 mm/s, 4 sub-steps:
-- 2.3e-4 m/s off over the frame, every frame), and the two positions read once more each:
-- (sub-steps + 2)·2^-24·8 m over the frame, below which nothing is read.
local function hidden_swing(speeds, distances, n)
  if substep_length() == step_length() or n < 3 then return false end
  local function off(i) return math.abs((distances[i] - distances[i - 1]) / step_length() - speeds[i]) end
  local substeps = substeps_a_frame()
  local unread = (substeps + 2) * 2 ^ -24 * 8 / step_length()
  -- (Set against the most around the middle of the run: over a frame or two a slowly dying
  -- cycle shrinks by less than the rounding, 0.4 % in two frames at 720 sub-steps a second.)
  local middle = 0
  for i = math.max(2, math.floor(0.4 * n)), math.floor(0.5 * n) do middle = math.max(middle, off(i)) end
  return off(n) > unread and off(n) + unread >= middle
end
local function seen(speed_probe, epsilon, distance_probe)
  local n = readable()
  local speeds = history(speed_probe)
  -- A block that settles does so on the law's linear branch, where the creep is: its last two
  -- speeds are both under ε, as the theory's own `settles` asks of its steps. A cycle of two
  -- steps bounded by drag and ε can be steady and still leave that branch every other step
  -- (c 507 N·s/m, b 813 N·s²/m², ε 0.0133 m/s at 7.4°, 240 Hz: −0.0153 and +0.0034 m/s for
  -- ever, after a swing of 0.064 m/s mid-run that made its end look like a settling; at ε
  -- 0.02 m/s on 18.2°, c 434, b 294: −0.0217 and +0.0093 m/s).
  if math.abs(speeds[n]) > epsilon or (n >= 2 and math.abs(speeds[n - 1]) > epsilon) then return "jitters" end
  if hidden_swing(speeds, history(distance_probe), n) then return "jitters" end
  local steady = creep(epsilon).speed
  local function swing(from, to)
    local largest = 0
    for i = math.max(1, math.floor(from)), math.floor(to) do largest = math.max(largest, math.abs(speeds[i] - steady)) end
    return largest
  end
  local late, middle = swing(0.9 * n, n), swing(0.4 * n, 0.5 * n)
  -- A swing that settles only shrinks from the first steps' (on the law's linear branch each
  -- step multiplies it by the same factor, below 1, and drag b only shrinks it faster); one
  -- past the boundary grows until ε and kinetic friction bound it,
  -- and then wanders there (c = 1000 N·s/m, b = 313.6 N·s²/m² at ε = 0.05 m/s: 0.051 m/s
  -- around the middle of the run, 0.025 at its end, from 0.0007 at the first step).
  local first = swing(1, math.min(2, n))
  -- A swing that shrinks slowly may still be above half its middle's at the end: with the
  -- step's factor near −1 it takes the whole run to halve (c = 1000 N·s/m, h·k = 1.014: −0.998
  -- a step; 0.0016 m/s at first, 0.0010 mid-run and 0.0006 at the end). It settles all the
  -- same if it never grew past its first steps', never left the law's linear branch (|v| < ε,
  -- where a jitter's swing ends up) and still shrinks from the middle of the run to its end.
  local fastest = 0
  for i = 3, n do fastest = math.max(fastest, math.abs(speeds[i])) end
  -- A swing can also shrink toward a cycle that stays: past the boundary (the creep's own
  -- factor -1.008 a step: ε 0.0314 m/s, μs 1.704 on 30°, b 1000 N·s²/m² at 240 Hz) drag b
  -- holds a cycle of two steps, which the swing from the first step's overshoot nears from
  -- above, 0.0095 m/s off the creep mid-run and 0.0093 at the end. A settling swing shrinks by
  -- the same factor over equal spans of steps (on the linear branch), so its shrinkings do
  -- too, and the limit Aitken's Δ² takes from three equal spans is 0; a swing nearing a
  -- cycle shrinks ever more slowly, toward that cycle's size (there 0.0093). One whose limit
  -- is more than half its last size is nearing a cycle, not settling: half, midway between the
  -- two pure cases (0 for a settling, the last size itself for a cycle reached). A swing that
  -- shrank only as a power of the steps (as 1/k: a limit two thirds of the last size) would be
  -- taken for a cycle too: off the linear branch, or at a factor of exactly -1, where the
  -- "on the boundary" words answer first (undecided below); none of 6 300 random settings
  -- checked read so.
  local function step_swing(to)  -- half the largest change between two steps, over four
    local largest = 0
    for i = math.max(2, to - 3), to do largest = math.max(largest, math.abs(speeds[i] - speeds[i - 1])) end
    return 0.5 * largest
  end
  local function nearing_a_cycle()
    local span = math.floor(0.25 * n)
    if span < 4 then return false end
    local s1, s2, s3 = step_swing(n - 2 * span), step_swing(n - span), step_swing(n)
    local d1, d2 = s2 - s1, s3 - s2
    if not (d1 < 0 and d2 < 0 and d2 > d1) then return false end
    return s3 - d2 * d2 / (d2 - d1) > 0.5 * s3
  end
  local shrinking = swing(3, n) <= first and fastest < epsilon and late < middle and not nearing_a_cycle()
  if late <= 1e-3 * epsilon or shrinking then return "settles" end
  -- On the law's linear branch a settling swing shrinks at every step; one still growing from
  -- two steps back to the last is no settling, however much larger it was mid-run (drag b
  -- bounds a swing past the boundary, which may shrink a while and grow again: b = 375 N·s²/m²,
  -- ε = 0.18 m/s at 60 Hz, 0.12 m/s off the creep mid-run, 0.022 at the end and growing).
  if n >= 3 and math.abs(speeds[n] - steady) > math.abs(speeds[n - 2] - steady) then return "jitters" end
  return (late >= 0.5 * middle or late > first) and "jitters" or "settles"
end

-- A block that breaks away slides on under mu_k, c and b; with strong drag it can cover less
-- than the millimetre that counts as sliding in the time so far, and theory says so too. As the
-- world steps it: drag faster than a step (m/c < h) lets a stepped block creep faster than the
-- continuous law does (c = 800 N·s/m at 240 Hz: 0.86 mm/s, not 0.25), to 2.8 mm in 3 s.
-- (Kept for the time and values it was worked out at, as creep's answers are: a row reads it
-- up to three times, and the stepped law walks every step of the run so far.)
local slid_for = {}
local function slid()
  local key = string.format("%.17g %.17g %.17g %.17g", time(), param.mu_k, param.c, param.b)
  if slid_for.key ~= key then
    slid_for = { key = key, distance = theory.incline_motion { angle = angle, mu_k = param.mu_k, c = param.c, b = param.b,
                                                               mass = 1, t = time(), step = substep_length() }.distance }
  end
  return slid_for.distance
end
-- Box2D keeps a body's position in single precision and adds h·v to it each step, rounded to
-- the floats' spacing at its coordinates (and a contact's push out of the slope rounds them
-- again): up to a spacing a step in each, along the slope n·(spacing at x·cos θ + spacing at
-- y·sin θ) after n steps. A creep near the line moves a few spacings a step, so the rounding
-- is a tenth of its way: c = b = 1000 at 13.05°, 240 Hz, μk 0.224: 3.23e-4 m/s, 1.35e-6 m a
-- step, which the world rounds to 1.47e-6 along the slope; 1.06 mm in 3 s where the stepped
-- law in doubles says 0.97. Within that of the line neither word can be told, and the row
-- sets the distances side by side instead, to the rounding's bound.
local start_x, start_y = block.x, block.y
local function float_spacing(v) return 2 ^ (math.floor(math.log(math.abs(v), 2)) - 23) end
-- (Down the slope both coordinates shrink, and their spacings with them: the start's are the
-- largest on the way.)
local function rounding_bound()
  local steps = time() / substep_length()
  return steps * (float_spacing(start_x) * math.cos(math.rad(angle)) + float_spacing(start_y) * math.sin(math.rad(angle)))
end
local line = 0.001
local function at_the_line() return math.abs(slid() - line) <= rounding_bound() end
expect { "stick-slip: slid", unit = "m",
  predicted = function()
    if stick_slip_holds() then return 0 end
    if at_the_line() then return slid() end
    return slid() > line and "slides" or "holds"
  end,
  measured = function()
    if not shown() then return nil end
    if stick_slip_holds() or at_the_line() then return value_at("stick_slip", time()) end
    return value_at("stick_slip", time()) > line and "slides" or "holds"
  end,
  tolerance = function()
    if stick_slip_holds() then return line end
    return rounding_bound()
  end }

-- Where the step's factor on the swing is so near −1 past the boundary that over the half of the
-- run that seen() compares (its middle against its end, a swing judged to jitter while it has
-- not halved) the swing grows by less than twice, the run cannot tell a jitter from a settling,
-- and both sides say so. (μs 0.97, μk 1.87, c 21, b 932 at ε 0.02 m/s: −1.0003 a step, 1.11
-- over those 360 steps; the world's swing, held by b's drag, shrank, and the row compared the
-- theory's "jitters" with a creep speed.)
local boundary = "on the boundary: too slow to tell in this run"
-- Over the whole run, as it will be read (the record up to the blocks' first touch, once there is
-- one), so that the answer is the same before Play and after.
local function undecided(epsilon)
  local factor = math.abs(creep(epsilon).amplification or 0)
  local frames = math.floor(run_length / step_length() + 0.5)
  local touches = history("regularized_blocks_touch")
  if #touches > 0 and readable() < #touches then frames = readable() end
  return factor >= 1 and factor ^ (0.5 * frames * substeps_a_frame()) < 2
end

-- Where the large threshold too is past its step's boundary (μs near 2 at 2 cm/s), it has no
-- creep speed to read, and both sides say so. Its speed starts at 0 and closes on the creep by
-- the factor `amplification` a step: what is left of that after the run so far, and 1 % for
-- the rest.
expect { "large ε: creep speed", unit = "m/s",
  predicted = function()
    if not has_theory() then return no_theory end
    if undecided(large) then return boundary end
    return creep(large).settles and creep(large).speed or no_creep
  end,
  measured = function()
    if not shown() then return nil end
    if not has_theory() then return no_theory end
    if undecided(large) then return boundary end
    if seen("large_epsilon_speed", large, "large_epsilon_distance") == "jitters" then return no_creep end
    -- Settled where the theory says it jitters: words, so that the row differs rather than
    -- setting a number against words.
    if not creep(large).settles then return "settles" end
    return history("large_epsilon_speed")[readable()]
  end,
  tolerance = function()
    if not has_theory() or not creep(large).settles then return 0 end
    local c = creep(large)
    local steps = readable() * substeps_a_frame() - 1  -- the world's steps
    return (0.01 + math.abs(c.amplification) ^ steps) * c.speed
  end }

expect { "small ε: at this step",
  predicted = function()
    if not has_theory() then return no_theory end
    if undecided(small) then return boundary end
    return creep(small).settles and "settles" or "jitters"
  end,
  measured = function()
    if not shown() then return nil end
    if not has_theory() then return no_theory end
    if undecided(small) then return boundary end
    return seen("small_epsilon_speed", small, "small_epsilon_distance")
  end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "small ε: at this step", choices = { "jitters", "settles" },
  question = "With a small threshold and this time step, does the block jitter for ever or settle?" }
predict { "large ε: creep speed", unit = "m/s",
  question = "With a large threshold, how fast does the block creep down a slope it should stick to?" }
