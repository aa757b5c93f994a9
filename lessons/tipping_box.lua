-- tipping_box: a box pushed on its side, harder and harder, at a chosen height.
-- The tribology article: pushed at height h, a box of width d tips over its front edge
-- before it slides when h >= d / (2·mu_s), however hard the push; pushed lower, it slides.

-- The box's angular acceleration about its front bottom corner, tipped by theta (rad) under
-- `push` (as a rigid box on a corner that holds, never turned back past flat):
-- I·θ'' = F·(d·sin θ + h·cos θ) − m·g·(d/2·cos θ − H/2·sin θ), with h the push's height and
-- I = m·(d² + H²)/3 about the corner.
local function tipping_spin_rate(push, theta)
  local m, d, h, H, g = param.mass, param.width, param.push_height, param.height, 9.81
  local turning = push * (d * math.sin(theta) + h * math.cos(theta)) - m * g * (d / 2 * math.cos(theta) - H / 2 * math.sin(theta))
  return math.max(turning, 0) / (m * (d * d + H * H) / 3)
end
-- How long after the tipping starts the box has tipped by `angle` (rad): that turn, the push
-- still growing, integrated in small steps.
local function time_to_tip(tip_time, angle)
  local theta, spin, t, step = 0, 0, tip_time, 1e-3
  while theta < angle and t < tip_time + 3 do
    spin = spin + tipping_spin_rate(param.push_rate * t, theta) * step
    theta = theta + spin * step
    t = t + step
  end
  return t - tip_time
end

