// The cheapest setting that answers a problem within a tolerance, and the bench's own problems
// it is tried on (bench/cheapest_setting.h).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "bench/cheapest_setting.h"

namespace frictionlab {
namespace {

// The cheapest setting that answers a problem (here the bench's own slope a degree above its
// sticking angle): the one the recommender names meets the tolerance and costs no more than any
// other that does.
TEST(Recommend, TheCheapestSettingMeetsTheToleranceAndNothingThatMeetsItIsCheaper) {
  Recommender recommender(incline_slides_problem(), 0.001, 1);
  recommender.run_all();
  EXPECT_EQ(recommender.trials().size(), 4u * 7u * 3u);
  const std::optional<Trial> best = recommender.cheapest();
  ASSERT_TRUE(best.has_value());
  EXPECT_LE(best->error, 0.001);
  int meeting = 0;
  for (const Trial& trial : recommender.trials()) {
    if (trial.meets) {
      ++meeting;
      EXPECT_GE(trial.cost, best->cost) << describe(trial.settings);
    }
    EXPECT_EQ(trial.meets, trial.error <= 0.001 && trial.fails.empty());
  }
  EXPECT_GT(meeting, 1);
  // 1 mm over a 3.7 m slide is out of the default's reach (the release step still holds with
  // mu_s, a lag of a·h that grows with t): halving the step halves the error.
  StepSettings settings;
  const double at_240 = incline_slides_problem().error(settings);
  settings.hz = 480;
  const double at_480 = incline_slides_problem().error(settings);
  EXPECT_GT(at_240, 0.001);
  EXPECT_NEAR(at_240 / at_480, 2.0, 0.3);
}

// The bench's own tipping push and 20° slope tell the treatments apart (the lessons' own
// problems are tested in test_lesson_problem).
TEST(Recommend, TheBenchsOwnProblemsTellTheTreatmentsApart) {
  // The box pushed above d/(2 mu_s) tips at m g d/(2 h) = 35.0 N and pushed below slides at
  // mu_s m g = 49.05 N: within 0.1 N at 240 Hz, and the error falls with the step (the tipping
  // push is placed where the back edge's load reaches zero).
  StepSettings fine;
  fine.hz = 960;
  const BenchmarkProblem tipping = tipping_push_problem();
  const double at_240 = tipping.error(StepSettings{});
  EXPECT_LT(at_240, 0.1);
  EXPECT_LT(tipping.error(fine), 0.5 * at_240);
  // One coefficient tips the box right but lets it slide at mu_k m g: 0.1 × 98.1 N early.
  StepSettings one_mu;
  one_mu.treatment = FrictionTreatment::box2d;
  EXPECT_NEAR(tipping.error(one_mu), 0.1 * 98.1, 0.2);
  // On a 20° slope every treatment that holds with a coefficient keeps the block
  // still; the regularized law with its default epsilon creeps or slides.
  const BenchmarkProblem holds = incline_sticks_problem(20.0 * M_PI / 180.0);
  EXPECT_EQ(holds.run(StepSettings{}).fails, "");
  StepSettings regularized;
  regularized.treatment = FrictionTreatment::regularized;
  EXPECT_NE(holds.run(regularized).fails, "");
}

}  // namespace
}  // namespace frictionlab
