-- expect: 3: pair wood/metal: unknown friction treatment 'regularised'; allowed: stick-slip, threshold, regularized, box2d
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "metal", mu_s = 0.6, mu_k = 0.5, treatment = "regularised", epsilon = 0.05 }
