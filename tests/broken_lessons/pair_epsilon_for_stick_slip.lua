-- expect: 3: pair wood/metal: epsilon is for the threshold and regularized treatments, not stick-slip
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "metal", mu_s = 0.6, mu_k = 0.5, treatment = "stick-slip", epsilon = 0.05 }
