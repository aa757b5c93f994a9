-- expect: 7: box 'box100': a lesson builds at most 100 bodies (a pile of more would make every step slow); this is one too many
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
-- 2 000 boxes on one spot: Box2D would handle about two million pairs of them every step.
-- The ground is the first body, so the 100th box is the 101st.
for i = 1, 2000 do
  box { "box" .. i, material = "wood", width = 0.4, height = 0.2, x = 0, y = 0.1 }
end
