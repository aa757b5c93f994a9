-- A student's trial (issue 29): boxes set down where a textbook's sizes put them. A crate of
-- height h on the floor has its centre at h/2; a box on top of it at h + h_top/2.
lesson { title = "Boxes set down by their sizes", question = "Do they stay where they were put?", duration = 1 }

material { "crate", density = 200 }
material { "floor", density = 500 }
pair { "crate", "floor", mu_s = 0.5, mu_k = 0.4, sliders = false }
pair { "crate", "crate", mu_s = 0.5, mu_k = 0.4, sliders = false }

ground { material = "floor" }
box { "crate", material = "crate", width = 0.6, height = 0.4, x = 0, y = 0.2 }
box { "top", material = "crate", width = 0.3, height = 0.2, x = 0, y = 0.4 + 0.1 }
circle { "ball", material = "crate", radius = 0.05, x = 1, y = 0.05 }
