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

}  // namespace
}  // namespace frictionlab
