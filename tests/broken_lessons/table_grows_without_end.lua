-- expect: 5: MB of memory (a table that grows without end
lesson { title = "Broken", question = "What goes wrong?" }
local log = {}
while true do
  log[#log + 1] = string.rep("step ", 200) .. #log
end
