-- expect: 3: 'require' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local json = require("json")
