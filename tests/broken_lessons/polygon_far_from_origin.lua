-- expect: 5: polygon 'wedge': its corners are centred 1000.33 m from {0, 0}, too far for a shape this small; give them around {0, 0} and place the polygon with x and y
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood" }
-- The corners in world coordinates, and the polygon placed at the origin.
polygon { "wedge", material = "wood", points = { { 1000, 0.5 }, { 1001, 0.5 }, { 1000, 1.5 } } }
