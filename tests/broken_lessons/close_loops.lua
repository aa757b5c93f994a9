-- expect: 4: variable 'guard' got a non-closable value
lesson { title = "Broken", question = "What goes wrong?" }
-- Without metatables nothing can be closed: no __close can run where no budget stops it.
local guard <close> = {}
