-- expect: 3: material 'felt': density must be a number (kg/m²), got the text "light"
lesson { title = "Broken", question = "What goes wrong?" }
material { "felt", density = "light" }
