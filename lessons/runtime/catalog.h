// The built-in lessons, listed explicitly (as Box2D's samples are), and how a name on the
// command line becomes a script path.
#pragma once

#include <string>
#include <vector>

namespace frictionlab::lessons {

// In the order a teacher meets them.
const std::vector<std::string>& builtin_lessons();

// Where the built-in scripts live: $FRICTIONLAB_LESSONS if set, else the source tree's
// lessons/ folder this program was built from.
std::string lessons_directory();

// A built-in lesson's name, or a path to a .lua file, to the path of its script. Throws
// InvalidInput listing the built-in lessons when it is neither.
std::string resolve_lesson(const std::string& name_or_path);

}  // namespace frictionlab::lessons
