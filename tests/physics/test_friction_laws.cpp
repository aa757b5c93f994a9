#include <gtest/gtest.h>

#include <cmath>

#include "physics/friction_laws.h"

using namespace frictionlab;

namespace {
const FrictionPair dry{0.6, 0.4, 0.0, 0.0};
const double normal = 10.0;
}  // namespace

TEST(EngineeringModel, StaticFrictionCancelsThePushUpToTheLimit) {
  for (double push : {0.0, 1.0, -3.5, 5.999}) {
    const FrictionOutcome f = engineering_friction(push, normal, 0.0, dry);
    EXPECT_DOUBLE_EQ(f.force, -push);
    EXPECT_EQ(f.state, ContactState::sticking);
  }
}

TEST(EngineeringModel, BreaksAwayAboveMuSN) {
  const FrictionOutcome f = engineering_friction(7.0, normal, 0.0, dry);
  EXPECT_DOUBLE_EQ(f.force, -6.0);
  EXPECT_EQ(f.state, ContactState::slipping);
  EXPECT_DOUBLE_EQ(engineering_friction(-7.0, normal, 0.0, dry).force, 6.0);
}

TEST(EngineeringModel, KineticOpposesVelocityWhateverThePush) {
  const FrictionPair wet{0.6, 0.4, 2.0, 0.5};
  // -mu_k N sign v - c v - b v^2 sign v at v = 3: -4 - 6 - 4.5
  EXPECT_DOUBLE_EQ(engineering_friction(100.0, normal, 3.0, wet).force, -14.5);
  EXPECT_DOUBLE_EQ(engineering_friction(-100.0, normal, -3.0, wet).force, 14.5);
}

TEST(RegularizedLaw, IsLinearBelowEpsilonAndKineticAbove) {
  const double epsilon = 0.1;
  EXPECT_DOUBLE_EQ(regularized_friction(0.05, normal, epsilon, dry), -3.0);  // mu_s N v / eps
  EXPECT_DOUBLE_EQ(regularized_friction(-0.05, normal, epsilon, dry), 3.0);
  EXPECT_DOUBLE_EQ(regularized_friction(0.0, normal, epsilon, dry), 0.0);
  EXPECT_DOUBLE_EQ(regularized_friction(0.5, normal, epsilon, dry), -4.0);
}

TEST(DampedVelocity, NeverReversesOrGrowsAtAnyStep) {
  const FrictionPair wet{0.0, 0.0, 50.0, 10.0};
  for (double h : {1e-4, 1e-2, 1.0, 100.0}) {
    for (double v : {-5.0, -0.1, 0.1, 5.0}) {
      const double after = damped_velocity(v, 0.5, h, wet);
      EXPECT_GE(after * v, 0.0) << "h=" << h << " v=" << v;  // may underflow to 0, never past it
      EXPECT_LT(std::abs(after), std::abs(v));
    }
  }
}

TEST(DampedVelocity, IsTheExactSolutionOfTheDragEquation) {
  // Viscous alone: v0·exp(-c t/m), whatever the number of steps it is cut into.
  const FrictionPair viscous{0.0, 0.0, 2.0, 0.0};
  for (int steps : {1, 7, 240}) {
    double v = 1.5;
    for (int i = 0; i < steps; ++i) v = damped_velocity(v, 0.5, 1.0 / steps, viscous);
    EXPECT_NEAR(v, 1.5 * std::exp(-2.0 / 0.5), 1e-12);
  }
  // Quadratic alone: v0 / (1 + b v0 t / m).
  const FrictionPair quadratic{0.0, 0.0, 0.0, 3.0};
  EXPECT_NEAR(damped_velocity(-2.0, 1.0, 0.5, quadratic), -2.0 / (1.0 + 3.0 * 2.0 * 0.5), 1e-12);
  // Both: compare with a fine RK4 integration of m v' = -c v - b v |v|.
  const FrictionPair both{0.0, 0.0, 1.3, 0.7};
  const double m = 0.8;
  double v = 2.0;
  const int n = 20000;
  const double dt = 1.0 / n;
  auto accel = [&](double u) { return (-both.c * u - both.b * u * std::abs(u)) / m; };
  for (int i = 0; i < n; ++i) {
    const double k1 = accel(v), k2 = accel(v + 0.5 * dt * k1), k3 = accel(v + 0.5 * dt * k2), k4 = accel(v + dt * k3);
    v += dt * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0;
  }
  EXPECT_NEAR(damped_velocity(2.0, m, 1.0, both), v, 1e-10);
}
