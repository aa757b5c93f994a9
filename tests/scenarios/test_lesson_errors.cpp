// Broken lesson scripts (tests/broken_lessons/*.lua) and the exact error each must give. A
// student who makes one of these mistakes must be told where it is and what was expected,
// and the program must neither crash nor hang.
//
// Each script starts with the message it must give, the leading number being its line:
//   -- expect: 7: box 'block': unknown field 'widht'
// and, when the error comes after loading, when it comes:
//   -- when: step          (while it runs, within one simulated second)
//   -- when: expectations  (when its expectations are evaluated after that second)
//   -- when: plots         (when its plots' theory curves are drawn, after the expectations)
// The message must start with "<path>:<line>: " and contain the rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {
namespace {

namespace fs = std::filesystem;

const fs::path corpus_folder = FRICTIONLAB_BROKEN_LESSONS;
constexpr double run_seconds = 1.0;

std::vector<std::string> corpus() {
  std::vector<std::string> names;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(corpus_folder, error)) {
    if (entry.path().extension() == ".lua") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct Expected {
  int line = 0;
  std::string text;
  std::string when = "load";
  std::string problem;  // why the header could not be read; empty when it could
};

Expected read_header(const fs::path& path) {
  Expected expected;
  std::ifstream file(path);
  std::string first, second;
  std::getline(file, first);
  std::getline(file, second);
  const std::string expect = "-- expect: ", when = "-- when: ";
  const std::size_t colon = first.find(": ", expect.size());
  if (first.rfind(expect, 0) != 0 || colon == std::string::npos) {
    expected.problem = "the first line must be '-- expect: LINE: MESSAGE', got '" + first + "'";
    return expected;
  }
  const std::string number = first.substr(expect.size(), colon - expect.size());
  if (number.empty() || !std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    expected.problem = "the line number in '" + first + "' is not a whole number";
    return expected;
  }
  expected.line = std::stoi(number);
  expected.text = first.substr(colon + 2);
  if (second.rfind(when, 0) == 0) {
    expected.when = second.substr(when.size());
    if (expected.when != "load" && expected.when != "step" && expected.when != "expectations" && expected.when != "plots") {
      expected.problem = "'-- when:' takes load, step, expectations or plots, got '" + expected.when + "'";
    }
  }
  return expected;
}

// Loads the script and runs it as far as `when` asks. Returns the stage the first error came
// at ("load", "step", "expectations", or "none") and its message.
struct Failure {
  std::string stage = "none";
  std::string message;
};

Failure first_failure(const std::string& path, const std::string& when) {
  Failure failure;
  failure.stage = "load";
  try {
    Lesson lesson(path);
    if (when == "load") return {};
    failure.stage = "step";
    const double h = lesson.scene().frame_step();
    while (lesson.scene().time() < run_seconds - 0.5 * h) {
      try {
        lesson.step();
      } catch (const ScriptError&) {
        // A script error stops the lesson until it is rebuilt.
        EXPECT_TRUE(lesson.failed()) << "step() threw, but the lesson does not say it failed";
        throw;
      }
    }
    if (when == "step") return {};
    failure.stage = "expectations";
    lesson.expectations();
    if (when == "expectations") return {};
    failure.stage = "plots";
    for (std::size_t plot = 0; plot < lesson.plots().size(); ++plot) {
      lesson.theory_samples(plot, 0.0, 10.0, 16);  // wider than the 0 to 1 tried at load
      lesson.theory_active(plot);
    }
    return {};
  } catch (const ScriptError& error) {
    failure.message = error.what();
  } catch (const std::exception& error) {
    failure.message = std::string("not a ScriptError: ") + error.what();
  }
  return failure;
}

class BrokenLesson : public testing::TestWithParam<std::string> {};

TEST_P(BrokenLesson, GivesTheErrorItsFirstLineNames) {
  const fs::path path = corpus_folder / GetParam();
  const Expected expected = read_header(path);
  ASSERT_TRUE(expected.problem.empty()) << path.string() << ": " << expected.problem;

  const Failure failure = first_failure(path.string(), expected.when);
  ASSERT_EQ(failure.stage, expected.when) << "the error came at a different stage than '-- when:' says; message: "
                                          << (failure.message.empty() ? "(none)" : failure.message);
  const std::string place = path.string() + ":" + std::to_string(expected.line) + ": ";
  EXPECT_EQ(failure.message.rfind(place, 0), 0u) << "expected the message to start with '" << place << "'\ngot: "
                                                 << failure.message;
  EXPECT_NE(failure.message.find(expected.text), std::string::npos)
      << "expected the message to contain '" << expected.text << "'\ngot: " << failure.message;
  // Placed once: no second "path:line: " after the first.
  const std::string rest = failure.message.size() >= place.size() ? failure.message.substr(place.size()) : "";
  EXPECT_NE(rest.rfind(path.string() + ":", 0), 0u) << "the message names its place twice: " << failure.message;
}

std::string test_name(const testing::TestParamInfo<std::string>& info) {
  std::string name = fs::path(info.param).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BrokenLesson, testing::ValuesIn(corpus()), test_name);

TEST(BrokenLessonCorpus, HasAtLeastFortyScripts) {
  EXPECT_GE(corpus().size(), 40u) << "in " << corpus_folder.string();
}

}  // namespace
}  // namespace frictionlab::lessons
