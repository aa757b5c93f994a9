// The benchmark problems, each with an exact answer (bench/problems.h), and how a run of one
// fails: named, not dropped, and never meeting the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bench/cheapest_setting.h"
#include "bench/problems.h"

namespace frictionlab {
namespace {

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

// The spring problem in Box2D with the regularized law: a step a fifth inside the boundary
// 2·eps/(mu_s·g) does not chatter, a quarter past it does; Box2D's single coefficient stops
// the block more often than Coulomb's (it touches rest each period of the spring); a large
// epsilon creeps through the sticks and misses them.
TEST(FailedRuns, TheSpringProblemNamesHowEachTreatmentFails) {
  const BenchmarkProblem spring = spring_problem();
  StepSettings settings;
  settings.treatment = FrictionTreatment::regularized;
  settings.threshold_speed = 0.01;
  const double boundary = 2.0 * settings.threshold_speed / (0.6 * 9.81);
  settings.hz = 1.0 / (0.8 * boundary);
  EXPECT_NE(spring.run(settings).fails, "chatters") << settings.hz << " Hz";
  settings.hz = 1.0 / (1.25 * boundary);
  EXPECT_EQ(spring.run(settings).fails, "chatters") << settings.hz << " Hz";
  // The same world step as 240 Hz, in two sub-steps a frame: a flip every sub-step shows as
  // no flip at all in the frames, so the check watches every sub-step.
  settings.hz = 120;
  settings.substeps = 2;
  EXPECT_EQ(spring.run(settings).fails, "chatters");
  settings.substeps = 1;
  settings.hz = 240.0;
  settings.threshold_speed = 0.1;
  EXPECT_EQ(spring.run(settings).fails, "misses stick-slip");
  settings.treatment = FrictionTreatment::box2d;
  EXPECT_EQ(spring.run(settings).fails, "spurious stick-slip");
  settings.treatment = FrictionTreatment::stick_slip;
  EXPECT_EQ(spring.run(settings).fails, "");
}

// A run that gets the number within the tolerance with the physics wrong does not meet it:
// box2d is within 5 cm on the spring, by a block that stops every period of the spring.
TEST(FailedRuns, AFailedRunNeverMeetsTheTolerance) {
  StepSettings one_mu;
  one_mu.treatment = FrictionTreatment::box2d;
  one_mu.hz = 60;
  const Trial trial = measure_setting(spring_problem(), one_mu, 1, 0.05);
  EXPECT_LT(trial.error, 0.05);
  EXPECT_EQ(trial.fails, "spurious stick-slip");
  EXPECT_FALSE(trial.meets);
}

// The reduced models answer every problem that is a block on a line: RK4 between located
// events to well under a micrometre, explicit Euler with the regularized law chattering once
// the block has come to rest exactly when its step passes 2·eps/(mu_s·g).
TEST(FailedRuns, ReducedModelsOnEveryLineProblem) {
  int lines = 0;
  for (const BenchmarkProblem& problem : benchmark_problems()) {
    if (!problem.line) continue;
    ++lines;
    const Outcome located = run_reduced(*problem.line, ReducedMethod::located_events, 240.0, 0.01);
    EXPECT_LT(located.error, 1e-6) << problem.name;
    EXPECT_EQ(located.fails, "") << problem.name;
  }
  EXPECT_EQ(lines, 5);
  const LineProblem slide = *benchmark_problems()[3].line;
  ASSERT_GT(slide.block.pair.c, 0.0);
  const double epsilon = 0.01, boundary = 2.0 * epsilon / (0.6 * 9.81);
  EXPECT_EQ(run_reduced(slide, ReducedMethod::explicit_euler, 1.0 / (0.9 * boundary), epsilon).fails, "");
  EXPECT_EQ(run_reduced(slide, ReducedMethod::explicit_euler, 1.0 / (1.1 * boundary), epsilon).fails, "chatters");
}

}  // namespace
}  // namespace frictionlab
