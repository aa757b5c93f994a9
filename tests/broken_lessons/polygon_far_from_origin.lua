-- expect: 5: polygon 'wedge': its corners are centred 100.337 m from {0, 0}, too far for a shape this small
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
-- The corners in world coordinates, and the polygon placed at the origin.
polygon { "wedge", material = "wood", points = { { 100, 0.5 }, { 101, 0.5 }, { 100, 1.5 } } }
