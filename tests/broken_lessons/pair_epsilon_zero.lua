-- expect: 3: pair wood/metal: epsilon = 0 m/s is outside the allowed range (0, 100]
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "metal", mu_s = 0.6, mu_k = 0.5, treatment = "regularized", epsilon = 0 }
