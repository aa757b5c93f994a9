// The reduced 1-DOF solvers: the exact event-driven solver against the event-driven RK4 one and
// the closed forms, and the fixed-step game-style integrators' convergence and failures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "physics/closed_forms.h"
#include "physics/reduced_model.h"
#include "tests/assertions.h"

namespace frictionlab {
namespace {

constexpr double g = 9.81;


// The suggested standard problem: 1 kg pulled by a 50 N/m spring at 0.1 m/s, μs 0.6, μk 0.4.
OneDofBlock spring_block(double c = 0.0) {
  OneDofBlock block;
  block.mass = 1.0;
  block.normal_force = 1.0 * g;
  block.pair = {0.6, 0.4, c, 0.0};
  block.spring_k = 50.0;
  block.pull_speed = 0.1;
  return block;
}

double max_position_difference(const Trajectory& a, const Trajectory& b, double t_end) {
  double worst = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    const double t = t_end * i / 20000.0;
    worst = std::max(worst, std::abs(a.position(t) - b.position(t)));
  }
  for (const Event& e : a.events()) worst = std::max(worst, std::abs(a.position(e.t) - b.position(e.t)));
  return worst;
}

std::vector<Event> events_of(const Trajectory& trajectory, EventKind kind) {
  std::vector<Event> found;
  for (const Event& e : trajectory.events())
    if (e.kind == kind) found.push_back(e);
  return found;
}

TEST(ReducedModel, ExactAndEventRk4AgreeOnStickSlip) {
  // Undamped, lightly damped, critically damped (c² = 4mk) and overdamped slipping; and pulled
  // the other way, so that it slips left.
  for (const double c : {0.0, 0.5, std::sqrt(200.0), 30.0, -0.5}) {
    OneDofBlock block = spring_block(std::abs(c));
    if (c < 0.0) block.pull_speed = -0.2;
    const Trajectory exact = solve_exact(block, 10.0);
    const Trajectory numeric = solve_event_rk4(block, 10.0, 1e-4);
    EXPECT_LT(max_position_difference(exact, numeric, 10.0), 1e-7) << "c " << c;
    ASSERT_EQ(exact.events().size(), numeric.events().size()) << "c " << c;
    for (std::size_t i = 0; i < exact.events().size(); ++i) {
      EXPECT_EQ(exact.events()[i].kind, numeric.events()[i].kind) << "c " << c << " event " << i;
      EXPECT_NEAR(exact.events()[i].t, numeric.events()[i].t, 1e-8) << "c " << c << " event " << i;
    }
    if (c * c < 4.0 * block.mass * block.spring_k) {
      EXPECT_GE(events_of(exact, EventKind::stop).size(), 3u) << "c " << c << ": still sticks and slips";
    } else {
      // Overdamped, the velocity rises towards the pull speed without overshoot and can never
      // come back down to zero: one breakaway, then steady sliding.
      EXPECT_EQ(exact.events().size(), 2u) << "c " << c;
    }
  }
}

TEST(ReducedModel, ExactAndEventRk4AgreeOnLaunchedSpringAtAnyDamping) {
  // Launched at 3 m/s against an unmoving spring: the stop (and any reversal) comes inside an
  // under-, critically or overdamped phase, or in a drift with no spring at all.
  // (k = 16, c = 8 is critical with c² = 4mk exactly, not merely to rounding.)
  struct Spring {
    double k, c;
  };
  for (const Spring spring : {Spring{50, 0}, Spring{50, 5}, Spring{16, 8}, Spring{50, 30}, Spring{50, 300},
                              Spring{0, 0}, Spring{0, 5}, Spring{0, 300}}) {
    OneDofBlock block = spring_block(spring.c);
    block.spring_k = spring.k;
    block.pull_speed = 0.0;
    block.v0 = 3.0;
    const Trajectory exact = solve_exact(block, 5.0);
    const Trajectory numeric = solve_event_rk4(block, 5.0, 1e-4);
    const std::string label = "k " + std::to_string(spring.k) + " c " + std::to_string(spring.c);
    EXPECT_LT(max_position_difference(exact, numeric, 5.0), 1e-7) << label;
    ASSERT_EQ(exact.events().size(), numeric.events().size()) << label;
    EXPECT_GE(exact.events().size(), 2u) << label << ": it stops or turns";
    for (std::size_t i = 0; i < exact.events().size(); ++i) {
      EXPECT_EQ(exact.events()[i].kind, numeric.events()[i].kind) << label << " event " << i;
      EXPECT_NEAR(exact.events()[i].t, numeric.events()[i].t, 1e-8) << label << " event " << i;
    }
  }
}

TEST(ReducedModel, ExactReproducesClosedFormStickSlip) {
  const OneDofBlock block = spring_block();
  const theory::StickSlip theory = theory::spring_stick_slip(1.0, 50.0, 0.1, 0.6, 0.4, g);
  const Trajectory exact = solve_exact(block, 10.0);
  const std::vector<Event> breakaways = events_of(exact, EventKind::breakaway);
  const std::vector<Event> stops = events_of(exact, EventKind::stop);
  ASSERT_GE(breakaways.size(), 5u);
  EXPECT_RELATIVE(breakaways[0].t, theory.first_breakaway_time, 1e-9);
  for (std::size_t i = 0; i + 1 < breakaways.size(); ++i) {
    EXPECT_RELATIVE(breakaways[i + 1].t - breakaways[i].t, theory.period, 1e-9) << "cycle " << i;
    EXPECT_RELATIVE(stops[i].t - breakaways[i].t, theory.slip_duration, 1e-9) << "cycle " << i;
    EXPECT_RELATIVE(applied_force(block, stops[i].t, stops[i].x), theory.restick_force, 1e-9) << "cycle " << i;
    EXPECT_RELATIVE(breakaways[i + 1].x - breakaways[i].x, theory.slip_distance, 1e-9) << "cycle " << i;
  }
  // Between events the phases say what the block does, and the state is continuous across them.
  for (const Phase& phase : exact.phases()) {
    const double middle = 0.5 * (phase.t_start + phase.t_end);
    if (phase.kind == PhaseKind::stick) {
      EXPECT_EQ(exact.velocity(middle), 0.0);
    } else {
      EXPECT_EQ(phase.kind, PhaseKind::slip_right);
      EXPECT_GT(exact.velocity(middle), 0.0);
    }
  }
}

// A light block behind a fast hand (spring_pull at mass 0.1 kg, k 107 N/m, 0.5 m/s): its speed
// touches zero for a sliver of each swing, a 5 ms stick in a 0.19 s cycle, between two points
// of the stop search's scan. Every one of those stops is still found: the cycle is the closed
// form's, not twice it.
TEST(ReducedModel, ExactFindsAStopThatOnlyTouchesZeroBetweenScanPoints) {
  OneDofBlock block = spring_block();
  block.mass = 0.1;
  block.normal_force = 0.1 * g;
  block.spring_k = 107.0;
  block.pull_speed = 0.5;
  block.pair = {0.7073, 0.5686, 0.0, 0.0};
  const theory::StickSlip theory = theory::spring_stick_slip(0.1, 107.0, 0.5, 0.7073, 0.5686, g);
  ASSERT_LT(theory.stick_duration, 0.03 * theory.period);
  const Trajectory exact = solve_exact(block, 1.5);
  const std::vector<Event> breakaways = events_of(exact, EventKind::breakaway);
  ASSERT_GE(breakaways.size(), 7u);
  for (std::size_t i = 0; i + 1 < breakaways.size(); ++i) {
    EXPECT_RELATIVE(breakaways[i + 1].t - breakaways[i].t, theory.period, 1e-6) << "cycle " << i;
  }
}

TEST(ReducedModel, FreeOscillationReversesUntilStaticFrictionHolds) {
  // Released 0.5 m from the spring's rest point: each half swing is centred on ±μk N/k and
  // loses 2 μk N / k of amplitude, taking π/ω; it stops at the first turn where k|x| <= μs N.
  OneDofBlock block;
  block.normal_force = g;
  block.pair = {0.3, 0.2, 0.0, 0.0};
  block.spring_k = 50.0;
  block.x0 = 0.5;
  const double loss = 2.0 * 0.2 * g / 50.0, half_swing = std::numbers::pi / std::sqrt(50.0);
  for (const bool exact_solver : {true, false}) {
    const Trajectory trajectory = exact_solver ? solve_exact(block, 5.0) : solve_event_rk4(block, 5.0, 1e-4);
    const std::vector<Event>& events = trajectory.events();
    ASSERT_EQ(events.size(), 8u);  // breakaway, 5 reversals, stop, end
    EXPECT_EQ(events[0].kind, EventKind::breakaway);
    double amplitude = 0.5, sign = 1.0;
    for (int n = 1; n <= 6; ++n) {
      amplitude -= loss;
      sign = -sign;
      EXPECT_EQ(events[n].kind, n < 6 ? EventKind::reversal : EventKind::stop) << "turn " << n;
      EXPECT_NEAR(events[n].x, sign * amplitude, 1e-10) << "turn " << n;
      EXPECT_NEAR(events[n].t, n * half_swing, 1e-10) << "turn " << n;
    }
    EXPECT_NEAR(trajectory.position(5.0), events[6].x, 1e-15);
  }
}

TEST(ReducedModel, InclineMatchesClosedFormsAndShallowInclineHolds) {
  const double mass = 2.0;
  for (const double c : {0.0, 1.2}) {
    const double angle = 0.6;
    OneDofBlock block;
    block.mass = mass;
    block.normal_force = mass * g * std::cos(angle);
    block.constant_force = mass * g * std::sin(angle);
    block.pair = {0.5, 0.3, c, 0.0};
    const Trajectory exact = solve_exact(block, 3.0);
    for (const double t : {0.1, 1.0, 3.0}) {
      EXPECT_RELATIVE(exact.velocity(t), theory::incline_speed(angle, 0.3, c, mass, g, t), 1e-12);
      EXPECT_RELATIVE(exact.position(t), theory::incline_distance(angle, 0.3, c, mass, g, t), 1e-12);
    }
  }
  OneDofBlock shallow;
  shallow.normal_force = g * std::cos(0.4);
  shallow.constant_force = g * std::sin(0.4);
  shallow.pair = {0.5, 0.3, 0.0, 0.0};  // tan 0.4 = 0.42 < 0.5
  const Trajectory held = solve_exact(shallow, 3.0);
  ASSERT_EQ(held.events().size(), 1u);
  EXPECT_EQ(held.events()[0].kind, EventKind::end);
  EXPECT_EQ(held.position(3.0), 0.0);
}

TEST(ReducedModel, LaunchedBlockSlidesToRestAndStays) {
  OneDofBlock block;
  block.mass = 2.0;
  block.normal_force = 2.0 * g;
  block.pair = {0.5, 0.3, 0.7, 0.0};
  block.v0 = -3.0;
  const theory::SlideToRest theory = theory::slide_to_rest(-3.0, 2.0, block.pair, g);
  const Trajectory exact = solve_exact(block, 5.0);
  ASSERT_EQ(exact.events().size(), 2u);
  EXPECT_EQ(exact.events()[0].kind, EventKind::stop);
  EXPECT_RELATIVE(exact.events()[0].t, theory.time, 1e-12);
  EXPECT_RELATIVE(exact.position(5.0), -theory.distance, 1e-12);
  EXPECT_EQ(exact.phases().front().kind, PhaseKind::slip_left);
}

TEST(ReducedModel, KineticAboveStaticCannotStartUntilThePushBeatsBoth) {
  OneDofBlock block = spring_block();
  block.pair = {0.4, 0.6, 0.0, 0.0};
  const Trajectory exact = solve_exact(block, 3.0);
  EXPECT_RELATIVE(exact.events().front().t, 0.6 * g / (50.0 * 0.1), 1e-12);
  EXPECT_LT(max_position_difference(exact, solve_event_rk4(block, 3.0, 1e-4), 3.0), 1e-7);
}

// Fitted slope of log(error) against log(h).
double fitted_order(const std::vector<double>& steps, const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double x = std::log(steps[i]), y = std::log(errors[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(ReducedModel, FixedStepIntegratorsConvergeAtTheirOrderWhileSliding) {
  // Launched at 2 m/s against the spring: it slides right for the whole 0.1 s, well above
  // epsilon, so the regularized law is the smooth μk law and the exact solver is the reference.
  OneDofBlock block = spring_block(0.3);
  block.v0 = 2.0;
  const double t_end = 0.1, epsilon = 1e-3;
  const Trajectory exact = solve_exact(block, t_end);
  ASSERT_EQ(exact.events().size(), 1u);
  const auto error = [&](Integrator integrator, double h) {
    const std::vector<Sample> samples = integrate_regularized(block, t_end, h, epsilon, integrator);
    return std::abs(samples.back().x - exact.position(t_end));
  };
  const std::vector<double> euler_steps{0.01, 0.005, 0.0025, 0.00125, 0.000625};
  const std::vector<double> rk4_steps{0.025, 0.0125, 0.00625, 0.003125};
  std::vector<double> semi, explicit_euler, rk4;
  for (const double h : euler_steps) semi.push_back(error(Integrator::semi_implicit_euler, h));
  for (const double h : euler_steps) explicit_euler.push_back(error(Integrator::explicit_euler, h));
  for (const double h : rk4_steps) rk4.push_back(error(Integrator::rk4, h));
  const double semi_order = fitted_order(euler_steps, semi), rk4_order = fitted_order(rk4_steps, rk4);
  EXPECT_GE(semi_order, 0.8);
  EXPECT_LE(semi_order, 1.2);
  EXPECT_GE(fitted_order(euler_steps, explicit_euler), 0.8);
  EXPECT_LE(fitted_order(euler_steps, explicit_euler), 1.2);
  EXPECT_GE(rk4_order, 3.5);
  EXPECT_LE(rk4_order, 4.5);
  EXPECT_LT(rk4.back(), 1e-8);
}

TEST(ReducedModel, RegularizedLawCrawlsWhereCoulombHolds) {
  // The tribology article's warning: below epsilon the regularized force only balances the push
  // once the block moves, at v = epsilon·F/(μs N). Coulomb friction holds it still.
  const double angle = 0.3, epsilon = 0.01;
  OneDofBlock block;
  block.normal_force = g * std::cos(angle);
  block.constant_force = g * std::sin(angle);
  block.pair = {0.6, 0.4, 0.0, 0.0};
  const std::vector<Sample> samples = integrate_regularized(block, 2.0, 1e-3, epsilon, Integrator::semi_implicit_euler);
  const double crawl = epsilon * block.constant_force / (0.6 * block.normal_force);
  EXPECT_RELATIVE(samples.back().v, crawl, 1e-6);
  EXPECT_GT(samples.back().x, 0.0);
  EXPECT_EQ(solve_exact(block, 2.0).position(2.0), 0.0);
}

TEST(ReducedModel, ExplicitDragStepReversesVelocityPastTheStabilityLimit) {
  // h·c/m = 2.5 >= 2: each explicit step overshoots zero velocity by more than it started.
  OneDofBlock block;
  block.normal_force = 0.0;
  block.pair = {0.0, 0.0, 10.0, 0.0};
  block.v0 = 1.0;
  const std::vector<Sample> samples = integrate_regularized(block, 2.0, 0.25, 1e-3, Integrator::explicit_euler);
  EXPECT_NEAR(samples[1].v, -1.5, 1e-12);
  EXPECT_GT(std::abs(samples.back().v), 10.0);
}

TEST(ReducedModel, SamplesLandOnEveryStepAndOnTEnd) {
  const std::vector<Sample> samples = integrate_regularized(spring_block(), 1.05, 0.1, 1e-3, Integrator::rk4);
  ASSERT_EQ(samples.size(), 12u);
  EXPECT_EQ(samples.front().t, 0.0);
  EXPECT_NEAR(samples[5].t, 0.5, 1e-15);
  EXPECT_EQ(samples.back().t, 1.05);
  EXPECT_EQ(integrate_regularized(spring_block(), 1.0, 0.1, 1e-3, Integrator::rk4).size(), 11u);
}


TEST(ReducedModelInput, NonPositiveMassThrows) {
  OneDofBlock block = spring_block();
  block.mass = -1.0;
  expect_invalid([&] { solve_exact(block, 1.0); }, "mass", "> 0");
  expect_invalid([&] { solve_event_rk4(block, 1.0, 1e-3); }, "mass", "> 0");
  expect_invalid([&] { integrate_regularized(block, 1.0, 1e-3, 1e-3, Integrator::rk4); }, "mass", "> 0");
}

TEST(ReducedModelInput, NaNThrows) {
  OneDofBlock block = spring_block();
  block.x0 = std::numeric_limits<double>::quiet_NaN();
  expect_invalid([&] { solve_exact(block, 1.0); }, "x0", "finite");
  expect_invalid([&] { solve_exact(spring_block(), std::numeric_limits<double>::quiet_NaN()); }, "t_end", ">= 0");
}

TEST(ReducedModelInput, NegativeCoefficientOrForceThrows) {
  OneDofBlock block = spring_block();
  block.pair.mu_k = -0.1;
  expect_invalid([&] { solve_exact(block, 1.0); }, "mu_k", ">= 0");
  block = spring_block();
  block.normal_force = -1.0;
  expect_invalid([&] { solve_event_rk4(block, 1.0, 1e-3); }, "normal_force", ">= 0");
  block = spring_block();
  block.spring_k = -5.0;
  expect_invalid([&] { solve_exact(block, 1.0); }, "spring_k", ">= 0");
}

TEST(ReducedModelInput, QuadraticDragNeedsTheRk4Solver) {
  OneDofBlock block = spring_block();
  block.pair.b = 0.2;
  expect_invalid([&] { solve_exact(block, 1.0); }, "b", "0");
  EXPECT_NO_THROW(solve_event_rk4(block, 1.0, 1e-3));
}

TEST(ReducedModelInput, NonPositiveStepThrows) {
  expect_invalid([] { solve_event_rk4(spring_block(), 1.0, 0.0); }, "h", "> 0");
  expect_invalid([] { integrate_regularized(spring_block(), 1.0, -1e-3, 1e-3, Integrator::rk4); }, "h", "> 0");
  expect_invalid([] { integrate_regularized(spring_block(), 1e3, 1e-9, 1e-3, Integrator::rk4); }, "h", "1e9 steps");
}

TEST(ReducedModelInput, NonPositiveEpsilonThrows) {
  expect_invalid([] { integrate_regularized(spring_block(), 1.0, 1e-3, 0.0, Integrator::rk4); }, "epsilon", "> 0");
}

TEST(ReducedModelInput, NegativeDurationThrows) {
  expect_invalid([] { solve_exact(spring_block(), -1.0); }, "t_end", ">= 0");
}

TEST(ReducedModelInput, EvaluatingOutsideTheSolveThrows) {
  const Trajectory exact = solve_exact(spring_block(), 2.0);
  expect_invalid([&] { exact.position(2.5); }, "t", "[0, t_end]");
  expect_invalid([&] { exact.velocity(-0.1); }, "t", "[0, t_end]");
}

}  // namespace
}  // namespace frictionlab
