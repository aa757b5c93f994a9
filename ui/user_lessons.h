// A student's own lessons in one folder of their home, listed in the window's Lesson menu
// beside the built-in ones: $XDG_DATA_HOME/frictionlab/lessons, or
// ~/.local/share/frictionlab/lessons when XDG_DATA_HOME is not set (the XDG base directory
// rule). A lesson anywhere else still opens by its path.
#pragma once

#include <string>
#include <vector>

namespace frictionlab::ui {

// The folder's path, whether or not it exists; empty when there is no home to find it in.
std::string user_lessons_folder();

struct UserLesson {
  std::string name;  // the file's name without .lua, as the menu shows it
  std::string path;
};

// The *.lua files in user_lessons_folder(), by name; none when the folder is missing. Scripts
// are not run here: a broken one is listed, and opening it shows its mistake.
std::vector<UserLesson> user_lessons();

}  // namespace frictionlab::ui
