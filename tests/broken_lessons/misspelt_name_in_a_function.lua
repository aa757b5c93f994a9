-- expect: 4: 'mas' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local function block_mass()
  return mas
end
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "wood" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0, mass = block_mass() }
