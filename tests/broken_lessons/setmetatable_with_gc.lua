-- expect: 3: attempt to call a nil value (global 'setmetatable')
lesson { title = "Broken", question = "What goes wrong?" }
local log = setmetatable({}, { __gc = function() while true do end end })