lesson {
  title = "Push a box: does it tip or slide?",
  question = "Push a box harder and harder: at which height does it tip over instead of sliding, and at what push?",
  -- A box that slides: until a second after it breaks away. A box that tips: until it has
  -- tipped by 20°, clearly over, while its corner is still on the floor; a second more and the
  -- growing push threw it into the air, which a class took for a fault (the teacher's trial).
  -- And never before the world can show it: the rows allow the push to be read up to two steps
  -- late, at the end of a step, so three steps past the push that starts it (a 0.1 m box pushed
  -- 2 m up at 130.6 N/s tips at 0.25 N, 2 ms in: at 30 Hz the run had ended after its first
  -- step, "not measured").
  duration = function()
    local outcome = theory.push_outcome { mass = param.mass, width = param.width, push_height = param.push_height,
                                          mu_s = math.max(param.mu_s, param.mu_k) }
    local starts = outcome.force / param.push_rate
    local shown = starts + 3 * step_length()
    if outcome.outcome == "slides" then return math.max(starts + 1, shown) end
    return math.max(starts + time_to_tip(starts, math.rad(20)), shown)
  end,
  order = 30,
  -- Pushed below width/(2·mu_s) = 0.5 m it slides upright; above, it tips about its front edge.
  moments = {
    { "pushed_low", at = 3, set = { push_height = 0.2 },
      shows = function() return value_at("slipping", time()) == 1 and math.abs(value_at("tilt", time())) < 0.5 end },
    { "pushed_high", at = 2.2, readme = true, shows = function() return value_at("tilt", time()) > 1.7 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local push_height = parameter { "push_height", 0.7, min = 0.05, max = 2, unit = "m",
                                text = "height of the push above the floor" }
local push_rate = parameter { "push_rate", 20, min = 1, max = 200, unit = "N/s", text = "how fast the push grows" }
local width = parameter { "width", 0.5, min = 0.1, max = 2, unit = "m", text = "width of the box (d)" }
local height = parameter { "height", 1.0, min = 0.1, max = 2, unit = "m", text = "height of the box" }
local mass = parameter { "mass", 10, min = 1, max = 100, unit = "kg", text = "mass of the box" }

material { "crate", density = 40, note = "the mass is set on the box itself" }
material { "floor", density = 2000, note = "fixed, so its density plays no part" }
pair { "crate", "floor", mu_s = 0.5, mu_k = 0.4 }

-- World -----------------------------------------------------------------------------------
local floor = ground { material = "floor" }
local crate = box { "box", material = "crate", width = width, height = height, on = floor, at = 0, mass = mass }

-- The push acts on the left side, push_height above the plane the box stands on; set above the
-- box's top (the sliders allow it), it acts through a rigid handle fixed to the box's side, and
-- theory's d/(2·mu_s) holds all the same. The box stands on its bottom face, so that plane is
-- the face itself.
-- The hand pushes while the box leans less than its balance angle, atan(width/height): past it
-- the box falls over by itself, away from the hand. (A push still growing at that point of the
-- fallen box dragged it along the floor by what had been its side: played on past the run's end,
-- a teacher saw a 69.9 N arrow pointing away from the box, like a pull.) The tilt is the last
-- step's, as recorded.
local balance_angle = math.deg(math.atan(width / height))
local push = force { "push", on = crate, at = { -width / 2, push_height - height / 2 },
                     force = function(t)
                       local tilts = history("tilt")
                       if #tilts > 0 and math.abs(tilts[#tilts]) >= balance_angle then return 0, 0 end
                       return push_rate * t, 0
                     end }

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(crate, floor)
local front_corner = { width / 2, -height / 2 }
probe { "push", unit = "N", read = { push, "fx" } }
-- Pushed to the right, it tips clockwise, which is a negative angle.
probe { "tilt", unit = "°", read = { crate, "angle", scale = -1 } }
-- Sliding is measured at the front bottom corner: it stays put while the box tips about it.
probe { "slide", unit = "m", read = { crate, "distance", at = front_corner, along = { 1, 0 } } }
-- The floor's friction on the box along x, as in every lesson: pushed to the right, it points
-- left, so it reads negative (lessons/README.md, "Which way friction counts").
probe { "friction_force", unit = "N", read = { touch, "fx" } }
-- The floor's push on the back and front edges: the box tips when the back one lets go.
probe { "back_load", unit = "N", read = { touch, "load_left" } }
probe { "front_load", unit = "N", read = { touch, "load_right" } }
probe { "slipping", read = { touch, "slipping" } }
probe { "contact_points", read = { touch, "points" } }

-- The key plot first (the first page in projector mode): friction answers the push until the box
-- tips or slides, whichever push comes first, and its first two levels are those pushes (negative,
-- as friction is here); the third is the kinetic friction a sliding box's trace then sits on (a
-- teacher's trial found that line of a low push unlabelled). The box slides at the most static friction gives, max(mu_s, mu_k)·N as the
-- solver's rule has it (see predicted() below); it tips when the push's moment about the front
-- edge, F·h, passes the weight's, m·g·d/2. The level says it in the sliders' words, "width" and
-- "push height": a class read an h beside the slider "height", which is the box's. On two lines,
-- so that it keeps to the column beside a projector's key plot as "−m·g·d/(2h)" did.
plot { "Friction against the push", x = "push", y = { "friction_force" },
  levels = {
    { "slides: −μs·N", function() return -math.max(param.mu_s, param.mu_k) * param.mass * g end },
    { "tips: −m·g·width\n/(2·push height)", function() return -param.mass * g * param.width / (2 * param.push_height) end },
    { "kinetic: −μk·N", function() return -param.mu_k * param.mass * g end },
  } }
plot { "How far the box tips", y = { "tilt" } }
plot { "How far the box slides", y = { "slide" } }
plot { "The floor's push on each edge", x = "push", y = { "back_load", "front_load" } }

-- Reading the record ----------------------------------------------------------------------
-- The first thing to happen: it slides when the contact starts slipping; it tips when the back
-- edge stops carrying any of the weight (or nothing touches the floor any more). The push that
-- did it is the one during that step. Box2D solves a face's two points together and lets a
-- point go with no load but its sums' round-off, so "none" is a ten-thousandth of the load
-- here, not a share of the weight: by statics the back edge carries N/2 − F·h/d, and a
-- threshold of 0.1 % of N (which this was) fires at (1 − 0.002)·m·g·d/(2·h), 0.2 % of the push
-- before the tipping push the row predicts; 10⁻⁴ of N fires 0.02 % before it, well within the
-- row's 0.5 % for the solver. Exactly 0 was a step late for a tall narrow box (0.108 m by
-- 2 m) pushed 1 % past tipping: its back edge kept 0.0008 N of 60.6, 1.3·10⁻⁵ of the load.
-- Only the back edge: a push to the right tips the box over its front one. The front edge may
-- let go for a frame as the box breaks away under sub-steps (69 kg, mu 2, c = 1000 N·s/m,
-- pushed 5 cm up, 2 sub-steps: all 898 N on the back edge, the box rocked 0.009° back), which
-- read as tipping where it slid.
local function first_outcome()
  local times, points, slipping = history("time"), history("contact_points"), history("slipping")
  local back, front = history("back_load"), history("front_load")
  for i = 1, #times do
    local outcome
    if points[i] == 0 then
      outcome = "tips"
    elseif slipping[i] == 1 then
      outcome = "slides"
    elseif points[i] < 2 or back[i] <= 1e-4 * (back[i] + front[i]) then
      outcome = "tips"
    end
    if outcome then return outcome, push_rate * (times[i] - step_length()) end
  end
end

-- Expectations ----------------------------------------------------------------------------
-- A box at rest breaks away once the push passes max(mu_s, mu_k)·N, as the solver's rule has
-- it: with mu_k above mu_s, kinetic friction would stop a box pushed just past mu_s·N at once.
-- Until then nothing moves, so the statics are exact however fast the push grows; drag (c, b)
-- acts only on sliding, after the row's moment.
local function predicted()
  return theory.push_outcome { mass = mass, width = width, push_height = push_height,
                               mu_s = math.max(param.mu_s, param.mu_k) }
end

-- The record tells the step it happened in, and the push during that step, which grows by
-- push_rate·h a step: up to that much off the exact push, and 0.5 % for the solver. And a step
-- more where the box must tip within the push's first two steps: a fresh contact, its load
-- moved from nothing to past tipping in one step, 0.7 % past it, still left the back edge 0.40 N
-- of its 4.9 (a light narrow box at 141 N/s; at 1.3 to 60 N/s the first step past the tipping
-- push is the one recorded).
local function push_tolerance()
  local steps = predicted().force < 2 * push_rate * step_length() and 2 or 1
  return 0.005 * predicted().force + steps * push_rate * step_length()
end
-- Where the push that tips the box and the push that slides it lie within that of each other
-- (h within as much of d/(2·mu_s)), the record cannot tell which came first: the step both
-- happen in shows the two at once, and the solver's last parts in a thousand pick which it
-- reports first (d = 2 m, h = 1.455 m, mu_s 0.6873: both at 6.742 N, the box slid in the step
-- its back edge let go). Theory then says it is a tie; so does the record where the world's
-- first outcome came at that push (within the same tolerance).
-- A box that tips turns about its front corner, and the floor must give that corner the
-- friction that turns its centre: f = m·a_x − F along the floor, and N = m·(g + a_y) across it.
-- Pushed high on a small box, the push's moment soon outgrows the weight's and the turn gets
-- fast, and the corner slides back once |f| passes mu·N: a 0.1 m box of 1 kg pushed 1.531 m up
-- at 59.67 N/s, mu_s 0.107, tips at 0.32 N and its corner slides at 0.47 N, 2.5 ms on, both
-- inside the 240 Hz step whose push, 0.50 N, first passes the tipping push, and the world
-- reported the slide. The push at which the corner slides: the turn of tipping_spin_rate, with the
-- centre's acceleration from it (nil: the corner holds until the push has grown by `within`).
local function corner_slides_at(within)
  local m, d, H, g = param.mass, param.width, param.height, 9.81
  local mu, tips = math.max(param.mu_s, param.mu_k), predicted().force
  local step = math.min(1e-5, within / push_rate / 1000)
  local theta, spin, t = 0, 0, tips / push_rate
  while push_rate * t <= tips + within do
    local push = push_rate * t
    local spin_rate = tipping_spin_rate(push, theta)
    -- The centre from the corner, turned by theta, and its acceleration in that turn.
    local x = -d / 2 * math.cos(theta) + H / 2 * math.sin(theta)
    local y = d / 2 * math.sin(theta) + H / 2 * math.cos(theta)
    local friction = m * (spin_rate * y - spin * spin * x) - push
    local normal_force = m * (g - spin_rate * x - spin * spin * y)
    if normal_force <= 0 or math.abs(friction) > mu * normal_force then return push end
    spin = spin + spin_rate * step
    theta = theta + spin * step
    t = t + step
  end
end
local tie = "a tie: tips and slides within a step"
local function is_tie()
  local mu, force = math.max(param.mu_s, param.mu_k), predicted().force
  if mu == 0 then return false end  -- frictionless: it slides at the first push
  local ratio = width / (2 * push_height * mu)  -- the tipping push over the sliding push
  local other = predicted().outcome == "tips" and force / ratio or force * ratio
  if math.abs(other - force) <= push_tolerance() then return true end
  return predicted().outcome == "tips" and corner_slides_at(push_tolerance()) ~= nil
end

expect { "tips or slides",
  predicted = function() return is_tie() and tie or predicted().outcome end,
  measured = function()
    local outcome, push_then = first_outcome()
    if outcome and is_tie() and math.abs(push_then - predicted().force) <= push_tolerance() then return tie end
    return outcome
  end }

expect { "push when it happens", unit = "N",
  predicted = function() return predicted().force end,
  measured = function()
    local _, push_then = first_outcome()
    return push_then
  end,
  tolerance = push_tolerance }

-- Predictions: the class says what it expects before Play; theory stays hidden until revealed.
predict { "tips or slides", choices = { "tips", "slides" },
  question = "Pushed at this height, does the box tip over or slide along the floor?" }
predict { "push when it happens", unit = "N",
  question = "How hard is the push when the box starts to tip or slide?" }
