-- expect: 4: attempt to call a nil value (field 'find')
lesson { title = "Broken", question = "What goes wrong?" }
-- Patterns are not in the sandbox: one can run for minutes inside a single C call.
local found = string.find("block on floor", "floor")
