-- expect: 5: pair crate/floor: there is no preset for this pair; give mu_s and mu_k
lesson { title = "Broken", question = "What goes wrong?" }
material { "crate", density = 40 }
material { "floor", density = 2000 }
pair { "crate", "floor" }
