-- expect: 5: the script ran for more than 5 seconds without finishing
lesson { title = "Broken", question = "What goes wrong?" }
-- Each step copies the whole string: few instructions, a lot of time.
local s = ""
for i = 1, 1e7 do s = s .. "x" end
