-- expect: 4: ran for more than 50 million instructions without finishing (an endless loop?)
lesson { title = "Broken", question = "What goes wrong?" }
local x = 0
while x >= 0 do x = x + 1 end
