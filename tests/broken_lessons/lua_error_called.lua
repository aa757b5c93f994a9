-- expect: 5: push_height (1.5 m) must not be above the top of the box
lesson { title = "Broken", question = "What goes wrong?" }
local push_height, height = 1.5, 1.0
if push_height > height then
  error(string.format("push_height (%g m) must not be above the top of the box", push_height))
end
