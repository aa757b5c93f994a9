-- expect: 3: pair metal/wood: sliders must be true or false, got the text "no"
lesson { title = "Broken", question = "What goes wrong?" }
pair { "metal", "wood", mu_s = 0.4, mu_k = 0.3, sliders = "no" }
