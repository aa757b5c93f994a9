-- expect: 6: ran for more than 50 million instructions without finishing (an endless loop?)
-- when: step
lesson { title = "Broken", question = "What goes wrong?" }
probe { "height", unit = "m", function()
  local h = 0
  while h >= 0 do h = h + 1 end
  return h
end }
