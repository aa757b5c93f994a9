// The guide's table of theory.* functions (lessons/reference/theory.md, section 11) and the runtime's
// one table of them (lessons/runtime/script_theory.cpp) name the same functions, and a
// described function's every argument is named in its row.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "lessons/runtime/theory_binding.h"

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

}  // namespace
}  // namespace frictionlab::lessons
