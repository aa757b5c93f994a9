// Where the window looks for a student's own lessons: the XDG base directory rule, and the
// listing of that folder.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "classroom_state/user_lessons.h"

namespace frictionlab::classroom_state {
namespace {

namespace fs = std::filesystem;

// Sets (or unsets, with nullopt) an environment variable for the test's length.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) ::setenv(name, value->c_str(), 1);
    else ::unsetenv(name);
  }
  ~ScopedEnvironment() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(UserLessons, TheFolderIsUnderXdgDataHome) {
  const ScopedEnvironment data("XDG_DATA_HOME", "/srv/class/data");
  const ScopedEnvironment home("HOME", "/home/student");
  EXPECT_EQ(user_lessons_folder(), "/srv/class/data/frictionlab/lessons");
}

TEST(UserLessons, WithoutXdgDataHomeOrWithARelativeOneItIsInTheHome) {
  const ScopedEnvironment home("HOME", "/home/student");
  {
    const ScopedEnvironment data("XDG_DATA_HOME", std::nullopt);
    EXPECT_EQ(user_lessons_folder(), "/home/student/.local/share/frictionlab/lessons");
  }
  // The XDG rule: a relative path is invalid and ignored.
  const ScopedEnvironment data("XDG_DATA_HOME", "data");
  EXPECT_EQ(user_lessons_folder(), "/home/student/.local/share/frictionlab/lessons");
}

TEST(UserLessons, NoHomeNoFolder) {
  const ScopedEnvironment data("XDG_DATA_HOME", std::nullopt);
  const ScopedEnvironment home("HOME", std::nullopt);
  EXPECT_EQ(user_lessons_folder(), "");
  EXPECT_TRUE(user_lessons().empty());
}

TEST(UserLessons, OnlyTheLuaFilesAreListedByName) {
  const fs::path data = fs::temp_directory_path() / ("frictionlab_user_lessons_" + std::to_string(::getpid()));
  const ScopedEnvironment environment("XDG_DATA_HOME", data.string());
  EXPECT_TRUE(user_lessons().empty());  // no folder yet: nothing, and no error
  const fs::path folder = data / "frictionlab" / "lessons";
  fs::create_directories(folder / "old.lua");  // a folder named like a script is not one
  for (const char* name : {"steep.lua", "notes.txt", "a_first.lua"}) std::ofstream(folder / name) << "-- a lesson\n";
  const std::vector<UserLesson> found = user_lessons();
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].name, "a_first");
  EXPECT_EQ(found[0].path, (folder / "a_first.lua").string());
  EXPECT_EQ(found[1].name, "steep");
  fs::remove_all(data);
}

// The menu shows a lesson by its title, read from the script's text without running it; a
// script with no title written as a plain string is shown by its file's name.
TEST(UserLessons, EachIsListedWithItsLessonsTitle) {
  const fs::path data = fs::temp_directory_path() / ("frictionlab_user_titles_" + std::to_string(::getpid()));
  const ScopedEnvironment environment("XDG_DATA_HOME", data.string());
  const fs::path folder = data / "frictionlab" / "lessons";
  fs::create_directories(folder);
  std::ofstream(folder / "my_push.lua") << "-- a plot's title = \"not this\"\nlocal p = plot { title = \"nor this\" }\n"
                                          "lesson {\n  order = 3,\n  title = 'Pushing a heavy box',\n}\n";
  std::ofstream(folder / "untitled.lua") << "lesson { title = make_title() }\n";
  const std::vector<UserLesson> found = user_lessons();
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].title, "Pushing a heavy box");
  EXPECT_EQ(found[1].title, "untitled");
  EXPECT_EQ(written_title("lesson{ title = \"Incline\" }"), "Incline");
  EXPECT_EQ(written_title("-- no lesson here\n"), "");
  // Only lesson{}'s own title: not a later call's, a longer name's, a string's or a nested table's.
  EXPECT_EQ(written_title("lesson { order = 3 }\nplot { title = \"Speed\" }\n"), "");
  EXPECT_EQ(written_title("lesson { question = \"what \\\" title = 'x'\", plot_title = 'no', -- title = 'comment'\n"
                          "  moments = { { title = 'inner' } }, title = 'Yes' }"),
            "Yes");
  fs::remove_all(data);
}

}  // namespace
}  // namespace frictionlab::classroom_state
