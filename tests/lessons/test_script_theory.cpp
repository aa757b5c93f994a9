// The guide's table of theory.* functions (lessons/reference/theory.md, section 11) and the runtime's
// one table of them (lessons/runtime/script_theory.cpp) name the same functions, and a
// described function's every argument is named in its row. The constants the guide prints
// (section 12, and the cheat sheet) are the values a script reads, and the engine's own. What
// theory.* answers in a script is what the closed forms the physics tests check answer, and it
// answers every value a slider allows.

#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>

#include "lessons/runtime/theory_binding.h"
#include "physics/closed_forms.h"
#include "physics/friction_laws.h"
#include "physics/scenarios.h"
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

// A theory of the stepped world reads the engine's own constants, not copies of them: the
// listener's hold band (wedge's rocking test) and Box2D's linear slop, the overlap its position
// solver allows (wedge's lost contact, stacked_blocks' tilt). The script's value is the C++ one
// exactly; Box2D keeps its slop as a float, and the script's is Box2D's to the float's precision.
struct EngineConstant {
  const char* name;      // the script's global
  double value;          // the engine's constant
  bool float_precision;  // the engine keeps it as a float: compared as one
};

void PrintTo(const EngineConstant& constant, std::ostream* out) { *out << constant.name; }

class ScriptConstants : public ::testing::TestWithParam<EngineConstant> {};

TEST_P(ScriptConstants, AreTheEnginesOwn) {
  const EngineConstant& constant = GetParam();
  const double read = script_global(constant.name);
  if (constant.float_precision) {
    EXPECT_EQ(static_cast<float>(read), static_cast<float>(constant.value));
  } else {
    EXPECT_EQ(read, constant.value);
  }
}

INSTANTIATE_TEST_SUITE_P(EngineConstants, ScriptConstants,
                         ::testing::Values(EngineConstant{"stick_slip_hold_band", stick_slip_hold_band, false},
                                           EngineConstant{"linear_slop", b2_linearSlop, true}),
                         [](const ::testing::TestParamInfo<EngineConstant>& constant) { return std::string(constant.param.name); });

constexpr double g = standard_gravity;
constexpr double degrees = std::numbers::pi / 180.0;

// Probe "r<i>" now, for scripts that list their answers as r[1], r[2]...
// Appended rather than "r" + to_string(i): GCC 12 warns falsely on that (-Wrestrict, PR 105329).
double numbered_probe_now(const Lesson& lesson, int i) {
  std::string name = "r";
  name += std::to_string(i);
  return lesson.scene().probe(name).history.back();
}

