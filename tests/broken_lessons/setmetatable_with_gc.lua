-- expect: 3: 'setmetatable' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
local log = setmetatable({}, { __gc = function() while true do end end })
