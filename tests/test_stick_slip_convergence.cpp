// The driven spring–block on Box2D against the exact event-driven solution: the stick-slip
// treatment converges as the step halves; the velocity threshold and Box2D's single
// coefficient stall, so the comparison is real.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "physics/scenarios.h"

using namespace frictionlab;

namespace {
const double duration = 10.0;
const double rates[] = {60, 120, 240, 480, 960};

std::map<double, double> errors_for(FrictionTreatment treatment) {
  std::map<double, double> errors;
  for (double hz : rates) {
    StepSettings settings;
    settings.hz = hz;
    settings.treatment = treatment;
    errors[hz] = spring_pull_max_error(SpringPull{}, settings, duration);
  }
  return errors;
}
}  // namespace

TEST(StickSlipConvergence, ErrorShrinksAsTheStepHalves) {
  const auto errors = errors_for(FrictionTreatment::stick_slip);
  for (double hz : rates) RecordProperty("max_error_m_at_" + std::to_string(static_cast<int>(hz)) + "_hz", std::to_string(errors.at(hz)));
  for (size_t i = 1; i < std::size(rates); ++i) {
    EXPECT_LT(errors.at(rates[i]), errors.at(rates[i - 1]))
        << rates[i] << " Hz should beat " << rates[i - 1] << " Hz";
  }
  EXPECT_LE(errors.at(240), 0.005) << "the issue's bound at 240 Hz, m";
  EXPECT_LE(errors.at(240), 0.001) << "the goal at 240 Hz, m";
  // Second order: the breakaway is placed inside its step and the start is leapfrog-true, so
  // each halving should divide the error by about four. A first-order treatment (the
  // breakaway left at a step boundary) divides it by about two and fails this.
  const double order = std::log2(errors.at(60) / errors.at(960)) / 4.0;
  RecordProperty("fitted_order", std::to_string(order));
  EXPECT_GT(order, 1.7) << "fitted order of convergence from 60 to 960 Hz";
}

TEST(StickSlipConvergence, ThresholdSwitchStalls) {
  const auto stick_slip = errors_for(FrictionTreatment::stick_slip);
  const auto threshold = errors_for(FrictionTreatment::threshold);
  EXPECT_GT(threshold.at(960), 0.5 * threshold.at(240)) << "halving the step twice barely helps";
  EXPECT_GT(threshold.at(960), 5.0 * stick_slip.at(960));
}

TEST(StickSlipConvergence, SingleCoefficientStalls) {
  const auto stick_slip = errors_for(FrictionTreatment::stick_slip);
  const auto box2d = errors_for(FrictionTreatment::box2d);
  EXPECT_GT(box2d.at(960), 0.5 * box2d.at(240));
  EXPECT_GT(box2d.at(960), 5.0 * stick_slip.at(960));
}

// The whole range --hz accepts, up to 100 000 Hz. The breakaway is declared within a relative
// 1e-5 of the limit, so at fine steps a block often breaks away in a step its friction still
// held, with round-off for a velocity: its slip direction taken from that velocity's sign was
// wrong half the time, and the next step read a reversal and stuck again (from 10 000 Hz the
// re-stick force was 2.85 N against 2.45 N, and the period 0.81 s against 1.01 s). Every
// reading stays within the lesson's tolerances. The position error no longer shrinks past
// about 1 kHz: Box2D keeps positions in single precision, and at 100 kHz a step moves the block
// about a micrometre, ten float spacings at 1 m, so rounding sets a floor (0.02 to 0.6 mm
// measured from 960 to 100 000 Hz); it stays within the 1 mm goal at 240 Hz.
TEST(StickSlipConvergence, StaysRightAcrossTheAcceptedStepRates) {
  for (double hz : {9500.0, 10000.0, 30000.0, 100000.0}) {
    StepSettings settings;
    settings.hz = hz;
    for (const Measurement& row : spring_pull_measurements(SpringPull{}, settings, duration)) {
      EXPECT_LE(std::abs(row.measured - row.predicted), row.tolerance)
          << row.name << " at " << hz << " Hz: predicted " << row.predicted << ", measured " << row.measured;
      if (row.name == "stick-slip max position error") {
        RecordProperty("max_error_m_at_" + std::to_string(static_cast<int>(hz)) + "_hz", std::to_string(row.measured));
        EXPECT_LE(row.measured, 0.001) << hz << " Hz";
      }
    }
  }
}

// Kinetic friction a tenth of static: after each slip the spring, pushing back, stops the block
// at (2·mu_k - mu_s)·m·g, within the static limit, and it holds. The solver leaves kinetic
// friction on to the end of the step in which the block stops, and the block moving back;
// undoing that in the next step asked friction for more than mu_s·N, whatever the step, and
// the block broke away backwards at once (re-stick -0.27 N for -0.78 N, period 0.54 s for
// 0.99 s at 240 Hz, as wrong at any step). The stop is now finished as Coulomb's law says. (The
// rates are fine enough for the breakaway to be within 1 % without the lesson's step term.)
TEST(StickSlipConvergence, HoldsWhereTheSpringStopsItWithLittleKineticFriction) {
  SpringPull setup;
  setup.block.pair.mu_s = 0.1;
  setup.block.pair.mu_k = 0.01;
  for (double hz : {960.0, 3840.0}) {
    StepSettings settings;
    settings.hz = hz;
    for (const Measurement& row : spring_pull_measurements(setup, settings, duration)) {
      EXPECT_LE(std::abs(row.measured - row.predicted), row.tolerance)
          << row.name << " at " << hz << " Hz: predicted " << row.predicted << ", measured " << row.measured;
    }
  }
}
