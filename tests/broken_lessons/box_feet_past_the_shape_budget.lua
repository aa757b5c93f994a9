-- expect: 6: box 'box12': a lesson builds at most 200 shapes (a box on feet is one shape per foot and one for the box, a ground of strips two per strip); this one would make 205
lesson { title = "Broken", question = "What goes wrong?" }
local floor = ground { material = "wood" }
-- Each box on 16 feet is 17 shapes: 11 of them and the ground make 188, the 12th goes past 200.
for i = 1, 30 do
  box { "box" .. i, material = "wood", width = 0.4, height = 0.2, x = i, y = 1, feet = 16, foot_width = 0.02,
        foot_height = 0.02 }
end
