-- tipping_box: a box pushed on its side, harder and harder, at a chosen height.
-- The tribology article: pushed at height h, a box of width d tips over its front edge
-- before it slides when h >= d / (2·mu_s), however hard the push; pushed lower, it slides.

lesson {
  title = "Push a box: does it tip or slide?",
  question = "Push a box harder and harder: at which height does it tip over instead of sliding, and at what push?",
  -- Until a second after theory says something happens.
  duration = function()
    local outcome = theory.push_outcome { mass = param.mass, width = param.width, push_height = param.push_height,
                                          mu_s = param.mu_s }
    return outcome.force / param.push_rate + 1
  end,
}

-- Parameters ------------------------------------------------------------------------------
local push_height = parameter { "push_height", 0.7, min = 0.05, max = 2, unit = "m",
                                text = "height of the push above the floor" }
local push_rate = parameter { "push_rate", 20, min = 1, max = 200, unit = "N/s", text = "how fast the push grows" }
local width = parameter { "width", 0.5, min = 0.1, max = 2, unit = "m", text = "width of the box (d)" }
local height = parameter { "height", 1.0, min = 0.1, max = 2, unit = "m", text = "height of the box" }
local mass = parameter { "mass", 10, min = 1, max = 100, unit = "kg", text = "mass of the box" }
if push_height > height then
  error(string.format("push_height (%g m) must not be above the top of the box (height %g m)", push_height, height))
end

material { "crate", density = 40, note = "the mass is set on the box itself" }
material { "floor", density = 2000, note = "fixed, so its density plays no part" }
pair { "crate", "floor", mu_s = 0.5, mu_k = 0.4 }

-- World -----------------------------------------------------------------------------------
local floor = ground { material = "floor" }
local crate = box { "box", material = "crate", width = width, height = height, on = floor, at = 0, mass = mass }

-- The push acts on the left side, push_height above the plane the box stands on. Box2D keeps
-- resting boxes resting_gap apart and puts the contact midway, so that plane lies half the
-- gap below the box's face.
local push = force { "push", on = crate, at = { -width / 2, push_height - height / 2 - resting_gap / 2 },
                     force = function(t) return push_rate * t, 0 end }

-- Sliding is measured at the front bottom corner: it stays put while the box tips about it.
local corner_x = crate:world_point(width / 2, -height / 2)

-- Probes and plots ------------------------------------------------------------------------
local touch = contact(crate, floor)
probe { "push", unit = "N", read = { push, "fx" } }
probe { "tilt", unit = "°", function() return -crate.angle end }  -- pushed to the right, it tips clockwise
probe { "slide", unit = "m", function() return (crate:world_point(width / 2, -height / 2)) - corner_x end }
probe { "friction_force", unit = "N", read = { touch, "friction" } }

plot { "What the box does", y = { "tilt" } }
plot { "Friction against the push", x = "push", y = { "friction_force" } }

-- Watching for the first thing to happen ------------------------------------------------
-- It slides when the contact starts slipping; it tips when the back edge stops carrying any
-- of the weight (or nothing touches the floor any more).
local outcome, outcome_push
every_step(function(t)
  if outcome then return end
  if touch.state == "none" then
    outcome = "tips"
  elseif touch.state == "slipping" then
    outcome = "slides"
  elseif touch.points < 2 or math.min(touch.load1, touch.load2) < 0.001 * (touch.load1 + touch.load2) then
    outcome = "tips"
  else
    return
  end
  outcome_push = push_rate * (t - step_length())  -- the push during the step it happened in
end)

-- Expectations ----------------------------------------------------------------------------
local function predicted()
  return theory.push_outcome { mass = mass, width = width, push_height = push_height, mu_s = param.mu_s }
end

expect { "tips or slides", predicted = function() return predicted().outcome end, measured = function() return outcome end }

expect { "push when it happens", unit = "N",
  predicted = function() return predicted().force end,
  measured = function() return outcome_push end,
  tolerance = function() return 0.005 * predicted().force end }
