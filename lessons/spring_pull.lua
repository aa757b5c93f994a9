-- spring_pull: a spring pulls a block along a wooden bench.
-- The spring article: the spring's stretch measures the force. Static friction holds the
-- block until the pull reaches mu_s·N; then kinetic friction, mu_k·N, takes over, the block
-- lurches forward, the spring relaxes, and the block sticks again: stick-slip.

-- Long enough for the first breakaway and four more cycles, whatever the sliders say. With
-- no cycle (mu_k >= mu_s: see below) the spring's own swing, 2π·sqrt(m/k), stands in.
local function run_length()
  local first = param.mu_s * param.mass * g / (param.k * param.pull_speed)
  if param.mu_k >= param.mu_s then
    return first + 4.5 * 2 * math.pi * math.sqrt(param.mass / param.k)
  end
  local cycle = theory.spring_stick_slip { mass = param.mass, k = param.k, pull_speed = param.pull_speed,
                                           mu_s = param.mu_s, mu_k = param.mu_k }
  return cycle.first_breakaway_time + 4.5 * cycle.period
end

lesson {
  title = "A spring pulls a block",
  -- The question leaves the jerks for the class to predict (see predict below).
  question = "How hard must the spring pull before the block moves, and how does it move once it does?",
  duration = run_length,
  order = 10,
  -- Its pictures: held by static friction, in the first slip, in the second slip (the README's
  -- frame), and the same in the dark theme. The probes are recorded once these run.
  moments = {
    { "sticking", at = 0.5, shows = function() return value_at("slipping", time()) == 0 end },
    { "mid_slip", at = 1.2, shows = function() return value_at("slipping", time()) == 1 end },
    { "second_slip", at = 2.5, readme = true, shows = function() return value_at("slipping", time()) == 1 end },
    { "dark_theme", at = 2.5, theme = "dark", shows = function() return value_at("slipping", time()) == 1 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local block_material = parameter { "block", "aluminium", choices = { "aluminium", "plastic" },
                                   text = "the block the article pulls" }
local mass = parameter { "mass", 1.0, min = 0.1, max = 5, unit = "kg", text = "mass of the block" }
local k = parameter { "k", 50, min = 5, max = 500, unit = "N/m", text = "spring stiffness" }
local pull_speed = parameter { "pull_speed", 0.1, min = 0.02, max = 0.5, unit = "m/s", text = "speed of the hand" }

-- The block on the bench. mu_s, mu_k, c and b become sliders, starting from the preset
-- values for the chosen block on wood.
pair { block_material, "wood" }

-- World -----------------------------------------------------------------------------------
local bench = ground { material = "wood" }
-- 8 cm high: pulled through its centre, only friction at its foot turns it, and the foot is
-- 4 cm below the centre; the weight holds it flat while friction·0.04 m <= weight·0.1 m, up to
-- mu = 2.5, past the sliders' 2. (10 cm high, it would tip from mu = 2.)
local block = box { "block", material = block_material, width = 0.2, height = 0.08, on = bench, at = 0, mass = mass }

-- The hand holds the spring's far end one rest length ahead of the block and walks away. The
-- block's lurch may carry it past where the spring is unstretched, squeezing it by up to
-- μs·N/k (a re-stick force as low as −μs·N, with μk near 0); a spring shorter than that
-- would be overrun, its ends crossing, and it would pull the block on instead of pushing it
-- back (5 N/m, 4.25 kg, μs 0.32, μk 0.12: the block went past the hand). So it is a fifth
-- longer than the largest squeeze the μs slider allows (pair{}'s sliders end at μs = 2). That
-- is μs's end, not its value: reading param.mu_s here would make its slider restart the run,
-- and a teacher changes μs while the block is pulled. At the defaults it is 0.47 m: 0.5 m.
local largest_mu_s = 2
local rest_length = math.max(0.5, 1.2 * largest_mu_s * mass * g / k)
local hand_x, hand_y = block.x + rest_length, block.y
local pull = spring { "spring", from = block, k = k, rest_length = rest_length,
                      to = function(t) return hand_x + pull_speed * t, hand_y end }

-- Probes and plots ------------------------------------------------------------------------
-- The contact between block and bench, read whenever its fields are read. Its friction is
-- everything the bench does along itself: the dry part and, when c or b is set, the drag.
local touch = contact(block, bench)
probe { "spring_force", unit = "N", read = { pull, "force_x" } }
probe { "friction_force", unit = "N", read = { touch, "fx" } }
probe { "block_speed", unit = "m/s", read = { block, "vx" } }
probe { "slipping", read = { touch, "slipping" } }  -- 1 while the block slides, 0 while it sticks

local N = mass * g  -- the bench holds the block up: it lies flat
-- Where friction gives way as the spring pulls forward, and where it sits while sliding
-- (negative: it pulls the block back). Both plots draw them: the first is the one a projector
-- shows, and its friction curve climbs to the one and drops to the other at each slip.
local friction_levels = {
  { "−μs·N", function() return -param.mu_s * N end },
  { "−μk·N", function() return -param.mu_k * N end },
}
plot { "Forces on the block", kind = "time", y = { "spring_force", "friction_force" }, levels = friction_levels }
-- Friction against the pull, over the Coulomb law as the article stacks it: stuck, friction
-- answers the pull, f = −F, as long as |F| ≤ μs·N; sliding, it is −μk·N whatever the pull.
-- The branch that applies (the contact's state) is drawn bold.
plot { "Friction against the pull", kind = "xy", x = "spring_force", y = { "friction_force" },
  theory = {
    { "sticking: f = −F, |F| ≤ μs·N", function(F) if math.abs(F) <= param.mu_s * N then return -F end end,
      active = function() return touch.slipping ~= 1 end },
    { "sliding: f = −μk·N", function(F) return -param.mu_k * N end,
      active = function() return touch.slipping == 1 end },
  },
  levels = friction_levels }

-- Reading the record ----------------------------------------------------------------------
-- Like the article's experiment: record, then read the graph. The contact changes state during
-- a step, so the pull that made it change is the one recorded the step before. Before the
-- first record the block stands stuck on an unstretched spring (no pull): under --substeps a
-- stiff spring may break it away within the first frame, whose record already reads slipping.
-- Averages over every breakaway and re-stick; nil where none happened yet.
local function stick_and_slip()
  local times, slipping, pulls = history("time"), history("slipping"), history("spring_force")
  local first, last, breakaways, breakaway_sum, resticks, restick_sum = nil, nil, 0, 0, 0, 0
  local first_force
  local slipping_before, pull_before = 0, 0
  for i = 1, #times do
    if slipping_before == 0 and slipping[i] == 1 then
      breakaways, breakaway_sum = breakaways + 1, breakaway_sum + pull_before
      first_force = first_force or pull_before
      first, last = first or times[i], times[i]
    elseif slipping_before == 1 and slipping[i] == 0 then
      resticks, restick_sum = resticks + 1, restick_sum + pull_before
    end
    slipping_before, pull_before = slipping[i], pulls[i]
  end
  return { breakaway_force = breakaways > 0 and breakaway_sum / breakaways or nil, first_breakaway_force = first_force,
           restick_force = resticks > 0 and restick_sum / resticks or nil,
           period = breakaways > 1 and (last - first) / (breakaways - 1) or nil }
end

-- Expectations ----------------------------------------------------------------------------
-- Theory is the run itself by the exact reduced model (theory.spring_stick_slip with a
-- duration): the same block, spring, hand and friction (mu_s, mu_k, c and b), read as the
-- record is read below. Without drag that is the closed form's cycle from the first breakaway
-- on; drag has no closed form, and may keep the block sliding after the hand for good.
-- With mu_k >= mu_s (mu_s = 0 among them) nothing makes the block lurch: once it moves,
-- friction at least as large as the pull stops it again, and it creeps after the hand. With
-- mu_k = 0 the spring, pushing back, stops the block with exactly mu_s·N: whether it holds there
-- is decided by less than a step, so the re-stick and what follows have no answer to check.
-- There the rows say so in words, from both sides.
local function no_cycle()
  if param.mu_k >= param.mu_s then return "no cycle: μk ≥ μs" end
  return nil
end
local cached_key, cached_run
local function run()
  local key = string.format("%.17g %.17g %.17g %.17g", param.mu_s, param.mu_k, param.c, param.b)
  if key ~= cached_key then
    cached_run = theory.spring_stick_slip { mass = mass, k = k, pull_speed = pull_speed, mu_s = param.mu_s,
                                            mu_k = param.mu_k, c = param.c, b = param.b, duration = run_length() }.run
    cached_key = key
  end
  return cached_run
end
local weight = mass * g
-- What the world's steps may move each reading by, for the rows' tolerances (h the frame's step,
-- step_length(), where the record is read; the world's own step, substep_length(), where the
-- world moves the block):
-- * The pull grows by k·v·h in a step, and a slip is seen at the end of the step it begins in:
--   the breakaway's recorded pull lies within k·v·h of μs·N, and the slip after it starts with
--   up to that much more force than the model's.
local function pull_in_a_step() return k * pull_speed * step_length() end
-- * A slip is a swing of the spring, at ω = sqrt(k/m), of amplitude A (in force: half the fall
--   from the breakaway force to the re-stick force). The world's block stops at the end of the
--   step in which it would turn back, at most a·h² of travel (a ≤ ω²·A/k) from where the model's
--   stops, k·a·h² = (ωh)²·A in force; and Box2D's symplectic Euler keeps not the energy but one
--   that differs from it by h·ω²·x·v, which moves the swing's far end, seen at a step, by about
--   (ωh)²·A/8 more: allowed here as (ωh)²·A/2, on the safe side. h is the world's step.
-- The swing's amplitude A in force, N (0 before a re-stick is known).
local function swing_force()
  local cycle = run()
  return cycle.breakaway_force and cycle.restick_force and math.abs(cycle.breakaway_force - cycle.restick_force) / 2 or 0
end
local function swing_in_a_step()
  return 1.5 * (k / mass) * substep_length() ^ 2 * swing_force()
end
-- * Single precision: the block's position is a float, rounded by up to 2^-24 of itself each
--   step it moves (the longest slip's steps), and the force reads it, the hand's and their
--   distance, three more roundings; at most the rest length plus the hand's walk from the start.
local function rounding()
  local farthest = rest_length + pull_speed * run_length()
  return k * 2 ^ -24 * farthest * ((run().longest_slip or 0) / substep_length() + 3)
end
-- * Drag (c, b): the listener takes each step's drag off the speed exactly (damped_velocity),
--   and the spring's impulse is added after it: a split of one step into two, each exact, whose
--   error per step is (h²/2)·[spring, drag] acting on the swing. In the swing's energy measure
--   (ω·x, v) that is at most (h/2)·Γ·ω·(ω·X) a second, with Γ = (c + 2b·|v|)/m the drag's rate
--   (b·v·|v| grows by 2b·|v| per m/s) and X the swing's reach; the swing carries an error on
--   without growing it (drag only takes energy out), and the error's source dies out with the
--   swing, e^(-Γt/2), so it adds up over the slip (T) or 2/Γ, whichever is shorter. In force
--   (k·X the swing A): h·ω·A·min(Γ·T/2, 1). With |v| at most the hand's speed plus the swing's
--   fastest, ω·A/k. (414 N/m, 5 kg, b 57, μs 1.83, μk 0.42, 0.02 m/s: the re-stick came 0.17,
--   0.078, 0.038, 0.019 N off at 240, 480, 960, 1920 Hz, halving with the step; this term is
--   1.8 N at 240 Hz. It replaces a flat 2 % of μs·m·g, which was not derived.)
local function drag_allowance()
  if param.c == 0 and param.b == 0 then return 0 end
  local swing = swing_force()
  local omega = math.sqrt(k / mass)
  local drag_rate = (param.c + 2 * param.b * (pull_speed + omega * swing / k)) / mass
  return substep_length() * omega * swing * math.min(drag_rate * (run().longest_slip or 0) / 2, 1)
end
-- The re-stick: the slip starts up to a step's pull late, and the block stops somewhere inside
-- a step and is held from its end while the hand pulls on (two steps' pull); the swing's turn,
-- met at a step; rounding; and drag's share.
local function restick_allowance() return 2 * pull_in_a_step() + swing_in_a_step() + rounding() + drag_allowance() end
-- A stick the world cannot show: the model's block stuck for less than two of the world's steps
-- between a stop and the next breakaway (μs and μk close, a stiff spring, a fast hand: 2.7 ms at
-- μs 2, μk 1.991, 427 N/m, 0.146 m/s). The world's block stops at the end of the step the model's
-- stops in, up to a step late, and breaks away at the end of the step the pull passes μs·N in:
-- a stick shorter than those two steps may fall between them. At 240 Hz it was never seen at
-- 2.7-3.9 ms, seen at 4.2 and 4.5, missed at 4.8 (the stop's place in its step), seen at 5.1 ms
-- and longer; at 480 Hz the 2.7 ms stick was seen.
local function stick_too_brief()
  local shortest = run().shortest_stick
  if shortest and shortest < 2 * step_length() then
    return string.format("sticks %.2g ms: under two steps", 1000 * shortest)
  end
end
-- A stop at the static limit's edge: the model's block stops with the spring's force closer to
-- μs·N than the world's re-stick may be off it (restick_allowance: the pull in a step, the
-- swing's turn met at a step, ...), so whether the world's is held there or slides back on is
-- undecided (500 N/m, 0.1 kg, μs 1.83, μk 0.034: the model's stops 0.067 N inside μs·N, the
-- world's, 0.31 N off it, slid back and stuck at −1.07 N). At μk 0.0026, μs 0.18, 327 N/m,
-- 0.418 kg, 0.02 m/s the model's block stops 0.021 N inside μs·N, where the world's may be
-- 0.07 N off at 240 Hz: the world's slid on and stuck at −0.147 N; from 480 Hz on it stuck at
-- −0.718 N, the model's −0.717 (at 960 Hz, 0.015 N off at most, the rows compare).
local function stops_at_the_edge()
  local restick = run().restick_force
  if restick and param.mu_s * weight - math.abs(restick) < restick_allowance() then
    return string.format("stops %.2g N inside μs·N: within the step's error", param.mu_s * weight - math.abs(restick))
  end
end
-- A slide that dips close to a stop without stopping (a strong drag damping the swing while
-- the hand walks on): the world's speed may be off the model's by ωh/2 of the slide's speed
-- (the term h·ω²·x·v by which Box2D's steps keep a swing's energy), and by a step's drag on it,
-- Γ·h, Γ = (c + 2b·v)/m (each step takes the drag off the speed before the spring's impulse is
-- added), h the world's step. Where the dip comes nearer a stop than that, the world's block
-- may stop there and stick, or not. At 375 N/m, 4.23 kg, μs 2, μk 1.88, b 420: the model's
-- block dips to 0.36 mm/s, where the world's may be 7.9 mm/s off; the world's stuck at 77.8 N.
local function grazes_a_stop()
  local nearest, fastest, h = run().nearest_stop, run().fastest_slide, substep_length()
  local off = (math.sqrt(k / mass) * h / 2 + (param.c + 2 * param.b * fastest) / mass * h) * fastest
  if nearest and nearest < off then
    return string.format("slows to %.2g m/s: within a step's error of stopping", nearest)
  end
end
-- A swing faster than the step: the allowances above are first terms in ω·h, and past ω·h = 1
-- Box2D's steps (stable up to 2) no longer follow the swing (60 Hz, 500 N/m on 0.1 kg, ω·h
-- 1.18: a period of 1.57 s where the model's is 0.40; with a strong drag the world's block stuck
-- every 0.12 s where the model's crept on). The cycle's rows say so; at 240 Hz the sliders'
-- stiffest spring on the lightest block is at 0.29.
local function swing_too_fast()
  local omega_h = math.sqrt(k / mass) * substep_length()
  if omega_h > 1 then return string.format("the spring swings too fast for the step: ω·h = %.3g", omega_h) end
end
-- Where the re-sticks are undecided (mu_k = 0, at the limit's edge, too brief to see, in a
-- dip, or the swing too fast) so are the breakaways after them: that row then reads the first
-- breakaway alone, from both sides.
local function at_the_limit()
  return no_cycle() or swing_too_fast() or (param.mu_k == 0 and "μk = 0: stops at the static limit") or stick_too_brief()
    or stops_at_the_edge() or grazes_a_stop() or nil
end
local function run_over() return reached(run_length()) end

local never_sticks = "never sticks again in the run"
local no_second = "no second breakaway in the run"

expect { "breakaway force", unit = "N",
  predicted = function() return no_cycle() or (at_the_limit() and run().first_breakaway_force) or run().breakaway_force end,
  measured = function()
    return no_cycle() or (at_the_limit() and stick_and_slip().first_breakaway_force) or stick_and_slip().breakaway_force
  end,
  -- The pull grows by k·v·h in a step, and the slip is seen at the end of the step it begins in.
  tolerance = function() return no_cycle() and 0 or pull_in_a_step() + rounding() end }

expect { "re-stick force", unit = "N",
  predicted = function() return at_the_limit() or run().restick_force or never_sticks end,
  measured = function()
    if at_the_limit() then return at_the_limit() end
    local seen = stick_and_slip().restick_force
    -- Where theory says it never sticks, a re-stick in the world is told in words, to differ.
    if seen and not run().restick_force then return string.format("sticks again at %.3g N", seen) end
    return seen or (run_over() and never_sticks) or nil
  end,
  -- restick_allowance (above). With a stiff spring on a light block (151.7 N/m, 0.1 kg, μs 1.09, μk
  -- 0.289, 0.02 m/s: tolerance 0.056 N at 240 Hz) the re-stick came 0.026 N off at 240 Hz,
  -- 0.0099 at 480, 0.0010 at 960, 0.00023 at 1920.
  tolerance = function() return restick_allowance() end }

-- How the block moves once it has broken away, as the class sees it: in jerks (it stops, the
-- spring stretches again, it lurches: stick-slip) or steadily after the hand. Theory: in jerks
-- when the model's block breaks away a second time in the run. Measured: in jerks once it has
-- stuck again and broken away a second time; steadily if the whole run passed without that.
-- Where the other rows have no answer to check (mu_k >= mu_s, mu_k = 0), this one says the same
-- in words from both sides.
expect { "steadily or in jerks",
  predicted = function() return at_the_limit() or (run().breakaways > 1 and "in jerks" or "steadily") end,
  measured = function()
    if at_the_limit() then return at_the_limit() end
    if stick_and_slip().period then return "in jerks" end
    if run_over() then return "steadily" end
  end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "breakaway force", unit = "N",
  question = "The spring pulls harder and harder. How hard is it pulling when the block starts to move?" }
predict { "steadily or in jerks", choices = { "steadily", "in jerks" },
  question = "Once the block starts to move, does it follow the hand steadily or in jerks?" }

expect { "stick-slip period", unit = "s",
  predicted = function() return at_the_limit() or run().period or no_second end,
  measured = function()
    if at_the_limit() then return at_the_limit() end
    local seen = stick_and_slip().period
    if seen and not run().period then return string.format("breaks away again after %.3g s", seen) end
    return seen or (run_over() and no_second) or nil
  end,
  -- The block sticks where a re-stick leaves it, and breaks away when the hand has walked μs·N/k
  -- ahead of it: a block stuck a distance d off the model's breaks away d/v off it in time, and
  -- d is the re-stick force's error over k. Over a run that error is the re-sticks' mean; and
  -- the first and last breakaways are each seen at the end of their steps, up to h apart.
  tolerance = function()
    if at_the_limit() or not run().period then return 0 end
    return restick_allowance() / (k * pull_speed) + step_length()
  end }
