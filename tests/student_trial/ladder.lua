-- A student's trial (issue 29): a ladder against a wall, written from lessons/README.md and a
-- textbook alone. A uniform ladder of length L leans at θ to the floor against a frictionless
-- wall; the floor's friction holds it while f = N_wall <= mu_s·m·g. Moments about its centre,
-- with its floor and wall contacts at its lower corners (it is w thick), give
--   tan θ >= 1 / (2·mu_s + w / L),
-- the thin ladder's tan θ = 1 / (2·mu_s) when w = 0.
lesson { title = "A ladder against a wall", question = "How low can the ladder lean before it slides?", duration = 2 }

local angle = parameter { "angle", 50, min = 30, max = 80, unit = "°", text = "the ladder's angle to the floor" }
local length, thickness = 4, 0.04
local mu_s = 0.5

material { "ladder", density = 50 }
material { "floor", density = 500 }
material { "wall", density = 500 }
pair { "ladder", "floor", mu_s = mu_s, mu_k = mu_s, sliders = false }
pair { "ladder", "wall", mu_s = 0, mu_k = 0, sliders = false }

ground { material = "floor" }
-- The wall's face is x = 0; the ladder leans on it from the right.
box { "wall", material = "wall", kind = "static", width = 0.2, height = 5, x = -0.1, y = 2.5 }
-- Its lower corners touch: the one at its foot the floor (y = 0), the one at its top the wall
-- (x = 0). Turned by 180° − θ, the ladder's length runs up to the left.
local t = math.rad(angle)
box { "ladder", material = "ladder", width = length, height = thickness, mass = 10, angle = 180 - angle,
      x = length / 2 * math.cos(t) + thickness / 2 * math.sin(t),
      y = length / 2 * math.sin(t) + thickness / 2 * math.cos(t) }

-- The textbook's angle, below which it slides.
probe { "sliding_angle", unit = "°", function() return math.deg(math.atan(1 / (2 * mu_s + thickness / length))) end }
