-- expect: 4: pair wood/metal is given twice
lesson { title = "Broken", question = "What goes wrong?" }
pair { "metal", "wood", mu_s = 0.4, mu_k = 0.3, sliders = false }
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.3 }
