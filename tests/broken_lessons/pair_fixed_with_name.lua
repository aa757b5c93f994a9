-- expect: 3: pair metal/wood: name prefixes its sliders' names; with sliders = false it has none
lesson { title = "Broken", question = "What goes wrong?" }
pair { "metal", "wood", mu_s = 0.4, mu_k = 0.3, name = "steel", sliders = false }
