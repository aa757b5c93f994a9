-- expect: 3: setmetatable: a metatable in a lesson cannot have __gc
lesson { title = "Broken", question = "What goes wrong?" }
local log = setmetatable({}, { __gc = function() while true do end end })
