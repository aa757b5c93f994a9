// The guide's table of theory.* functions (lessons/reference/theory.md, section 11) and the runtime's
// one table of them (lessons/runtime/script_theory.cpp) name the same functions, and a
// described function's every argument is named in its row. The constants the guide prints
// (section 12, and the cheat sheet) are the values a script reads.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "lessons/runtime/theory_binding.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

// function name -> its row's arguments column, from rows "| `theory.NAME` | ARGUMENTS | ...".
std::map<std::string, std::string> guide_rows() {
  std::ifstream guide(std::string(FRICTIONLAB_SOURCE_DIR) + "/lessons/reference/theory.md");
  EXPECT_TRUE(guide) << "cannot read lessons/reference/theory.md";
  std::map<std::string, std::string> rows;
  const std::string start = "| `theory.";
  for (std::string line; std::getline(guide, line);) {
    if (line.rfind(start, 0) != 0) continue;
    const std::size_t name_end = line.find('`', start.size());
    const std::size_t arguments_end = line.find(" | ", name_end + 4);
    if (name_end == std::string::npos || arguments_end == std::string::npos) continue;
    rows[line.substr(start.size(), name_end - start.size())] = line.substr(name_end + 4, arguments_end - name_end - 4);
  }
  return rows;
}

TEST(TheoryGuide, EveryTheoryFunctionHasARowAndEveryRowAFunction) {
  const std::map<std::string, std::string> rows = guide_rows();
  std::set<std::string> bound;
  for (const TheoryFunction& function : theory_functions()) {
    bound.insert(function.name);
    EXPECT_TRUE(rows.contains(function.name)) << "lessons/reference/theory.md: the table of theory.* functions has no row for theory."
                                              << function.name;
  }
  for (const auto& [name, arguments] : rows) {
    EXPECT_TRUE(bound.contains(name)) << "lessons/reference/theory.md lists theory." << name
                                      << ", which script_theory.cpp's table does not have";
  }
  EXPECT_EQ(bound.size(), theory_functions().size()) << "a theory function is listed twice";
}

TEST(TheoryGuide, ADescribedFunctionsArgumentsAreAllInItsRow) {
  const std::map<std::string, std::string> rows = guide_rows();
  for (const TheoryFunction& function : theory_functions()) {
    const auto row = rows.find(function.name);
    if (row == rows.end()) continue;  // the test above says so
    for (const TheoryArgument& argument : function.arguments) {
      EXPECT_NE(row->second.find(std::string("`") + argument.key + "`"), std::string::npos)
          << "lessons/reference/theory.md: theory." << function.name << "'s row does not name its argument `" << argument.key << "`";
    }
  }
}

// name -> the value printed, from the constants table's rows "| `NAME` | VALUE | ...".
std::map<std::string, std::string> printed_constants() {
  std::ifstream guide(std::string(FRICTIONLAB_SOURCE_DIR) + "/lessons/reference/theory.md");
  EXPECT_TRUE(guide) << "cannot read lessons/reference/theory.md";
  std::map<std::string, std::string> printed;
  bool in_table = false;
  for (std::string line; std::getline(guide, line);) {
    if (line.rfind("## ", 0) == 0) in_table = line.find("Constants") != std::string::npos;
    if (!in_table || line.rfind("| `", 0) != 0) continue;
    const std::size_t name_end = line.find('`', 3);
    const std::size_t value_end = line.find(" |", name_end + 4);
    if (name_end == std::string::npos || value_end == std::string::npos) continue;
    printed[line.substr(3, name_end - 3)] = line.substr(name_end + 4, value_end - name_end - 4);
  }
  return printed;
}

// The value a lesson script reads for the global `name`.
double script_global(const std::string& name) {
  ScriptFile script(with_heading("probe { \"value\", function() return " + name + " end }\n"));
  Lesson lesson(script.path());
  lesson.step();
  return lesson.scene().probe("value").history.back();
}

// The docs print the hold band (set from physics/friction_laws.h, not in a script) as 0.02, and
// g, resting_gap and Box2D's linear slop likewise: each printed number must be the one a script reads, so that a
// change in the C++ shows up here until the docs say it.
TEST(TheoryGuide, TheConstantsPrintedAreTheValuesAScriptReads) {
  const std::map<std::string, std::string> printed = printed_constants();
  for (const char* name : {"g", "resting_gap", "stick_slip_hold_band", "linear_slop"}) {
    const auto row = printed.find(name);
    if (row == printed.end()) {
      ADD_FAILURE() << "lessons/reference/theory.md, section 12: no row for `" << name << "`";
      continue;
    }
    const double read = script_global(name);
    EXPECT_EQ(std::stod(row->second), read) << "lessons/reference/theory.md prints `" << name << "` as " << row->second;
    // The cheat sheet's row of constants: "`NAME` (VALUE)".
    std::ifstream sheet(std::string(FRICTIONLAB_SOURCE_DIR) + "/lessons/cheatsheet.md");
    const std::string text{std::istreambuf_iterator<char>(sheet), std::istreambuf_iterator<char>()};
    const std::string opening = std::string("`") + name + "` (";
    const std::size_t at = text.find(opening);
    if (at == std::string::npos) {
      ADD_FAILURE() << "lessons/cheatsheet.md does not print `" << name << "`";
      continue;
    }
    const std::size_t from = at + opening.size();
    const std::string value = text.substr(from, text.find(')', from) - from);
    EXPECT_EQ(std::stod(value), read) << "lessons/cheatsheet.md prints `" << name << "` as " << value;
  }
}

}  // namespace
}  // namespace frictionlab::lessons
