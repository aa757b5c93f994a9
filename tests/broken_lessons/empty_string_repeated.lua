-- expect: 5: 'undefined_number' is not defined
lesson { title = "Broken", question = "What goes wrong?" }
-- Repeating nothing a huge number of times is nothing, at once.
local nothing = string.rep("", math.maxinteger)
local oops = #nothing + undefined_number
