// Helpers for tests that run lesson scripts: a script written to a temporary file, and
// running a lesson for a while.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

// A script in its own temporary file, removed when the test ends; rewrite() is what a
// student's editor does on save.
class ScriptFile {
 public:
  explicit ScriptFile(const std::string& text) {
    static int count = 0;
    std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(test.begin(), test.end(), '/', '_');  // a parameterized test's name holds its parameter after a '/'
    path_ = (std::filesystem::temp_directory_path() /
             ("frictionlab_" + test + "_" + std::to_string(::getpid()) + "_" + std::to_string(++count) + ".lua"))
                .string();
    rewrite(text);
  }
  ~ScriptFile() { std::filesystem::remove(path_); }
  void rewrite(const std::string& text) const { std::ofstream(path_, std::ios::binary) << text; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// `text` with its first `from` replaced by `to`: a script broken or changed in one place. A
// `from` the text lacks fails the test (the script it was written for has changed).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The opening every small test script shares.
inline std::string with_heading(const std::string& body) {
  return "lesson { title = \"test\", question = \"does it work?\" }\n" + body;
}

// `body` on a frictionless floor of ice, `floor`, with pucks (material "puck", 100 kg/m³)
// sliding on it and on each other without friction: for forces, springs and readings held to
// closed forms that friction would only blur.
inline std::string on_frictionless_ice(const std::string& body) {
  return with_heading(R"(
material { "puck", density = 100 }
pair { "puck", "ice", mu_s = 0, mu_k = 0 }
pair { "puck", "puck", mu_s = 0, mu_k = 0 }
local floor = ground { material = "ice" }
)" + body);
}

inline void run_for(Lesson& lesson, double seconds) { lesson.step_to(lesson.scene().time() + seconds); }

// The message of the InvalidInput (or ScriptError) `call` throws; fails the test when none.
template <class Call>
std::string error_of(Call call) {
  try {
    call();
  } catch (const InvalidInput& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error was raised";
  return "";
}

// The message a script refused while it builds gives (written to its own file first).
inline std::string error_building(const std::string& text) {
  const ScriptFile script(text);
  return error_of([&] { Lesson lesson(script.path()); });
}

}  // namespace frictionlab::lessons
