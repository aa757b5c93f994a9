-- pulley: connected masses, from the friction-situations article. A block on a table is tied by
-- a rope over a pulley at the table's edge to a weight that hangs beside it. The rope makes
-- the two one body along it, of mass m_b + m_h, pulled by the weight's m_h·g and held back by
-- the table's friction on the block alone, whose normal force is m_b·g (the weight touches
-- nothing). So the block stays put while m_h <= mu_s·m_b (max(mu_s, mu_k)·m_b if a slider puts
-- mu_k above mu_s: pulled past mu_s·N it would at once be held back by mu_k·N), and otherwise
-- both move with a = g·(m_h − mu_k·m_b)/(m_b + m_h). The rope pulls each of them with the same
-- T = m_h·(g − a): less than the weight's m_h·g, since the weight speeds up, and more than the
-- table's mu_k·m_b·g, since the block speeds up too.

local function pulley_theory()
  return theory.connected_masses { block_mass = param.block_mass, hanging_mass = param.hanging_mass,
                                   mu_s = param.mu_s, mu_k = param.mu_k }
end
-- Theory holds the block at equality too: static friction can give all of mu_s·N. So does the
-- solver: a stuck contact pushed a hair past its limit while Box2D's iterations catch up with
-- the rope is watched for a step or two and stays stuck if the excess dies away (see
-- physics/treatment_stick_slip.cpp).

-- The block may slide 0.22 m before the weight reaches the floor: the run ends before that,
-- or after 2 s.
local travel = 0.22
local function run_length()
  local a = pulley_theory().acceleration
  return a > 0 and math.min(2, math.sqrt(2 * travel / a)) or 2
end

