-- expect: 3: parameter 'block': its default comes second and must be one of the choices aluminium, plastic, as in parameter{ "block", "aluminium", choices = { ... } }; got the text "steel"
lesson { title = "Broken", question = "What goes wrong?" }
local block = parameter { "block", "steel", choices = { "aluminium", "plastic" } }
