-- A student's trial (issue 29): a disk released on an incline, written from lessons/README.md
-- and a textbook alone. Rolling, a solid disk (I = m·r²/2) needs friction f = m·g·sin θ / 3;
-- the slope gives at most mu_s·m·g·cos θ, so it rolls without slipping while tan θ <= 3·mu_s.
lesson { title = "A disk rolling down a slope", question = "How steep can the slope be before the disk slips?",
         duration = 1 }

local angle = parameter { "angle", 30, min = 5, max = 70, unit = "°", text = "the slope's angle" }
local radius = 0.1
local mu_s = 0.3

material { "disk", density = 100 }
material { "slope", density = 500 }
pair { "disk", "slope", mu_s = mu_s, mu_k = mu_s, sliders = false }

ground { material = "slope" }
local slope = incline { "slope", material = "slope", angle = angle, length = 8 }
local disk = circle { "disk", material = "disk", radius = radius, on = slope, at = 7, mass = 1 }

-- How fast its rim slides over the slope: its speed less its spin times its radius.
probe { "slip", unit = "m/s", function() return math.sqrt(disk.vx ^ 2 + disk.vy ^ 2) - math.abs(disk.omega) * radius end }
-- The textbook's angle, above which it slips.
probe { "slipping_angle", unit = "°", function() return math.deg(math.atan(3 * mu_s)) end }
