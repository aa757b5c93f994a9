-- thrown_box: the tribology article's thrown box. "If you throw a box across the room, once it
-- hits the floor it will tumble all over the place instead of simply sliding to a halt." Thrown
-- spinning, the box lands on a corner; friction grips that corner (or drags it) and the impact
-- turns the box over it. Beside it the same throw with its rotation locked, as a game without
-- rotation shows it: it lands flat and slides to a halt. The impact on the corner follows from
-- m·Δv = J and I·Δω = r × J, with the corner either stopped within the impact (it grips, which
-- needs |J_t| <= mu_k·J_n) or sliding through it (J_t = mu_k·J_n).

local function throw()
  return theory.thrown_box { width = 0.4, height = 0.3, mass = param.mass, throw_speed = param.throw_speed,
                             spin = param.spin, centre_height = 1, mu_k = param.mu_k }
end

lesson {
  title = "Throw a box: does it slide or tumble?",
  question = "Why does a thrown box tumble when it lands, while a game's box that cannot turn slides to a halt?",
  -- (At most 10 s: with no friction the locked box never stops.)
  duration = function() return math.min(throw().locked_stop_time + 0.5, 10) end,
  order = 35,
  moments = {
    { "in_flight", at = 0.3, shows = function() return value_at("box_touches", time()) == 0 end },
    { "tumbling", at = 0.75, readme = true, shows = function() return math.abs(value_at("box_spin", time())) > 1 end },
  },
}

-- Parameters ------------------------------------------------------------------------------
local throw_speed = parameter { "throw_speed", 3, min = 0.5, max = 8, unit = "m/s", text = "how fast it is thrown" }
local spin = parameter { "spin", -6, min = -20, max = 20, unit = "rad/s", text = "spin (negative: clockwise)" }
local mass = parameter { "mass", 2, min = 0.2, max = 20, unit = "kg", text = "mass of each box" }

-- Wooden crates on a wooden floor; the two lanes' floors never meet the other box.
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }

-- World -----------------------------------------------------------------------------------
-- Two lanes: the locked box 1.6 m above the thrown one, on a floor 0.2 m thick.
local floor = ground { "floor", material = "wood" }
local upper = ground { "upper_floor", material = "wood", y = 1.6, thickness = 0.2 }
local thrown = box { "box", material = "wood", width = 0.4, height = 0.3, x = 0, y = 1, mass = mass,
                     velocity = { throw_speed, 0 }, spin = spin }
local locked = box { "locked_box", material = "wood", width = 0.4, height = 0.3, x = 0, y = 2.6, mass = mass,
                     velocity = { throw_speed, 0 }, spin = spin, fixed_rotation = true }

-- A strip for each box, side by side in time: the tumble above, the game's slide below.
view { lanes = { thrown, locked } }

-- Probes and plots ------------------------------------------------------------------------
local landing = contact(thrown, floor)
probe { "box_spin", unit = "rad/s", read = { thrown, "omega" } }
probe { "box_touches", read = { landing, "points" } }
probe { "box_speed", unit = "m/s", read = { thrown, "vx" } }
probe { "locked_box_speed", unit = "m/s", read = { locked, "vx" } }
probe { "locked_box_distance", unit = "m", read = { locked, "distance", along = { 1, 0 } } }

plot { "Spin of the thrown box", kind = "time", y = { "box_spin" } }
plot { "Speed along the floor", kind = "time", y = { "box_speed", "locked_box_speed" } }

-- Reading the record ----------------------------------------------------------------------
-- The first step that ends touching the floor is the impact: Box2D found the contact at its
-- start, so the corner came within reach during the step before it.
local function first_impact()
  local touches = history("box_touches")
  for i = 2, #touches do
    if touches[i] > 0 then return i end
  end
end

-- Expectations ----------------------------------------------------------------------------
expect { "landing time", unit = "s",
  predicted = function() return throw().landing_time end,
  measured = function() local i = first_impact() return i and history("time")[i - 1] end,
  tolerance = function() return step_length() end }

-- Whether theory has the corner grip or slide (or the box land flat), throw().corner says; the
-- spin it leaves is what the class can see.
expect { "spin just after the impact", unit = "rad/s",
  predicted = function() return throw().spin_after end,
  measured = function() local i = first_impact() return i and history("box_spin")[i] end,
  -- 5 %, and for the step: the box lands at the end of a step, within about spin·h of the exact
  -- landing angle, and the impact's lever arm with it; that error is first order in the step
  -- (at spin −20 rad/s: 1.0, 0.2 and 0.07 rad/s at 240, 960 and 3840 Hz), so spin²·h/2 is allowed.
  tolerance = function() return 0.05 * math.abs(throw().spin_after - spin) + 0.05 + spin * spin * step_length() / 2 end }

expect { "locked box: distance to rest", unit = "m",
  predicted = function() return throw().locked_distance end,
  measured = function()
    return time() >= throw().locked_stop_time + 0.25 and value_at("locked_box_distance", time()) or nil
  end,
  tolerance = function() return 0.01 * throw().locked_distance + throw_speed * step_length() end }
