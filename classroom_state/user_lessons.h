// A student's own lessons in one folder of their home, listed in the window's Lesson menu
// beside the built-in ones: $XDG_DATA_HOME/frictionlab/lessons, or
// ~/.local/share/frictionlab/lessons when XDG_DATA_HOME is not set (the XDG base directory
// rule). A lesson anywhere else still opens by its path.
#pragma once

#include <string>
#include <vector>

namespace frictionlab::classroom_state {

// The folder's path, whether or not it exists; empty when there is no home to find it in.
std::string user_lessons_folder();

struct UserLesson {
  std::string name;  // the file's name without .lua
  std::string path;
  std::string title;  // the script's lesson{ title = "..." }, as the menu shows it; else the name
};

// The *.lua files in user_lessons_folder(), by name; none when the folder is missing. Scripts
// are not run here (a broken one is listed, and opening it shows its mistake): the title is
// read from the script's text: lesson{}'s own title = "..." (or '...'), written as a plain string.
std::vector<UserLesson> user_lessons();

// A lesson file's name (without ".lua") made from `name` as the page makes it: any folder and
// ".lua" dropped, every character but letters, digits, '_', '-' and '.' made '_', no leading
// dots, at most 100 characters; "linked_lesson" when nothing is left.
std::string lesson_file_stem(const std::string& name);
// Keeps `script` among the user's lessons under the name lesson_file_stem(name): NAME.lua, else
// NAME_2.lua, NAME_3.lua..., never over another file or through a link placed in the folder,
// as the page keeps a lesson that comes in from outside; a lesson of that name already holding
// that very text is the same one, kept once. Makes the folder if need be; a write that fails
// leaves no file. Returns the path. Throws InvalidInput when there is no home to keep it in,
// the script is empty, or it cannot be written.
std::string keep_user_lesson(const std::string& name, const std::string& script);

// That title read from a script's text; empty when it has none written as a plain string.
std::string written_title(const std::string& script);

}  // namespace frictionlab::classroom_state
