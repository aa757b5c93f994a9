// Where an installed FrictionLab finds its files. `cmake --install` lays them out with
// GNUInstallDirs (bin/frictionlab, share/frictionlab/lessons/); the program looks for them
// relative to its own binary, so an installed tree works wherever it is put (/usr, /opt, a
// temporary folder) and never reaches back into the source tree it was built from.
#pragma once

#include <string>

namespace frictionlab {

// The folder the running binary is in (from /proc/self/exe); empty if the system does not say.
std::string executable_folder();

// The built-in lessons of an installed copy: FRICTIONLAB_DATA_FROM_BIN/lessons from the binary's
// folder (../share/frictionlab/lessons for bin/frictionlab). Empty when there is no such folder:
// a binary run from its build folder then uses the source tree's lessons/.
std::string installed_lessons_directory();

// Points the lesson catalog at the installed lessons, unless $FRICTIONLAB_LESSONS already names a
// folder (the user's override wins). The catalog reads $FRICTIONLAB_LESSONS, so that is the
// channel: set here only when it is unset, before anything lists the lessons.
void use_installed_lessons();

}  // namespace frictionlab
