-- expect: 4: theory.wedge: law 'as written' is neither "coulomb" nor "article"
-- when: load
lesson { title = "Broken", question = "What goes wrong?" }
local run = theory.wedge { mass = 1, theta0 = 10, mu_k = 0.2, duration = 1, step = 0.01, law = "as written" }
