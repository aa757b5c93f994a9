-- expect: 4: pair metal/wood is given twice (first at
lesson { title = "Broken", question = "What goes wrong?" }
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
pair { "metal", "wood", mu_s = 0.6, mu_k = 0.5 }
