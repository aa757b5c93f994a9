-- expect: 3: pair wood/metal: epsilon needs treatment = "threshold" or "regularized"
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "metal", mu_s = 0.6, mu_k = 0.5, epsilon = 0.05 }
