-- expect: 3: 'require' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
local json = require("json")
