// The energy ledger: what went in (applied work), where it went (kinetic, potential,
// spring) and what friction took, closing to within 1 % of the energy dissipated.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/closed_forms.h"
#include "physics/scenarios.h"

using namespace frictionlab;

TEST(EnergyLedger, ClosesForStickSlip) {
  auto scene = make_spring_pull(SpringPull{}, StepSettings{});
  for (int i = 0; i < 2400; ++i) scene->step();
  const EnergyLedger& e = scene->ledger();
  ASSERT_GT(e.dissipated(), 1.0) << "ten seconds of stick-slip dissipate joules";
  EXPECT_LT(std::abs(e.residual()), 0.01 * e.dissipated()) << "residual " << e.residual() << " J";
  EXPECT_GT(e.work_applied, 0.0) << "the hand does the work";
  EXPECT_LE(e.work_friction, 0.0);
}

TEST(EnergyLedger, ClosesOnTheInclineAndFrictionWorkIsMuKNTimesDistance) {
  Incline incline;
  incline.angle = 40.0 * M_PI / 180.0;
  auto scene = make_incline(incline, StepSettings{});
  for (int i = 0; i < 720; ++i) scene->step();
  const EnergyLedger& e = scene->ledger();
  EXPECT_LT(std::abs(e.residual()), 0.01 * e.dissipated()) << "residual " << e.residual() << " J";
  const double distance = scene->probe("distance").history.back();
  const double expected = -incline.block.pair.mu_k * incline.block.mass * standard_gravity * std::cos(incline.angle) * distance;
  EXPECT_NEAR(e.work_friction, expected, 0.01 * std::abs(expected));
  EXPECT_NEAR(e.potential, -incline.block.mass * standard_gravity * std::sin(incline.angle) * distance,
              0.001 * incline.block.mass * standard_gravity * distance);
}

TEST(EnergyLedger, DampingWorkIsBookedSeparately) {
  Slide slide;
  slide.block.pair = {0.0, 0.0, 2.0, 0.0};
  auto scene = make_slide(slide, StepSettings{});
  for (int i = 0; i < 960; ++i) scene->step();
  const EnergyLedger& e = scene->ledger();
  EXPECT_NEAR(e.work_friction, 0.0, 1e-9) << "mu = 0: no dry friction";
  EXPECT_NEAR(-e.work_damping, e.initial - e.kinetic, 1e-3) << "all the kinetic energy lost went to damping";
  EXPECT_LT(std::abs(e.residual()), 0.01 * e.dissipated());
}
