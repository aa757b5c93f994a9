-- expect: 5: pair crate/floor: give both mu_s and mu_k, or neither for the preset values
lesson { title = "Broken", question = "What goes wrong?" }
material { "crate", density = 40 }
material { "floor", density = 2000 }
pair { "crate", "floor", mu_s = 0.5 }
