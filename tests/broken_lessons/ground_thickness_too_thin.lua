-- expect: 3: ground: thickness = 0.001 m is outside the allowed range [0.02, 2]
lesson { title = "Broken", question = "What goes wrong?" }
ground { material = "wood", thickness = 0.001 }
