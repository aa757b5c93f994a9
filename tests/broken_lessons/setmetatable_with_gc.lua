-- expect: 3: 'setmetatable' is left out of the lesson sandbox
lesson { title = "Broken", question = "What goes wrong?" }
local log = setmetatable({}, { __gc = function() while true do end end })