TEST(TheoryFunctions, TheoryInScriptsIsTheTheoryTheTestsCheck) {
  ScriptFile script(with_heading(R"(
local r = {}
r[1] = theory.sticking_angle { mu_s = 1 }
r[2] = theory.incline_acceleration { angle = 30, mu_k = 0.2 }
r[3] = theory.incline_motion { angle = 40, mu_k = 0.3, c = 1.5, mass = 2, t = 0.7 }.distance
r[4] = theory.tip_height { width = 0.5, mu_s = 0.5 }
r[5] = theory.push_outcome { mass = 10, width = 0.5, push_height = 0.3, mu_s = 0.5 }.force
r[6] = theory.spring_stick_slip { mass = 1, k = 50, pull_speed = 0.1, mu_s = 0.6, mu_k = 0.4 }.period
r[7] = theory.slide_to_rest { v0 = 3, mass = 1, mu_s = 0.5, mu_k = 0.4, c = 2, b = 0.5 }.distance
r[8] = theory.disk_on_incline { angle = 30, mass = 1, radius = 0.1, mu_s = 0.1, mu_k = 0.08 }.acceleration
r[9] = theory.disk_starts_rolling { v0 = 2, mass = 1, radius = 0.1, mu_k = 0.3 }.time
r[10] = theory.stacked_blocks { top_mass = 1, bottom_mass = 2, push = 30,
          between = { mu_s = 0.3, mu_k = 0.2 }, ground = { mu_s = 0.4, mu_k = 0.3 } }.top_acceleration
r[11] = theory.spring_stick_slip { mass = 1, k = 50, pull_speed = 0.1, mu_s = 0.6, mu_k = 0.4, duration = 5 }.run.shortest_stick
r[12] = theory.spring_stick_slip { mass = 1, k = 50, pull_speed = 0.1, mu_s = 0.6, mu_k = 0.4, duration = 5 }.run.longest_slip
for i = 1, #r do probe { "r" .. i, function() return r[i] end } end
)"));
  Lesson lesson(script.path());
  lesson.step();
  auto r = [&](int i) { return numbered_probe_now(lesson, i); };
  using namespace theory;
  EXPECT_NEAR(r(1), 45.0, 1e-12);
  EXPECT_NEAR(r(2), incline_sliding_acceleration(30 * degrees, 0.2, g), 1e-12);
  EXPECT_NEAR(r(3), incline_distance(40 * degrees, 0.3, 1.5, 2, g, 0.7), 1e-12);
  EXPECT_NEAR(r(4), 0.5, 1e-12);
  EXPECT_NEAR(r(5), push_outcome(10 * g, 0.5, 0.3, 0.5).force, 1e-12);
  EXPECT_NEAR(r(6), spring_stick_slip(1, 50, 0.1, 0.6, 0.4, g).period, 1e-12);
  EXPECT_NEAR(r(7), slide_to_rest(3, 1, {0.5, 0.4, 2, 0.5}, g).distance, 1e-12);
  EXPECT_NEAR(r(8), disk_on_incline(30 * degrees, 1, 0.1, 0.5 * 0.01, 0.1, 0.08, g).acceleration, 1e-12);
  EXPECT_NEAR(r(9), disk_starts_rolling(2, 1, 0.1, 0.5 * 0.01, 0.3, g).time, 1e-12);
  EXPECT_NEAR(r(10), stacked_blocks(1, 2, {0.3, 0.2, 0, 0}, {0.4, 0.3, 0, 0}, 30, g).top_acceleration, 1e-12);
  // The run's events are the closed form's phases joined where each ends, found to 1e-13 s: every
  // stick lasts the cycle's 2(μs − μk)·m·g/(k·v), 0.785 s (5 s hold three of them).
  EXPECT_NEAR(r(11), spring_stick_slip(1, 50, 0.1, 0.6, 0.4, g).stick_duration, 1e-9);
  // And every slip lasts the cycle's slip_duration, 0.542 s (5 s hold three, the last ending at 4.37 s).
  EXPECT_NEAR(r(12), spring_stick_slip(1, 50, 0.1, 0.6, 0.4, g).slip_duration, 1e-9);
}

// A theory call reads a pair's fields as the pair's table has them (physics/materials.h): a
// pair given inside the call (stacked_blocks' between) without mu_s slides and holds at mu_k,
// and the drag coefficients reach the functions that run a model (regularized_creep's creep
// against its closed form, spring_stick_slip's cycle, which drag takes away).
TEST(TheoryFunctions, APairsFieldsAreReadAsThePairsTableHasThem) {
  ScriptFile script(with_heading(R"(
local r = {}
r[1] = theory.stacked_blocks { top_mass = 1, bottom_mass = 2, push = 30,
         between = { mu_k = 0.2 }, ground = { mu_s = 0.4, mu_k = 0.3 } }.max_push_together
r[2] = theory.regularized_creep { angle = 20, mu_s = 0.5, epsilon = 0.05, c = 3, mass = 2 }.speed
r[3] = theory.spring_stick_slip { mass = 1, k = 50, pull_speed = 0.1, mu_s = 0.6, mu_k = 0.4,
         b = 0.5 }.no_closed_form and 1 or 0
for i = 1, 3 do probe { "r" .. i, function() return r[i] end } end
)"));
  Lesson lesson(script.path());
  lesson.step();
  auto r = [&](int i) { return numbered_probe_now(lesson, i); };
  // Together up to (μs between + μk ground)·(m1 + m2)·g, with μs between = μk between = 0.2.
  EXPECT_NEAR(r(1), (0.2 + 0.3) * 3.0 * g, 1e-12);
  // The creep without a step: c·v/m = g·sin θ − (μs·g·cos θ/ε)·v, so
  // v = g·sin θ/(μs·g·cos θ/ε + c/m); the runtime bisects it to 1e-15·ε.
  const double angle = 20 * degrees;
  EXPECT_NEAR(r(2), g * std::sin(angle) / (0.5 * g * std::cos(angle) / 0.05 + 3.0 / 2.0), 1e-12);
  EXPECT_EQ(r(3), 1.0);
}

// A slider may reach values a closed form has no answer for: theory.* then answers in words
// (or by the contacts' own rule) instead of raising an error that stops the lesson.
TEST(TheoryFunctions, TheoryAnswersEveryValueASliderAllows) {
  ScriptFile script(with_heading(R"(
local r = {}
r[1] = theory.disk_on_incline { angle = 20, mass = 1, radius = 0.1, mu_s = 0.05, mu_k = 0.3 }.rolls and 1 or 0
r[2] = theory.stacked_blocks { top_mass = 1, bottom_mass = 2, push = 30,
         between = { mu_s = 0.2, mu_k = 0.4 }, ground = { mu_s = 0.4, mu_k = 0.3 } }.no_closed_form and 1 or 0
r[3] = theory.regularized_creep { angle = 40, mu_s = 0.5, epsilon = 0.05, step = 1 / 240 }.no_creep and 1 or 0
r[4] = theory.spring_stick_slip { mass = 1, k = 50, pull_speed = 0.1, mu_s = 0.2, mu_k = 0.5 }.no_closed_form and 1 or 0
r[5] = theory.spring_stick_slip { mass = 1, k = 50, pull_speed = 0.1, mu_s = 0.2, mu_k = 0.5, duration = 3 }.run.breakaways
for i = 1, #r do probe { "r" .. i, function() return r[i] end } end
)"));
  Lesson lesson(script.path());
  lesson.step();
  auto r = [&](int i) { return numbered_probe_now(lesson, i); };
  EXPECT_EQ(r(1), 1.0);  // rolling needs 1.12 N of friction: more than mu_s·N holds, within mu_k·N
  EXPECT_EQ(r(2), 1.0);
  EXPECT_EQ(r(3), 1.0);
  EXPECT_EQ(r(4), 1.0);
  EXPECT_GE(r(5), 1.0);  // the run itself still answers: it breaks away at max(mu_s, mu_k)·N
}

}  // namespace
}  // namespace frictionlab::lessons
