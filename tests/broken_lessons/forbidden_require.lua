-- expect: 3: attempt to call a nil value (global 'require')
lesson { title = "Broken", question = "What goes wrong?" }
local json = require("json")