lesson {
  title = "A block pulled by a hanging weight",
  question = "How heavy must the hanging weight be to drag the block, and does the rope pull with the weight's whole weight?",
  duration = run_length,
  order = 13,
  moments = {
    -- At the run's end (2 s, held), where every row has been measured.
    { "held", at = 2, set = { hanging_mass = 0.3 },
      shows = function() return value_at("slipping", time()) == 0 and math.abs(value_at("speed", time())) < 1e-3 end },
    { "sliding", at = 0.6, readme = true, shows = function() return value_at("slipping", time()) == 1 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local block_mass = parameter { "block_mass", 1, min = 0.1, max = 10, unit = "kg", text = "mass of the block on the table" }
local hanging_mass = parameter { "hanging_mass", 0.45, min = 0.01, max = 10, unit = "kg", text = "mass of the hanging weight" }

-- Wood on wood, from the tribology article's 0.25 to 0.50; only mu_s and mu_k as sliders.
pair { "wood", "wood", mu_s = 0.4, mu_k = 0.3, sliders = { "mu_s", "mu_k" } }
material { "iron", density = 7870 }
pair { "wood", "iron", mu_s = 0.5, mu_k = 0.4, sliders = false }  -- the weight never touches the table

-- World -----------------------------------------------------------------------------------
local floor = ground { "floor", material = "wood" }
local table_top = box { "table", material = "wood", kind = "static", width = 1.2, height = 0.5, x = 0, y = 0.25 }
-- Four times as wide as it is tall, it cannot tip over its front edge for any mu up to 2 (the
-- rope pulls at its middle, friction at its base).
local block = box { "block", material = "wood", width = 0.4, height = 0.1, on = table_top, at = -0.25, mass = block_mass }
-- The pulley sits just past the table's edge at the height of the block's middle, so the rope
-- runs level to the block and straight down to the weight.
local pulley_at = { 0.75, block.y }
local weight = box { "weight", material = "iron", width = 0.2, height = 0.2, x = 0.75, y = block.y - 0.2,
                     mass = hanging_mass }
-- The table's top, the pulley and the weight's whole fall, from the floor up.
view { window = { -0.62, -0.02, 0.88, 0.7 } }
local cord = rope { "rope", from = block, at = { 0.2, 0 }, over = pulley_at, to = weight, to_at = { 0, 0.1 } }

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(block, table_top)
probe { "acceleration", unit = "m/s²", read = { block, "acceleration", along = { 1, 0 } } }
probe { "tension", unit = "N", read = { cord, "tension" } }
probe { "friction_force", unit = "N", read = { touch, "fx" } }  -- negative: it holds the block back
probe { "speed", unit = "m/s", read = { block, "vx" } }
probe { "slipping", read = { touch, "slipping" } }  -- 1 while the block slides

plot { "Rope and table on the block", kind = "time", y = { "tension", "friction_force" },
  theory = { { "weight of the hanging mass M: M·g", function() return param.hanging_mass * g end } } }
-- The speed rather than the acceleration: a straight line whose slope is the acceleration
-- reads better than a flat trace, and at rest it is 0 without the solver's 10⁻⁴ m/s² of noise.
-- The law holds while the weight hangs: it ends where the weight lands, its foot (half its
-- 0.2 m height below its centre) come down to the floor (a render past the run's end shows the
-- block sliding on without the rope).
local fall = weight.y - 0.1
plot { "Speed of the block", kind = "time", y = { "speed" },
  theory = { { "a·t, a = g·(M − μk·m)/(m + M), m the block's mass", function(t)
    local a = pulley_theory().acceleration
    if a > 0 and t > math.sqrt(2 * fall / a) then return nil end
    return a * t
  end } } }

-- Reading the record ----------------------------------------------------------------------
local function at_the_end(probe)
  return reached(run_length()) and value_at(probe, run_length()) or nil
end
local function ever_slipped()
  for _, slipping in ipairs(history("slipping")) do
    if slipping == 1 then return true end
  end
  return false
end

-- Expectations ----------------------------------------------------------------------------
-- What the rows allow (issue 29: derived, not a flat share). Every row is read at the run's
-- end, long after the start, and by then the stepped world holds theory's answer exactly:
-- * The step: none. The acceleration is constant, and the probe's (the change of the block's
--   velocity over the last step, over h) is exact for a constant acceleration, at any h; the
--   rope's tension and the table's friction are the step's mean, constant too. The breakaway
--   (held at mu_s·N for its step, then given back the speed mu_k would have left) changes
--   where the block is, which no row reads, and not its speed after.
-- * The solver: none. Sliding, the friction is clamped at mu_k times the normal impulse, which
--   on a level table is the block's weight alone; with friction fixed the rope is one
--   constraint between two bodies, met in one turn, and warm starting carries its impulse on.
--   Held, the contact and the rope are solved together and converge from step to step: by the
--   run's end (2 s) nothing of the start is left (the largest seen: 3e-6 N on a 10 kg block
--   at 480 Hz, which the rounding below allows).
-- * Single precision: Box2D keeps velocities and impulses as floats, and every operation on
--   them rounds by up to 2^-24 of the magnitudes involved (theory itself is double). In a
--   step the block's velocity is changed by gravity's integration and by each constraint on it
--   (the two contact points' friction, the normal's block solve, the rope) in the warm start
--   and in each of Box2D's 8 velocity iterations, (1 + 8)·4 + 1 = 37 operations, and its
--   mass and g were rounded once each. The reading differences two velocities a step apart, so only
--   its last step's rounding is left in it: 37·2^-24 of the velocity (and of the step's change
--   g·h), over h; with --substeps, each sub-step's. A force reads an impulse over h: its error
--   is the masses' times that, which holds 2^-24 of both weights per operation too.
local operations = (1 + 8) * 4 + 1 + 2
local function rounding()
  local h, speed = step_length(), math.abs(pulley_theory().acceleration) * run_length()
  local substeps = math.floor(step_length() / substep_length() + 0.5)
  local acceleration = substeps * operations * 2 ^ -24 * (speed / h + g)
  return { acceleration = acceleration, force = (param.block_mass + param.hanging_mass) * acceleration }
end

expect { "the block",
  predicted = function() return pulley_theory().slides and "slides" or "stays put" end,
  -- Slid as soon as it slips; stayed put only once the run is over (before Play: not yet).
  measured = function()
    if ever_slipped() then return "slides" end
    return reached(run_length()) and "stays put" or nil
  end }
expect { "acceleration", unit = "m/s²",
  predicted = function() return pulley_theory().acceleration end,
  measured = function() return at_the_end("acceleration") end,
  tolerance = function() return rounding().acceleration end }
expect { "rope tension", unit = "N",
  predicted = function() return pulley_theory().tension end,
  measured = function() return at_the_end("tension") end,
  tolerance = function() return rounding().force end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "the block", choices = { "slides", "stays put" },
  question = "Let the weight hang: does it drag the block along the table, or does the block stay put?" }
predict { "rope tension", unit = "N",
  question = "How hard does the rope pull on the block: the hanging weight's whole weight, or less?" }
expect { "friction on the block", unit = "N",
  -- Signed as the probe is (to the right, towards the pulley, positive): theory's size, pointing back.
  predicted = function() return -pulley_theory().friction end,
  measured = function() return at_the_end("friction_force") end,
  tolerance = function() return rounding().force end }
