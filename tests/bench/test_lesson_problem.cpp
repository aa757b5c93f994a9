// Each built-in lesson is its own benchmark problem: its script run at a setting and judged by
// its expectations, each numeric row in units of its tolerance at the default setting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"
#include "bench/lesson_problem.h"
#include "bench/cheapest_setting.h"

namespace frictionlab::lessons {
namespace {

StepSettings setting(FrictionTreatment treatment, double hz, int substeps = 1) {
  StepSettings settings;
  settings.treatment = treatment;
  settings.hz = hz;
  settings.substeps = substeps;
  return settings;
}

// Every built-in lesson (the folder's list) answers: at its default setting within its own
// tolerances and without a failure, and at a coarse one with a finite error.
TEST(LessonBenchmark, EveryBuiltInLessonIsAnswerableAtItsDefaultAndACoarseSetting) {
  ASSERT_FALSE(builtin_lessons().empty());
  for (const std::string& name : builtin_lessons()) {
    const BenchmarkProblem problem = lesson_problem(name);
    const Outcome at_default = problem.run(StepSettings{});
    EXPECT_LE(at_default.error, 1.0) << name;
    EXPECT_EQ(at_default.fails, "") << name;
    const Outcome coarse = problem.run(setting(FrictionTreatment::stick_slip, 60.0));
    EXPECT_TRUE(std::isfinite(coarse.error)) << name << " at 60 Hz: " << coarse.fails;
  }
}

// A tolerance that grows with the step (spring_pull's breakaway allows k·v·h) does not loosen
// the judging: at 30 Hz the lesson's own table passes (its tolerances have grown with the
// step), but judged by the 240 Hz tolerances the run misses.
TEST(LessonBenchmark, RowsAreJudgedByTheirToleranceAtTheDefaultSetting) {
  const StepSettings coarse = setting(FrictionTreatment::stick_slip, 30.0);
  Lesson lesson(resolve_lesson("spring_pull"), {}, coarse);
  lesson.step_to(lesson.duration());
  double own = 0.0;
  for (const ExpectationResult& row : lesson.expectations()) {
    if (row.numeric && row.tolerance > 0.0) own = std::max(own, std::abs(row.error()) / row.tolerance);
  }
  const double judged = lesson_problem("spring_pull").error(coarse);
  EXPECT_LT(own, 1.0);
  EXPECT_GT(judged, 1.0) << "own tolerances " << own;
}

// One coefficient (Box2D's own) lets the low-pushed box slide at mu_k·m·g = 39.2 N where it
// should at mu_s·m·g = 49.05 N: tens of the lesson's tolerances (0.5 % of the push) early.
// The regularized law lets the box creep and chatter under the growing push.
TEST(LessonBenchmark, TippingBoxTellsTheTreatmentsApartAtTheSlidersValues) {
  const BenchmarkProblem slides = lesson_problem("tipping_box", {{"push_height", "0.3"}});
  EXPECT_LE(slides.error(StepSettings{}), 1.0);
  EXPECT_GT(slides.error(setting(FrictionTreatment::box2d, 240.0)), 10.0);
  const Outcome regularized = lesson_problem("tipping_box").run(setting(FrictionTreatment::regularized, 240.0));
  EXPECT_FALSE(std::isfinite(regularized.error) && regularized.error <= 1.0) << regularized.error;
  EXPECT_EQ(regularized.fails, "chatters");
}

// On where_methods_fail's 20° slope every treatment that holds with a coefficient keeps the
// block still (its "slid" row is 0 within 1 mm); the regularized law lets it creep.
// where_methods_fail gives each of its three blocks its own treatment (pair{ treatment = ... }),
// so the run's treatment changes nothing in it: every setting at 240 Hz answers as the lesson's
// own run does, and only the step rate and sub-steps are left for the recommender to vary.
TEST(LessonBenchmark, WhereMethodsFailKeepsItsPairsOwnTreatmentsWhateverTheRunsIs) {
  const BenchmarkProblem problem = lesson_problem("where_methods_fail");
  const double stick_slip = problem.error(setting(FrictionTreatment::stick_slip, 240.0));
  EXPECT_LE(stick_slip, 1e-3);
  for (const FrictionTreatment other : {FrictionTreatment::threshold, FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    EXPECT_EQ(problem.error(setting(other, 240.0)), stick_slip) << treatment_name(other);
  }
}

// The recommender over a lesson: what it names meets the tolerance and nothing that meets it
// is cheaper; a tolerance ten times tighter is met by fewer settings.
TEST(LessonBenchmark, TheRecommenderFindsTheCheapestSettingThatAnswersTheLesson) {
  Recommender loose(lesson_problem("spring_pull"), 1.0, 1), tight(lesson_problem("spring_pull"), 0.1, 1);
  loose.run_all();
  tight.run_all();
  const std::optional<Trial> best = loose.cheapest();
  ASSERT_TRUE(best.has_value());
  int meeting_loose = 0, meeting_tight = 0;
  for (const Trial& trial : loose.trials()) {
    EXPECT_EQ(trial.meets, trial.error <= 1.0 && trial.fails.empty()) << describe(trial.settings);
    if (trial.meets) {
      EXPECT_GE(trial.cost, best->cost) << describe(trial.settings);
    }
    meeting_loose += trial.meets;
  }
  for (const Trial& trial : tight.trials()) meeting_tight += trial.meets;
  EXPECT_GT(meeting_tight, 0);
  EXPECT_LT(meeting_tight, meeting_loose);
}

// A name that is no lesson is refused with the built-in lessons listed, from the folder.
TEST(LessonBenchmark, AnUnknownLessonListsTheBuiltInOnes) {
  try {
    lesson_problem("ramp");
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& error) {
    for (const std::string& name : builtin_lessons()) EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << name;
  }
}

// The window measures at its sliders' values: they come back as the same numbers and choices.
TEST(LessonBenchmark, TheSlidersValuesAreTheLessonsParameters) {
  Lesson lesson(resolve_lesson("spring_pull"), {{"k", "123.456"}, {"block", "plastic"}});
  const auto values = parameter_values(lesson);
  EXPECT_EQ(values.at("k"), "123.456");
  EXPECT_EQ(values.at("block"), "plastic");
  Lesson again(resolve_lesson("spring_pull"), values);
  EXPECT_EQ(again.parameter("k").value, 123.456);
}

}  // namespace
}  // namespace frictionlab::lessons
