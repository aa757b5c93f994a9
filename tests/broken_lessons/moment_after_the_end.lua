-- expect: 4: lesson: moment 'late': at = 3 s is after the lesson's end, at 2 s
-- A moment the lesson never reaches at its defaults.
local duration = 2
lesson { title = "Broken", question = "What goes wrong?", duration = duration,
  moments = { { "early", at = 1 }, { "late", at = 3 } } }
