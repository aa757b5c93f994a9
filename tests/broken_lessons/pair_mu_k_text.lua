-- expect: 3: pair aluminium/wood: mu_k must be a number, got the text "0.4"
lesson { title = "Broken", question = "What goes wrong?" }
pair { "aluminium", "wood", mu_s = 0.5, mu_k = "0.4" }
