// Where the game-style methods fail, against linear stability theory: the regularized law's
// boundary h = 2·epsilon/(mu_s·g) for both Euler methods (2.785 for RK4), the creep a large
// epsilon causes on a slope, and the viscous term applied explicitly or exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/cheapest_setting.h"
#include "physics/stability.h"

namespace frictionlab {
namespace {

const FrictionPair wood_on_wood{0.5, 0.4, 0.0, 0.0};
constexpr double g = 9.81;

class Boundary : public ::testing::TestWithParam<Integrator> {};

TEST_P(Boundary, MeasuredWithinTenPercentOfLinearTheory) {
  for (const double epsilon : {1e-3, 1e-2, 1e-1}) {
    const double theory = theoretical_boundary(wood_on_wood, g, epsilon, GetParam());
    const double measured = measured_boundary(wood_on_wood, g, epsilon, GetParam());
    EXPECT_NEAR(measured / theory, 1.0, 0.10) << "epsilon = " << epsilon << ": theory " << theory << " s, measured "
                                               << measured << " s";
    // Either side of it, well away: settles, and chatters for ever.
    EXPECT_EQ(classify_regularized(wood_on_wood, g, 0.7 * theory, epsilon, GetParam()), Behaviour::stable);
    EXPECT_EQ(classify_regularized(wood_on_wood, g, 1.4 * theory, epsilon, GetParam()), Behaviour::chattering);
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, Boundary,
                         ::testing::Values(Integrator::explicit_euler, Integrator::semi_implicit_euler, Integrator::rk4));

TEST(Boundary, EulerAtTwoAndRk4AtItsRealStabilityLimit) {
  // h·mu_s·g/epsilon at the boundary: 2 for Euler; for RK4 the real root of |R(-z)| = 1.
  const double scale = wood_on_wood.mu_s * g / 0.01;
  EXPECT_NEAR(theoretical_boundary(wood_on_wood, g, 0.01, Integrator::explicit_euler) * scale, 2.0, 1e-12);
  EXPECT_NEAR(theoretical_boundary(wood_on_wood, g, 0.01, Integrator::rk4) * scale, 2.7853, 1e-4);
}

TEST(Creep, ALargeThresholdLetsABlockCreepDownASlopeItShouldStickTo) {
  const double angle = 20.0 * M_PI / 180.0;  // tan 20° = 0.36 < mu_s = 0.5: Coulomb's block sticks
  for (const double epsilon : {0.01, 0.05, 0.2}) {
    const double h = 0.2 * theoretical_boundary(wood_on_wood, g, epsilon, Integrator::semi_implicit_euler);
    const double creep = creep_speed(wood_on_wood, g, angle, epsilon, h, Integrator::semi_implicit_euler);
    EXPECT_NEAR(creep, theoretical_creep_speed(wood_on_wood, angle, epsilon), 1e-3 * creep) << "epsilon = " << epsilon;
    EXPECT_GT(creep, 0.0);
  }
  // 0.2 m/s threshold: the "stuck" block slides 1.5 m in ten seconds.
  EXPECT_NEAR(10.0 * theoretical_creep_speed(wood_on_wood, angle, 0.2), 1.456, 0.001);
}

TEST(Viscous, AnExplicitForceDivergesPastTwoAndTheExactStepNever) {
  EXPECT_EQ(classify_velocities(viscous_explicit(0.5, 200)), Behaviour::stable);
  const std::vector<double> reversing = viscous_explicit(1.5, 200);
  EXPECT_LT(reversing[1], 0.0);  // past 1 the velocity reverses in one step: unphysical
  EXPECT_EQ(classify_velocities(reversing), Behaviour::stable);
  EXPECT_EQ(classify_velocities(viscous_explicit(2.5, 200)), Behaviour::divergent);
  // The boundary, by bisection on what the steps do.
  double low = 0.5, high = 4.0;
  while (high - low > 1e-6) {
    const double middle = 0.5 * (low + high);
    (classify_velocities(viscous_explicit(middle, 400)) == Behaviour::stable ? low : high) = middle;
  }
  EXPECT_NEAR(low, 2.0, 0.2);
  for (const double ratio : {0.5, 2.5, 10.0, 1000.0}) {
    const std::vector<double> exact = viscous_exact(ratio, 50);
    for (std::size_t i = 1; i < exact.size(); ++i) {
      EXPECT_GE(exact[i], 0.0) << "reversed at h·c/m = " << ratio;
      EXPECT_LE(exact[i], exact[i - 1]);
    }
    EXPECT_NEAR(exact[1], std::exp(-ratio), 1e-15);
  }
}

TEST(StabilityMap, CellsBelowTheBoundarySettleAndAboveChatter) {
  const std::vector<double> steps = logarithmic_range(1e-4, 1e-1, 13);
  const std::vector<double> epsilons = logarithmic_range(1e-3, 1e-1, 9);
  for (const Integrator integrator : {Integrator::explicit_euler, Integrator::semi_implicit_euler, Integrator::rk4}) {
    int disagreements = 0, judged = 0;
    for (const StabilityCell& cell : stability_map(wood_on_wood, g, integrator, steps, epsilons)) {
      const double boundary = theoretical_boundary(wood_on_wood, g, cell.epsilon, cell.integrator);
      if (std::abs(std::log(cell.h / boundary)) < std::log(1.1)) continue;  // on the line: either
      const Behaviour expected = cell.h < boundary ? Behaviour::stable : Behaviour::chattering;
      disagreements += cell.behaviour != expected;
      ++judged;
    }
    EXPECT_EQ(disagreements, 0) << "integrator " << static_cast<int>(integrator);
    EXPECT_GT(judged, 90);
  }
}

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
// problems are tested in test_lesson_benchmark).
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

// Every benchmark problem has an exact answer the stick-slip treatment approaches as the step
// halves (or meets exactly), without a failure, and the slope a degree below its sticking
// angle tells the treatments apart.
TEST(BenchmarkProblems, StickSlipConvergesOnEachAndHoldsTheSlopeTheOthersLetGo) {
  const std::vector<BenchmarkProblem> problems = benchmark_problems();
  ASSERT_EQ(problems.size(), 8u);
  StepSettings coarse, fine;
  fine.hz = 480;
  for (const BenchmarkProblem& problem : problems) {
    const Outcome at_240 = problem.run(coarse), at_480 = problem.run(fine);
    EXPECT_TRUE(std::isfinite(at_240.error)) << problem.name;
    EXPECT_EQ(at_240.fails, "") << problem.name;
    EXPECT_LE(at_480.error, at_240.error + 1e-12) << problem.name << ": halving the step made it worse";
  }
  const BenchmarkProblem& holds = problems[2];
  ASSERT_EQ(holds.name, "Incline 30\u00b0: just below, it sticks");
  EXPECT_EQ(holds.error(coarse), 0.0);
  StepSettings box2d, regularized;
  box2d.treatment = FrictionTreatment::box2d;
  regularized.treatment = FrictionTreatment::regularized;
  // One coefficient (mu_k = 0.4 < tan 30° = 0.58) cannot hold it: it slides ½·g·(sin − mu_k·cos)·t²
  // = 3.01 m in 2 s.
  const double slid = 0.5 * 9.81 * (std::sin(M_PI / 6) - 0.4 * std::cos(M_PI / 6)) * 4.0;
  const Outcome one_mu = holds.run(box2d);
  EXPECT_NEAR(one_mu.error, slid, 0.02 * slid);
  EXPECT_EQ(one_mu.fails, "slides");
  // The regularized law at 240 Hz with epsilon = 0.01 m/s is past its boundary on this slope
  // (2·eps/(mu_s·g·cos 30°) = 3.9 ms < 4.2 ms): its chatter carries it past epsilon, where
  // friction drops to mu_k, and away.
  EXPECT_EQ(holds.run(regularized).fails, "slides");
  // With a large epsilon it is stable but creeps at epsilon·tan θ/mu_s instead of sticking.
  regularized.threshold_speed = 0.1;
  const Outcome crept = holds.run(regularized);
  EXPECT_EQ(crept.fails, "creeps");
  EXPECT_NEAR(crept.error, 0.1 * std::tan(M_PI / 6) / 0.6 * 2.0, 0.05 * 0.19);
}

}  // namespace
}  // namespace frictionlab
