-- push: a block on a table pushed harder and harder, as the tribology article pushes its book
-- (and as a force-sensor lab does). Static friction answers the push exactly, f = −F, until the
-- push reaches mu_s·N; then the block breaks away, friction drops to mu_k·N, and the push,
-- still growing, speeds the block up: a = (F − mu_k·N)/m.

-- What theory says at time t, with the sliders as they are now.
local function push_theory(t)
  return theory.growing_push { mass = param.mass, rate = param.push_rate, mu_s = param.mu_s, mu_k = param.mu_k,
                               c = param.c, b = param.b, t = t }
end

lesson {
  title = "Push a block harder and harder",
  question = "How hard must you push before the block moves, and what does friction do once it moves?",
  -- A second and a half of sliding after theory says it breaks away, whatever the sliders say.
  duration = function() return push_theory(0).breakaway_time + 1.5 end,
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
-- The block broke away in the first step that ends with the contact slipping; the push that
-- did it is the one recorded the step before (none before the first step).
local function breakaway_push()
  local slipping, pushes = history("slipping"), history("push")
  for i = 1, #slipping do
    if slipping[i] == 1 then return i > 1 and pushes[i - 1] or 0 end
  end
end

-- The end of the run at the sliders' values, where the last two rows are read.
local function ending() return push_theory(0).breakaway_time + 1.5 end
local function at_the_end(probe)
  return reached(ending()) and value_at(probe, ending()) or nil
end

-- Expectations ----------------------------------------------------------------------------
expect { "breakaway push", unit = "N",
  predicted = function() return push_theory(0).breakaway_push end,
  measured = breakaway_push,
  -- The push grows by rate·h in a step, and the slip is seen at the end of the step it begins in.
  -- (On a smooth table that is the second step, the first with a push: the recorded push is then
  -- rate·h exactly, read from Box2D's float force, so a float's rounding, 2^-24 of it, is let
  -- in too.)
  tolerance = function() return (0.01 * push_theory(0).breakaway_push + push_rate * step_length()) * (1 + 2 ^ -23) end }

-- Where the run cannot show the end theory describes, the last two rows say so: the block has
-- slid off the table's end (200 m from where it stood, less its half width), or it moves more
-- than Box2D lets a body move in one step (b2_maxTranslation, 2 m), which caps its speed.
local function out_of_reach()
  local final = push_theory(ending())
  if final.distance > 200 - 0.15 then return "off the table's end before the run ends" end
  if final.speed * step_length() > 2 then return "faster than Box2D's 2 m a step" end
end

-- The drag's step term. The drag is taken off before each step and the push's impulse added
-- after it, so each step's push escapes that step's drag: the step is forward Euler with the
-- drag's rate Γ = f'(v)/m (f = c·v + b·v²) replaced by (1 − e^(−Γh))/h, and the speed the drag
-- holds the block to runs high by (f/f')·(q − 1), q = Γh/(1 − e^(−Γh)) ≈ 1 + Γh/2 (at c = 10,
-- mass 0.1: Γh = 0.42, 22 %). Past Γh = 1 that is over half the drag's share of the speed:
-- the row then says the step is too long rather than compare.
local function drag_step()
  local v = push_theory(ending()).speed
  local gamma_h = (param.c + 2 * param.b * v) / mass * step_length()
  if gamma_h == 0 then return 0, 0 end
  local share = (param.c * v + param.b * v * v) / (param.c + 2 * param.b * v)  -- f/f'
  return share * (gamma_h / (1 - math.exp(-gamma_h)) - 1), gamma_h
end
local function step_too_long()
  local _, gamma_h = drag_step()
  if gamma_h > 1 then return string.format("step too long for this drag: Γ·h = %.3g > 1", gamma_h) end
end

-- Friction includes the drag c·v + b·v² when a slider sets them: the table's whole answer.
expect { "friction at the end", unit = "N",
  -- Signed as the probe is (to the right positive): theory's size, pointing back.
  predicted = function() return out_of_reach() or -push_theory(ending()).friction end,
  measured = function()
    if out_of_reach() then return out_of_reach() end
    return at_the_end("friction_force")
  end,
  -- 1 %, 1 mN, and the drag's two step terms: the contact reads the mean over the step just
  -- taken, half a step before the end, while the drag grows at f'(v)·v'; and it drags the
  -- speed the drag step term above puts on the block, f'(v) times that.
  tolerance = function()
    local final = push_theory(ending())
    local slope = param.c + 2 * param.b * final.speed  -- f'(v)
    return 0.01 * final.friction + 1e-3 + slope * (math.abs(final.acceleration) * step_length() / 2 + drag_step())
  end }

-- Whether friction, once the block slides, is smaller than the push that broke it away, the same,
-- or larger: the two rows above set side by side, as a class compares them. Within about the
-- two rows' tolerances together (2 % of the push, its growth in a step, 1 mN) they are the same. At the defaults kinetic friction is a quarter
-- below static (mu_k·N against mu_s·N): smaller. A strong drag can make it larger by the end.
local function compared(friction, breakaway, band)
  if math.abs(friction - breakaway) <= band then return "the same" end
  return friction < breakaway and "smaller" or "larger"
end
local function same_band()
  return 0.02 * push_theory(0).breakaway_push + push_rate * step_length() + 1e-3
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
    return out_of_reach() or step_too_long()
      or compared(push_theory(ending()).friction, push_theory(0).breakaway_push, same_band())
  end,
  measured = function()
    if out_of_reach() or step_too_long() then return out_of_reach() or step_too_long() end
    local f, breakaway = sliding_friction(), breakaway_push()
    if f == nil or breakaway == nil then return nil end
    return compared(-f, breakaway, same_band())
  end }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "breakaway push", unit = "N",
  question = "The push grows steadily. How hard is it when the block starts to move?" }
predict { "sliding vs breakaway", choices = { "smaller", "the same", "larger" },
  question = "Once it slides, is friction smaller than the push that started it, the same, or larger?" }

expect { "speed at the end", unit = "m/s",
  predicted = function() return out_of_reach() or step_too_long() or push_theory(ending()).speed end,
  measured = function() return out_of_reach() or step_too_long() or at_the_end("speed") end,
  -- 1 %, 1 cm/s for the push sampled at the start of each step, and the drag's step term.
  tolerance = function() return 0.01 * push_theory(ending()).speed + 0.01 + drag_step() end }
