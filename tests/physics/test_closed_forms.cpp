// Each closed form against an independent numerical solution of the same equations: the
// event-driven RK4 solver for the dynamics, bisection and small linear solves for the statics.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "physics/closed_forms.h"
#include "physics/reduced_model.h"
#include "tests/assertions.h"

namespace frictionlab {
namespace {

using namespace theory;

constexpr double g = 9.81;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

// Agreement with a numerical solution, relative to the size of the expected value.

// Bisection for the first x in [lo, hi] at which a monotone predicate turns true.
template <class Predicate>
double first_true(double lo, double hi, Predicate predicate) {
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (predicate(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

const Event& nth_event(const Trajectory& trajectory, EventKind kind, int n) {
  int seen = 0;
  for (const Event& event : trajectory.events()) {
    if (event.kind == kind && seen++ == n) return event;
  }
  throw std::runtime_error("event not found");
}

TEST(ClosedForms, StickingAngleBalancesGravityAgainstMaximumStaticFriction) {
  for (const double mu_s : {0.05, 0.6, 1.3}) {
    const double mass = 2.0;
    // The block slips once the pull along the slope beats μs times the normal force.
    const double angle = first_true(0.0, std::numbers::pi / 2, [&](double theta) {
      return mass * g * std::sin(theta) > mu_s * mass * g * std::cos(theta);
    });
    EXPECT_RELATIVE(sticking_angle(mu_s), angle, 1e-12) << "mu_s " << mu_s;
  }
  EXPECT_EQ(sticking_angle(0.0), 0.0);
}

TEST(ClosedForms, InclineSlidingAccelerationFromFreeBodyDiagramVectors) {
  for (const double angle : {0.2, 0.7, 1.2}) {
    const double mass = 3.0, mu_k = 0.45;
    // Gravity (0, −m g) resolved on the slope's unit vectors, down-slope (cos, −sin) and normal (sin, cos).
    const double along = mass * g * std::sin(angle);           // −m g · (−sin θ)
    const double normal_force = mass * g * std::cos(angle);    // surface pushes back what gravity presses in
    const double expected = (along - mu_k * normal_force) / mass;
    EXPECT_RELATIVE(incline_sliding_acceleration(angle, mu_k, g), expected, 1e-12) << "angle " << angle;
  }
  EXPECT_LT(incline_sliding_acceleration(0.2, 0.45, g), 0.0);  // kinetic friction would stop it
}

// Stepped as the world steps, the slide tends to the continuous one as the step shrinks (the
// split of drag from the other forces is first order: the error halves with h, to within the
// next order's share, O(h), which is a few parts in a thousand at these steps); and where the
// drag is faster than a step it creeps at the stepped fixed point v = a·h/(1 − e^(−c·h/m)),
// not at a·m/c: where_methods_fail's block at c = 799.5 N·s/m, 1 kg, 30°, μk 0.5539, 240 Hz.
TEST(ClosedForms, InclineSlideSteppedTendsToTheContinuousOneAndCreepsAtTheSteppedFixedPoint) {
  const double angle = 0.6, mu_k = 0.3, c = 0.8, b = 0.7, mass = 2.0, t = 2.0;
  const double exact = incline_distance(angle, mu_k, c, b, mass, g, t);
  const double coarse = incline_slide_stepped(angle, mu_k, c, b, mass, g, t, 1e-2).distance - exact;
  const double fine = incline_slide_stepped(angle, mu_k, c, b, mass, g, t, 5e-3).distance - exact;
  EXPECT_NEAR(fine / coarse, 0.5, 0.02);
  EXPECT_RELATIVE(incline_slide_stepped(angle, mu_k, c, b, mass, g, t, 1e-5).speed, incline_speed(angle, mu_k, c, b, mass, g, t),
                  1e-4);

  const double slope = 30.0 * std::numbers::pi / 180.0, h = 1.0 / 240.0, drag = 799.5;
  const double a = incline_sliding_acceleration(slope, 0.5539, g);
  const InclineSlide creep = incline_slide_stepped(slope, 0.5539, drag, 0.0, 1.0, g, 3.0, h);
  EXPECT_RELATIVE(creep.speed, a * h / -std::expm1(-drag * h), 1e-9);
  EXPECT_GT(creep.speed, 3.0 * a / drag);  // the continuous law's terminal speed, a·m/c
  EXPECT_EQ(incline_slide_stepped(0.2, 0.45, drag, 0.0, 1.0, g, 3.0, h).distance, 0.0);  // kinetic friction holds it
}

TEST(ClosedForms, InclineSpeedAndDistanceMatchEventSolver) {
  for (const double c : {0.0, 0.8, 5.0}) {
    const double mass = 2.0, angle = 0.6;
    OneDofBlock block;
    block.mass = mass;
    block.normal_force = mass * g * std::cos(angle);
    block.constant_force = mass * g * std::sin(angle);
    block.pair = {0.5, 0.3, c, 0.0};  // tan 0.6 = 0.684 > μs: it breaks away at once
    const Trajectory numeric = solve_event_rk4(block, 2.0, 1e-4);
    ASSERT_EQ(numeric.events().front().kind, EventKind::breakaway);
    for (const double t : {0.25, 1.0, 2.0}) {
      EXPECT_RELATIVE(incline_speed(angle, 0.3, c, mass, g, t), numeric.velocity(t), 1e-6) << "c " << c << " t " << t;
      EXPECT_RELATIVE(incline_distance(angle, 0.3, c, mass, g, t), numeric.position(t), 1e-6) << "c " << c << " t " << t;
    }
  }
  // Quadratic drag b too (the incline lesson's b slider), alone and with c: from a b too small
  // to matter (where the Riccati form would cancel) to one that holds the block near its
  // terminal speed within milliseconds.
  for (const auto& [c, b] : {std::pair{0.0, 1e-9}, std::pair{0.0, 0.7}, std::pair{0.8, 0.7}, std::pair{5.0, 30.0},
                             std::pair{0.0, 900.0}}) {
    const double mass = 2.0, angle = 0.6;
    OneDofBlock block;
    block.mass = mass;
    block.normal_force = mass * g * std::cos(angle);
    block.constant_force = mass * g * std::sin(angle);
    block.pair = {0.5, 0.3, c, b};
    const Trajectory numeric = solve_event_rk4(block, 2.0, 1e-5);
    for (const double t : {0.25, 1.0, 2.0}) {
      EXPECT_RELATIVE(incline_speed(angle, 0.3, c, b, mass, g, t), numeric.velocity(t), 1e-6) << "c " << c << " b " << b << " t " << t;
      EXPECT_RELATIVE(incline_distance(angle, 0.3, c, b, mass, g, t), numeric.position(t), 1e-6) << "c " << c << " b " << b << " t " << t;
    }
  }
  // Steeper than atan(μs) but not than atan(μk): it cannot keep sliding.
  EXPECT_EQ(incline_speed(0.3, 0.4, 0.0, 1.0, g, 1.0), 0.0);
  EXPECT_EQ(incline_distance(0.3, 0.4, 0.0, 1.0, g, 1.0), 0.0);
}

// A uniform box of width d and weight W pushed at height h, standing still: horizontal balance
// gives friction = F, vertical gives N = W, and moments about the base centre put the normal
// force's line at e = F h / W towards the front. It tips once e must pass d/2, slides once
// friction must pass μs N.
struct BoxPush {
  double weight, width, height, mu_s;
  double tipping_push() const {
    return first_true(0.0, 1e6, [&](double push) { return push * height / weight > width / 2.0; });
  }
  double sliding_push() const {
    return first_true(0.0, 1e6, [&](double push) { return push > mu_s * weight; });
  }
};

TEST(ClosedForms, TipHeightIsWhereTippingAndSlidingNeedTheSamePush) {
  for (const double mu_s : {0.3, 0.6, 1.1}) {
    const double width = 0.8;
    const double height = first_true(1e-3, 100.0, [&](double h) {
      const BoxPush box{50.0, width, h, mu_s};
      return box.tipping_push() <= box.sliding_push();
    });
    EXPECT_RELATIVE(tip_height(width, mu_s), height, 1e-9) << "mu_s " << mu_s;
  }
  EXPECT_EQ(tip_height(1.0, 0.0), infinity);
}

TEST(ClosedForms, PushOutcomeMatchesEquilibriumOfTheBox) {
  const double weight = 60.0, width = 0.5, mu_s = 0.5;  // tip height 0.5 m
  for (const double height : {0.1, 0.45, 0.55, 1.5}) {
    const BoxPush box{weight, width, height, mu_s};
    const double tip = box.tipping_push(), slide = box.sliding_push();
    const PushOutcome outcome = push_outcome(weight, width, height, mu_s);
    EXPECT_EQ(outcome.tips, tip < slide) << "height " << height;
    EXPECT_RELATIVE(outcome.force, std::min(tip, slide), 1e-9) << "height " << height;
  }
  EXPECT_TRUE(push_outcome(weight, width, tip_height(width, mu_s), mu_s).tips);  // "at or above" tips
  EXPECT_FALSE(push_outcome(weight, width, 0.0, mu_s).tips);
}

struct SpringCase {
  double mass, k, pull_speed, mu_s, mu_k;
};

TEST(ClosedForms, SpringStickSlipMatchesEventSolver) {
  // The suggested standard problem; μs > 2μk, where the block restops on a compressed spring;
  // and a heavier, faster case.
  for (const SpringCase& s : {SpringCase{1.0, 50.0, 0.1, 0.6, 0.4}, SpringCase{1.0, 50.0, 0.1, 0.6, 0.2},
                              SpringCase{2.5, 20.0, 0.3, 0.5, 0.35}}) {
    OneDofBlock block;
    block.mass = s.mass;
    block.normal_force = s.mass * g;
    block.pair = {s.mu_s, s.mu_k, 0.0, 0.0};
    block.spring_k = s.k;
    block.pull_speed = s.pull_speed;
    const StickSlip theory = spring_stick_slip(s.mass, s.k, s.pull_speed, s.mu_s, s.mu_k, g);
    const Trajectory numeric = solve_event_rk4(block, theory.first_breakaway_time + 3.2 * theory.period, 1e-4);
    const Event& break1 = nth_event(numeric, EventKind::breakaway, 0);
    const Event& stop1 = nth_event(numeric, EventKind::stop, 0);
    const Event& break2 = nth_event(numeric, EventKind::breakaway, 1);
    const Event& stop2 = nth_event(numeric, EventKind::stop, 1);
    const Event& break3 = nth_event(numeric, EventKind::breakaway, 2);
    const auto spring = [&](const Event& e) { return applied_force(block, e.t, e.x); };
    EXPECT_RELATIVE(theory.first_breakaway_time, break1.t, 1e-6);
    EXPECT_RELATIVE(theory.breakaway_force, spring(break2), 1e-6);
    EXPECT_RELATIVE(theory.restick_force, spring(stop1), 1e-6);
    EXPECT_RELATIVE(theory.restick_force, spring(stop2), 1e-6);
    EXPECT_RELATIVE(theory.slip_duration, stop1.t - break1.t, 1e-6);
    EXPECT_RELATIVE(theory.stick_duration, break2.t - stop1.t, 1e-6);
    EXPECT_RELATIVE(theory.period, break2.t - break1.t, 1e-6);
    EXPECT_RELATIVE(theory.period, break3.t - break2.t, 1e-6);
    EXPECT_RELATIVE(theory.slip_distance, break3.x - break2.x, 1e-6);
  }
}

TEST(ClosedForms, SpringStickSlipStandardNumbers) {
  // Hand-checked: Δ = 0.2·9.81/50 = 0.03924 m, ω = √50, so stick 0.7848 s and slip
  // (π + 2 atan(0.1/(√50·0.03924)))/√50 = 0.542127 s; breakaway 5.886 N, restick 1.962 N.
  const StickSlip s = spring_stick_slip(1.0, 50.0, 0.1, 0.6, 0.4, g);
  EXPECT_NEAR(s.breakaway_force, 5.886, 1e-12);
  EXPECT_NEAR(s.restick_force, 1.962, 1e-12);
  EXPECT_NEAR(s.stick_duration, 0.7848, 1e-12);
  EXPECT_NEAR(s.slip_duration, 0.542127, 1e-6);
  EXPECT_NEAR(s.period, 1.326927, 1e-6);
  EXPECT_NEAR(s.first_breakaway_time, 1.1772, 1e-12);
}

TEST(ClosedForms, SlideToRestMatchesEventSolverForEveryDragCombination) {
  const double mass = 2.0, mu_k = 0.3;
  // c and b each off and on, and with both on the three discriminant cases of a + γv + βv²
  // (a = 2.943, γ = c/m, β = b/m): complex roots, real roots, and (nearly) a double root.
  const double double_root_b = mass * (1.5 / mass) * (1.5 / mass) / (4.0 * mu_k * g);
  struct Drag {
    double c, b;
  };
  for (const Drag drag : {Drag{0, 0}, Drag{1.5, 0}, Drag{0, 0.4}, Drag{1.5, 0.4}, Drag{6.0, 0.4},
                          Drag{1.5, double_root_b}}) {
    for (const double v0 : {0.01, 3.0, 40.0, -3.0}) {
      const FrictionPair pair{0.5, mu_k, drag.c, drag.b};
      const SlideToRest theory = slide_to_rest(v0, mass, pair, g);
      OneDofBlock block;
      block.mass = mass;
      block.normal_force = mass * g;
      block.pair = pair;
      block.v0 = v0;
      const Trajectory numeric = solve_event_rk4(block, theory.time + 0.5, std::min(1e-4, theory.time / 200.0));
      const Event& stop = nth_event(numeric, EventKind::stop, 0);
      EXPECT_RELATIVE(theory.time, stop.t, 1e-6) << "c " << drag.c << " b " << drag.b << " v0 " << v0;
      EXPECT_RELATIVE(theory.distance, std::abs(stop.x), 1e-6) << "c " << drag.c << " b " << drag.b << " v0 " << v0;
    }
  }
}

TEST(ClosedForms, SlideToRestWithoutDryFrictionNeverStops) {
  const double mass = 2.0, v0 = 3.0;
  EXPECT_EQ(slide_to_rest(v0, mass, {0, 0, 0, 0}, g).time, infinity);
  EXPECT_EQ(slide_to_rest(v0, mass, {0, 0, 0, 0}, g).distance, infinity);
  EXPECT_EQ(slide_to_rest(v0, mass, {0, 0, 0, 0.4}, g).distance, infinity);
  // Drag alone: it never stops, but linear drag bounds the distance. Compare with a long run.
  for (const FrictionPair& pair : {FrictionPair{0, 0, 1.5, 0}, FrictionPair{0, 0, 1.5, 0.4}}) {
    const SlideToRest theory = slide_to_rest(v0, mass, pair, g);
    EXPECT_EQ(theory.time, infinity);
    OneDofBlock block;
    block.mass = mass;
    block.normal_force = mass * g;
    block.pair = pair;
    block.v0 = v0;
    EXPECT_RELATIVE(theory.distance, solve_event_rk4(block, 60.0, 1e-3).position(60.0), 1e-6) << "b " << pair.b;
  }
}

// Rolling: m a = m g sinθ − f, I α = f R, a = α R, three equations solved by elimination.
struct RollingSolution {
  double acceleration, angular_acceleration, friction;
};
RollingSolution solve_rolling(double angle, double mass, double radius, double inertia) {
  double m[3][4] = {{mass, 0.0, 1.0, mass * g * std::sin(angle)},
                    {0.0, inertia, -radius, 0.0},
                    {1.0, -radius, 0.0, 0.0}};
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row)
      if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
    std::swap(m[col], m[pivot]);
    for (int row = 0; row < 3; ++row) {
      if (row == col) continue;
      const double factor = m[row][col] / m[col][col];
      for (int k = col; k < 4; ++k) m[row][k] -= factor * m[col][k];
    }
  }
  return {m[0][3] / m[0][0], m[1][3] / m[1][1], m[2][3] / m[2][2]};
}

TEST(ClosedForms, DiskOnInclineRollsUntilStaticFrictionCannotSupplyTheTorque) {
  const double mass = 1.5, radius = 0.2, mu_s = 0.3, mu_k = 0.2;
  for (const double inertia : {0.5 * mass * radius * radius, mass * radius * radius, 0.4 * mass * radius * radius}) {
    const auto needs_more_than_static = [&](double angle) {
      return solve_rolling(angle, mass, radius, inertia).friction > mu_s * mass * g * std::cos(angle);
    };
    const double critical = first_true(0.0, std::numbers::pi / 2, needs_more_than_static);
    const double flips = first_true(0.0, std::numbers::pi / 2, [&](double angle) {
      return !disk_on_incline(angle, mass, radius, inertia, mu_s, mu_k, g).rolls;
    });
    EXPECT_RELATIVE(flips, critical, 1e-9) << "inertia " << inertia;

    const double gentle = 0.5 * critical;
    const RollingSolution rolling = solve_rolling(gentle, mass, radius, inertia);
    const DiskOnIncline below = disk_on_incline(gentle, mass, radius, inertia, mu_s, mu_k, g);
    EXPECT_TRUE(below.rolls);
    EXPECT_RELATIVE(below.acceleration, rolling.acceleration, 1e-12);
    EXPECT_RELATIVE(below.angular_acceleration, rolling.angular_acceleration, 1e-12);
    EXPECT_RELATIVE(below.friction_force, rolling.friction, 1e-12);

    // Slipping: kinetic friction μk N up the slope drives the spin and slows the centre.
    const double steep = std::min(1.5 * critical, 1.5);
    const double normal_force = mass * g * std::cos(steep);
    const DiskOnIncline above = disk_on_incline(steep, mass, radius, inertia, mu_s, mu_k, g);
    EXPECT_FALSE(above.rolls);
    EXPECT_RELATIVE(above.acceleration, g * std::sin(steep) - mu_k * normal_force / mass, 1e-12);
    EXPECT_RELATIVE(above.angular_acceleration, mu_k * normal_force * radius / inertia, 1e-12);
    EXPECT_RELATIVE(above.friction_force, mu_k * normal_force, 1e-12);
    EXPECT_GT(above.acceleration, above.angular_acceleration * radius);  // the contact slides down
  }
}

TEST(ClosedForms, DiskStartsRollingMatchesIntegratedSpinUp) {
  const double mass = 2.0, radius = 0.3, mu_k = 0.25;
  for (const double inertia : {0.5 * mass * radius * radius, mass * radius * radius}) {
    for (const double v0 : {4.0, 0.3}) {
      // x' = v, v' = −μk g, ω' = μk m g R / I while the contact slips forward (v > ωR).
      struct State {
        double x, v, omega;
      };
      const auto rate = [&](const State&) {
        return State{0.0, -mu_k * g, mu_k * mass * g * radius / inertia};
      };
      const auto step = [&](State s, double h) {
        const State k1 = rate(s);
        const State m1{s.x + 0.5 * h * s.v, s.v + 0.5 * h * k1.v, s.omega + 0.5 * h * k1.omega};
        const State k2 = rate(m1);
        const State m2{s.x + 0.5 * h * m1.v, s.v + 0.5 * h * k2.v, s.omega + 0.5 * h * k2.omega};
        const State k3 = rate(m2);
        const State e{s.x + h * m2.v, s.v + h * k3.v, s.omega + h * k3.omega};
        const State k4 = rate(e);
        return State{s.x + h / 6.0 * (s.v + 2.0 * m1.v + 2.0 * m2.v + e.v),
                     s.v + h / 6.0 * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v),
                     s.omega + h / 6.0 * (k1.omega + 2.0 * k2.omega + 2.0 * k3.omega + k4.omega)};
      };
      const double h = 1e-4;
      State s{0.0, v0, 0.0};
      double t = 0.0;
      while (step(s, h).v - step(s, h).omega * radius > 0.0) {
        s = step(s, h);
        t += h;
      }
      const double sub = first_true(0.0, h, [&](double dt) { return step(s, dt).v - step(s, dt).omega * radius <= 0.0; });
      const State rolling = step(s, sub);
      const RollStart theory = disk_starts_rolling(v0, mass, radius, inertia, mu_k, g);
      EXPECT_RELATIVE(theory.time, t + sub, 1e-6) << "inertia " << inertia << " v0 " << v0;
      EXPECT_RELATIVE(theory.speed, rolling.v, 1e-6);
      EXPECT_RELATIVE(theory.distance, rolling.x, 1e-6);
    }
  }
  EXPECT_EQ(disk_starts_rolling(2.0, mass, radius, 0.1, 0.0, g).time, infinity);
}

// The stack's regime by trying each hypothesis in turn with Newton's second law for each block.
StackedBlocks stack_by_hypotheses(double top, double bottom, const FrictionPair& between, const FrictionPair& ground,
                                  double push) {
  const double total = top + bottom;
  if (push <= ground.mu_s * total * g) return {StackRegime::at_rest, 0.0, 0.0, 0.0};
  // Together: top m_t a − f = 0, bottom m_b a + f = F − μk_g (m_t+m_b) g; Cramer's rule.
  const double kinetic_ground = ground.mu_k * total * g;
  const double m11 = top, m12 = -1.0, r1 = 0.0, m21 = bottom, m22 = 1.0, r2 = push - kinetic_ground;
  const double det = m11 * m22 - m12 * m21;
  const double a = (r1 * m22 - m12 * r2) / det;
  const double f = (m11 * r2 - r1 * m21) / det;
  if (std::abs(f) <= between.mu_s * top * g) return {StackRegime::together, a, a, 0.0};
  return {StackRegime::top_slips, between.mu_k * g,
          (push - between.mu_k * top * g - kinetic_ground) / bottom, 0.0};
}

TEST(ClosedForms, StackedBlocksMatchNewtonForEachBlock) {
  const double top = 1.0, bottom = 3.0;
  const FrictionPair between{0.5, 0.4, 0, 0}, ground{0.3, 0.2, 0, 0};
  const double threshold = first_true(0.0, 1e4, [&](double push) {
    return stack_by_hypotheses(top, bottom, between, ground, push).regime == StackRegime::top_slips;
  });
  EXPECT_RELATIVE(stacked_blocks(top, bottom, between, ground, 10.0, g).max_push_together, threshold, 1e-9);
  for (const double push : {5.0, 11.0, 12.5, 20.0, 27.0, 28.0, 60.0}) {
    const StackedBlocks expected = stack_by_hypotheses(top, bottom, between, ground, push);
    const StackedBlocks actual = stacked_blocks(top, bottom, between, ground, push, g);
    EXPECT_EQ(actual.regime, expected.regime) << "push " << push;
    EXPECT_NEAR(actual.top_acceleration, expected.top_acceleration, 1e-12) << "push " << push;
    EXPECT_NEAR(actual.bottom_acceleration, expected.bottom_acceleration, 1e-12) << "push " << push;
  }
  const StackedBlocks mirrored = stacked_blocks(top, bottom, between, ground, -60.0, g);
  EXPECT_EQ(mirrored.regime, StackRegime::top_slips);
  EXPECT_NEAR(mirrored.bottom_acceleration, -stack_by_hypotheses(top, bottom, between, ground, 60.0).bottom_acceleration,
              1e-12);
  // Slippery top, grippy ground: the top block slips the moment the bottom one moves.
  const StackedBlocks slippery = stacked_blocks(top, bottom, {0.05, 0.04, 0, 0}, {0.6, 0.5, 0, 0}, 24.0, g);
  EXPECT_EQ(slippery.regime, StackRegime::top_slips);
}

// Bad parameters: one test for each kind, each checking the message names the parameter and range.

TEST(ClosedFormsInput, NonPositiveMassThrows) {
  expect_invalid([] { slide_to_rest(1.0, -1.0, {0.5, 0.4, 0, 0}, g); }, "mass", "> 0");
  expect_invalid([] { spring_stick_slip(0.0, 50, 0.1, 0.6, 0.4, g); }, "mass", "> 0");
  expect_invalid([] { stacked_blocks(1.0, -3.0, {}, {}, 1.0, g); }, "bottom_mass", "> 0");
}

TEST(ClosedFormsInput, NaNThrows) {
  expect_invalid([] { sticking_angle(nan); }, "mu_s", ">= 0");
  expect_invalid([] { incline_speed(nan, 0.3, 0.0, 1.0, g, 1.0); }, "angle", "[0, pi/2]");
  expect_invalid([] { slide_to_rest(nan, 1.0, {0.5, 0.4, 0, 0}, g); }, "v0", "finite");
}

TEST(ClosedFormsInput, NegativeCoefficientThrows) {
  expect_invalid([] { tip_height(1.0, -0.1); }, "mu_s", ">= 0");
  expect_invalid([] { incline_sliding_acceleration(0.3, -0.2, g); }, "mu_k", ">= 0");
  expect_invalid([] { slide_to_rest(1.0, 1.0, {0.5, 0.4, -1.0, 0}, g); }, "c", ">= 0");
  expect_invalid([] { slide_to_rest(1.0, 1.0, {0.5, 0.4, 0, -1.0}, g); }, "b", ">= 0");
}

TEST(ClosedFormsInput, KineticAboveStaticThrowsWhereStickSlipNeedsIt) {
  expect_invalid([] { spring_stick_slip(1.0, 50, 0.1, 0.4, 0.6, g); }, "mu_k", "[0, mu_s]");
}

// A slider may put mu_k above mu_s (theory.disk_on_incline refused such a lesson's value): the
// disk grips up to max(mu_s, mu_k)·N, the contacts' own rule, and slips against mu_k·N past it.
TEST(ClosedForms, DiskOnInclineWithKineticAboveStaticGripsUpToTheLarger) {
  const double mass = 1.0, radius = 0.2, inertia = 0.5 * mass * radius * radius;  // κ = 1/2
  // Rolling needs friction κ/(1+κ)·m·g·sin θ = m·g·sin θ/3: at 0.3 rad that is 0.985 N against
  // N = 9.37 N, more than mu_s = 0.05 holds but within mu_k = 0.2's 1.87 N.
  const DiskOnIncline grips = disk_on_incline(0.3, mass, radius, inertia, 0.05, 0.2, g);
  EXPECT_TRUE(grips.rolls);
  EXPECT_RELATIVE(grips.acceleration, g * std::sin(0.3) / 1.5, 1e-12);
  const DiskOnIncline slips = disk_on_incline(1.3, mass, radius, inertia, 0.05, 0.2, g);
  EXPECT_FALSE(slips.rolls);
  EXPECT_RELATIVE(slips.friction_force, 0.2 * mass * g * std::cos(1.3), 1e-12);
}

TEST(ClosedFormsInput, NonPositiveSizesThrow) {
  expect_invalid([] { tip_height(0.0, 0.5); }, "width", "> 0");
  expect_invalid([] { push_outcome(10.0, 1.0, -0.5, 0.5); }, "push_height", ">= 0");
  expect_invalid([] { disk_on_incline(0.3, 1.0, -0.2, 0.02, 0.3, 0.2, g); }, "radius", "> 0");
  expect_invalid([] { disk_starts_rolling(1.0, 1.0, 0.2, 0.0, 0.2, g); }, "inertia", "> 0");
  expect_invalid([] { spring_stick_slip(1.0, 0.0, 0.1, 0.6, 0.4, g); }, "k", "> 0");
  expect_invalid([] { spring_stick_slip(1.0, 50.0, 0.0, 0.6, 0.4, g); }, "pull_speed", "> 0");
}

TEST(ClosedFormsInput, NonPositiveGravityThrows) {
  expect_invalid([] { incline_sliding_acceleration(0.3, 0.2, 0.0); }, "g", "> 0");
  expect_invalid([] { slide_to_rest(1.0, 1.0, {0.5, 0.4, 0, 0}, -g); }, "g", "> 0");
}

TEST(ClosedFormsInput, AngleOutsideFlatToVerticalThrows) {
  expect_invalid([] { incline_sliding_acceleration(-0.1, 0.2, g); }, "angle", "[0, pi/2]");
  expect_invalid([] { disk_on_incline(2.0, 1.0, 0.2, 0.02, 0.3, 0.2, g); }, "angle", "[0, pi/2]");
}

TEST(ClosedFormsInput, NegativeTimeThrows) {
  expect_invalid([] { incline_distance(0.6, 0.3, 0.0, 1.0, g, -1.0); }, "t", ">= 0");
}

// The growing push, against the event solver. The reduced model has no force that grows with
// time alone, but a spring whose far end runs away at V gives k·(V·t − x): with k tiny and
// k·V the push's rate, the k·x part is below 1e-9 N over the run, so this is the same problem.
// Pure Coulomb, with viscous drag (closed form) and with quadratic drag (RK4 inside).
TEST(ClosedForms, GrowingPushMatchesEventSolver) {
  struct Case {
    double mass, rate;
    FrictionPair pair;
  };
  for (const Case c : {Case{1.0, 2.0, {0.5, 0.4, 0, 0}}, Case{3.0, 10.0, {0.8, 0.3, 0, 0}},
                       Case{0.5, 1.0, {0.3, 0.45, 0, 0}}, Case{1.0, 2.0, {0.4, 0.3, 2.0, 0}},
                       Case{1.0, 2.0, {0.4, 0.3, 1e-5, 0}}, Case{2.0, 5.0, {0.4, 0.3, 0.5, 0.8}}}) {
    OneDofBlock block;
    block.mass = c.mass;
    block.normal_force = c.mass * g;
    block.pair = c.pair;
    block.spring_k = 1e-10;
    block.pull_speed = c.rate / block.spring_k;
    const GrowingPush start = growing_push(c.mass, c.rate, c.pair, g, 0.0);
    const double t_end = start.breakaway_time + 2.0;
    const Trajectory numeric = solve_event_rk4(block, t_end, 1e-4);
    ASSERT_EQ(numeric.events().front().kind, EventKind::breakaway);
    EXPECT_NEAR(numeric.events().front().t, start.breakaway_time, 1e-9) << "mass " << c.mass;
    EXPECT_DOUBLE_EQ(start.breakaway_push, std::max(c.pair.mu_s, c.pair.mu_k) * c.mass * g);
    for (const double t : {0.5 * start.breakaway_time, start.breakaway_time + 0.3, t_end}) {
      const GrowingPush now = growing_push(c.mass, c.rate, c.pair, g, t);
      EXPECT_NEAR(now.speed, numeric.velocity(t), 1e-7 * std::max(1.0, now.speed)) << "c " << c.pair.c << " t " << t;
      EXPECT_NEAR(now.distance, numeric.position(t), 1e-7 * std::max(1.0, now.distance)) << "c " << c.pair.c << " t " << t;
      // Friction is whatever balances the rest of m·a: the push while stuck, mu_k·N and drag after.
      EXPECT_NEAR(now.friction, now.push - c.mass * now.acceleration, 1e-9 * now.push) << "t " << t;
    }
  }
}

TEST(ClosedFormsInput, GrowingPushNeedsAGrowingPush) {
  expect_invalid([] { growing_push(1.0, 0.0, {0.5, 0.4, 0, 0}, g, 1.0); }, "rate", "> 0");
  expect_invalid([] { growing_push(1.0, 1.0, {0.5, 0.4, 0, 0}, g, -1.0); }, "t", ">= 0");
}

// The thrown box's landing: without spin, the centre falls until the bottom face is within the
// clearance, t = sqrt(2·(y0 − h/2 − clearance)/g), and it lands flat; with spin, at the time
// found the lowest corner is at the clearance, and just before it every corner was above it.
TEST(ClosedForms, BoxLandingMatchesFreeFall) {
  const BoxLanding level = box_landing(0.4, 0.3, 1.0, 0.0, 0.0, g, 0.02);
  EXPECT_NEAR(level.time, std::sqrt(2.0 * (1.0 - 0.15 - 0.02) / g), 1e-9);
  EXPECT_TRUE(level.flat);
  for (const double omega : {-20.0, -6.0, 3.0, 20.0}) {
    const BoxLanding landing = box_landing(0.4, 0.3, 1.0, 0.0, omega, g, 0.02);
    EXPECT_FALSE(landing.flat) << omega;
    const auto lowest_corner = [&](double t) {
      double low = infinity;
      for (const double sx : {-0.2, 0.2}) {
        for (const double sy : {-0.15, 0.15}) {
          low = std::min(low, 1.0 - 0.5 * g * t * t + sx * std::sin(omega * t) + sy * std::cos(omega * t));
        }
      }
      return low;
    };
    EXPECT_NEAR(lowest_corner(landing.time), 0.02, 1e-9) << omega;
    for (double t = 0.0; t < landing.time - 1e-6; t += 1e-5) ASSERT_GT(lowest_corner(t), 0.02) << omega << " at " << t;
    EXPECT_NEAR(landing.corner_y, lowest_corner(landing.time) - (1.0 - 0.5 * g * landing.time * landing.time), 1e-9);
  }
}

// The impact on a corner: whatever branch it takes, its answer must satisfy the impulse laws
// (checked here from the impulses, not from the formulas): momentum and angular momentum about
// the centre change by J and r × J; the point stops falling (e = 0); and either it stops sliding
// with |J_t| <= mu·J_n, or it still slides with J_t = mu·J_n against that sliding. And a rigid
// impact with e = 0 never creates energy.
TEST(ClosedForms, CornerImpactObeysTheImpulseLaws) {
  const double mass = 2.0, inertia = mass * (0.4 * 0.4 + 0.3 * 0.3) / 12.0;
  int grips = 0, slides = 0;
  for (const double mu : {0.05, 0.4, 2.0}) {
    for (const double omega : {-20.0, -6.0, 0.0, 6.0, 20.0}) {
      for (const double rx : {-0.2, 0.1, 0.2}) {
        const double ry = -0.15, vx = 3.0, vy = -3.8;
        if (vy + omega * rx >= 0.0) continue;  // that corner is not coming down
        const CornerImpact after = corner_impact(mass, inertia, rx, ry, vx, vy, omega, mu, 0.0);
        const double jt = after.tangent_impulse, jn = after.normal_impulse;
        EXPECT_NEAR(after.vx, vx + jt / mass, 1e-12);
        EXPECT_NEAR(after.vy, vy + jn / mass, 1e-12);
        EXPECT_NEAR(after.omega, omega + (rx * jn - ry * jt) / inertia, 1e-12);
        EXPECT_GE(jn, 0.0);
        const double ux = after.vx - after.omega * ry, uy = after.vy + after.omega * rx;
        EXPECT_NEAR(uy, 0.0, 1e-9) << "mu " << mu << " omega " << omega << " rx " << rx;
        if (after.grips) {
          ++grips;
          EXPECT_NEAR(ux, 0.0, 1e-9);
          EXPECT_LE(std::abs(jt), mu * jn * (1.0 + 1e-12));
        } else {
          ++slides;
          EXPECT_NEAR(std::abs(jt), mu * jn, 1e-9 * jn);
          EXPECT_LE(jt * ux, 1e-12) << "friction against the sliding after the impact";
        }
        const double before = 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega;
        const double now = 0.5 * mass * (after.vx * after.vx + after.vy * after.vy) + 0.5 * inertia * after.omega * after.omega;
        EXPECT_LE(now, before * (1.0 + 1e-12));
      }
    }
  }
  EXPECT_GT(grips, 0);
  EXPECT_GT(slides, 0);
}

// Box2D's own solver on a corner met in a step: a box with no gravity, a corner just into a
// static floor, stepped once. Its spin after the step is what solver_corner_impact says for the
// solve's point and the world's 8 turns, to single precision (the floats' 2^-24 over a few dozen
// operations on speeds up to 20 rad/s: 1e-4), while the settled impact of corner_impact may lie
// far from it (a gripping corner's friction waiting on a growing normal impulse).
TEST(ClosedForms, SolverCornerImpactIsWhatBox2DsSolverLeaves) {
  double largest_shortfall = 0.0;
  for (const double mu : {0.3, 1.28, 2.0}) {
    for (const double spin : {-14.0, 6.0, 14.3}) {
      for (const float angle : {0.9f, -0.25f}) {
        b2World world(b2Vec2(0.0f, 0.0f));
        b2BodyDef floor_def;
        b2Body* floor = world.CreateBody(&floor_def);
        b2PolygonShape floor_shape;
        floor_shape.SetAsBox(5.0f, 0.5f, b2Vec2(0.0f, -0.5f), 0.0f);
        floor->CreateFixture(&floor_shape, 0.0f)->SetFriction(static_cast<float>(mu));
        // Turned, its lowest corner 2 mm into the floor's skin band.
        const float c = std::cos(angle), s = std::sin(angle);
        float lowest = 0.0f;
        for (const float sx : {-0.2f, 0.2f}) {
          for (const float sy : {-0.15f, 0.15f}) lowest = std::min(lowest, sx * s + sy * c);
        }
        b2BodyDef box_def;
        box_def.type = b2_dynamicBody;
        box_def.position.Set(0.0f, -lowest + 2.0f * b2_polygonRadius - 0.002f);
        box_def.angle = angle;
        box_def.linearVelocity.Set(5.18f, -3.98f);
        box_def.angularVelocity = static_cast<float>(spin);
        b2Body* box = world.CreateBody(&box_def);
        b2PolygonShape box_shape;
        box_shape.SetAsBox(0.2f, 0.15f);
        b2FixtureDef box_fixture;
        box_fixture.shape = &box_shape;
        box_fixture.density = 17.81f / 0.12f;
        box_fixture.friction = static_cast<float>(mu);
        box->CreateFixture(&box_fixture);
        const b2Transform floor_at = floor->GetTransform(), box_at = box->GetTransform();
        const b2Vec2 centre = box->GetWorldCenter();
        world.Step(1.0f / 240.0f, 8, 3);
        const b2Contact* contact = world.GetContactList();
        ASSERT_NE(contact, nullptr);
        ASSERT_EQ(contact->GetManifold()->pointCount, 1) << "one corner, not a face";
        // The point the solve used: the manifold found at the step's start, at the bodies' places then.
        b2WorldManifold solved;
        solved.Initialize(contact->GetManifold(), floor_at, floor_shape.m_radius, box_at, box_shape.m_radius);
        const double rx = solved.points[0].x - centre.x, ry = solved.points[0].y - centre.y;
        // (GetInertia is about the body's origin, here its centre.)
        const double mass = box->GetMass(), inertia = box->GetInertia();
        const CornerImpact turns = solver_corner_impact(mass, inertia, rx, ry, 5.18, -3.98, spin, mu, 0.0, 8);
        EXPECT_NEAR(box->GetAngularVelocity(), turns.omega, 1e-4) << "mu " << mu << " spin " << spin;
        EXPECT_NEAR(box->GetLinearVelocity().x, turns.vx, 1e-4) << "mu " << mu << " spin " << spin;
        EXPECT_NEAR(box->GetLinearVelocity().y, turns.vy, 1e-4) << "mu " << mu << " spin " << spin;
        const CornerImpact settled = corner_impact(mass, inertia, rx, ry, 5.18, -3.98, spin, mu, 0.0);
        // Enough turns settle on the impact itself.
        const CornerImpact many_turns = solver_corner_impact(mass, inertia, rx, ry, 5.18, -3.98, spin, mu, 0.0, 200);
        EXPECT_NEAR(many_turns.omega, settled.omega, 1e-9);
        largest_shortfall = std::max(largest_shortfall, std::abs(turns.omega - settled.omega));
      }
    }
  }
  // Somewhere among these the world's 8 turns leave the spin visibly short of the settled impact.
  EXPECT_GT(largest_shortfall, 0.1);
}

// Launched up a slope: against the event solver (gravity along the slope as a constant force),
// where it stops, and whether it stays there.
TEST(ClosedForms, SlopeLaunchMatchesEventSolver) {
  for (const double angle : {0.0, 0.2, 0.5}) {
    for (const double mu_k : {0.05, 0.45}) {
      const double mu_s = mu_k + 0.1, mass = 1.0;  // and below, mu_k above mu_s
      OneDofBlock block;
      block.mass = mass;
      block.normal_force = mass * g * std::cos(angle);
      block.constant_force = -mass * g * std::sin(angle);
      block.pair = {mu_s, mu_k, 0.0, 0.0};
      block.v0 = 3.0;
      const SlopeLaunch launch = slope_launch(3.0, angle, mu_s, mu_k, g);
      const Trajectory numeric = solve_event_rk4(block, launch.time + 1.0, 1e-4);
      const Event& stop = numeric.events().front();
      EXPECT_NEAR(stop.t, launch.time, 1e-9) << angle << " " << mu_k;
      EXPECT_NEAR(stop.x, launch.distance, 1e-9) << angle << " " << mu_k;
      EXPECT_EQ(launch.stays, stop.kind == EventKind::stop) << angle << " " << mu_k;
    }
  }
}

// With mu_k above mu_s a stopped block is held up to mu_k·N (as the solver holds it): on a slope
// with mu_s < tan θ <= mu_k it stays.
TEST(ClosedForms, SlopeLaunchHoldsUpToTheLargerCoefficient) {
  EXPECT_TRUE(slope_launch(3.0, std::atan(0.4), 0.3, 0.5, g).stays);
  EXPECT_FALSE(slope_launch(3.0, std::atan(0.6), 0.3, 0.5, g).stays);
}

// The velocity hack against the discrete process itself, sub-step by sub-step, as the scene
// runs it: the first frame from half a sub-step back (its leapfrog start), gravity before each
// sub-step's move, the cut after each frame. On the flat the start and the sub-steps change
// nothing; on a slope the old model (no half step, one step a frame) is 0.5 % off at 30°.
TEST(ClosedForms, VelocityHackMatchesTheFramesItSums) {
  for (const int substeps : {1, 2, 3}) {
    for (const double angle : {0.0, 0.1, 0.35, 0.5236}) {
      for (const double keep : {0.0, 0.5, 0.99}) {
        const double h = 1.0 / 240.0, v0 = 3.0, pull = g * std::sin(angle) * h / substeps;
        double x = 0.0, v = v0 + 0.5 * pull, farthest = 0.0;  // v(−h/2) = v0 − (h/2)·(−g sin θ)
        for (int frame = 0; frame < 200000; ++frame) {
          for (int sub = 0; sub < substeps; ++sub) {
            v -= pull;
            x += h / substeps * v;
          }
          v *= keep;
          farthest = std::max(farthest, x);
        }
        const VelocityHack hack = velocity_hack(v0, keep, h, angle, g, substeps);
        EXPECT_NEAR(hack.distance_up, farthest, 1e-9 * std::max(1.0, farthest)) << angle << " " << keep << " " << substeps;
        EXPECT_NEAR(hack.drift_speed, v, 1e-9) << angle << " " << keep << " " << substeps;
      }
    }
  }
  EXPECT_NEAR(velocity_hack(3.0, 0.99, 0.01, 0.0, g).distance_up, 0.01 * 3.0 / 0.01, 1e-9);
  EXPECT_THROW(velocity_hack(3.0, 0.99, 0.01, 0.0, g, 0), InvalidInput);
}

// Connected masses against the event solver: the block and the weight are one body of mass
// m_b + m_h along the rope, driven by m_h·g, with the table's friction on N = m_b·g. On both
// sides of the threshold m_h = max(mu_s, mu_k)·m_b, at it, and with mu_k above mu_s.
TEST(ClosedForms, ConnectedMassesMatchTheEventSolver) {
  struct Case {
    double block_mass, hanging_mass, mu_s, mu_k;
  };
  for (const Case& c : {Case{1.0, 0.3, 0.4, 0.3}, Case{1.0, 0.5, 0.4, 0.3}, Case{2.0, 0.8, 0.4, 0.3},
                        Case{2.0, 0.81, 0.4, 0.3}, Case{0.5, 3.0, 0.6, 0.5}, Case{1.0, 0.45, 0.4, 0.5},
                        Case{1.0, 0.55, 0.4, 0.5}, Case{1.0, 0.2, 0.0, 0.0}}) {
    OneDofBlock line;
    line.mass = c.block_mass + c.hanging_mass;
    line.normal_force = c.block_mass * g;
    line.constant_force = c.hanging_mass * g;
    line.pair = {c.mu_s, c.mu_k, 0.0, 0.0};
    const Trajectory numeric = solve_event_rk4(line, 2.0, 1e-4);
    const ConnectedMasses exact = connected_masses(c.block_mass, c.hanging_mass, c.mu_s, c.mu_k, g);
    const std::string name = std::to_string(c.hanging_mass) + " kg on " + std::to_string(c.block_mass) + " kg";
    EXPECT_EQ(exact.slides, numeric.position(2.0) > 0.0) << name;
    EXPECT_NEAR(0.5 * exact.acceleration * 4.0, numeric.position(2.0), 1e-9) << name;
    // The block's own balance, m_b·a = T − friction (T is defined by the weight's).
    EXPECT_NEAR(c.block_mass * exact.acceleration, exact.tension - exact.friction, 1e-12) << name;
  }
  // Exactly at the threshold it stays put.
  EXPECT_FALSE(connected_masses(2.0, 0.8, 0.4, 0.3, g).slides);
  EXPECT_TRUE(connected_masses(2.0, 0.8000001, 0.4, 0.3, g).slides);
}

// A surface oiled between two instants, against the event solver run stretch by stretch (each
// from where the last left the block): held, set going by the oil, slowed and stopped on the
// dry surface again, or still sliding; with mu_k above mu_s; and with no oil at all.
TEST(ClosedForms, IntermittentSlideMatchesTheEventSolverStretchByStretch) {
  struct Case {
    double pull, mu_s, mu_k, oiled_mu_s, oiled_mu_k, from, until;
  };
  const double mass = 1.0;
  for (const Case& c : {Case{3.0, 0.4, 0.35, 0.15, 0.1, 1.0, 2.0}, Case{3.0, 0.4, 0.25, 0.15, 0.1, 1.0, 2.0},
                        Case{5.0, 0.4, 0.35, 0.15, 0.1, 0.5, 1.5}, Case{3.0, 0.2, 0.4, 0.15, 0.1, 1.0, 2.0},
                        Case{3.0, 0.4, 0.35, 0.4, 0.35, 1.0, 2.0}, Case{0.0, 0.4, 0.35, 0.0, 0.0, 1.0, 2.0},
                        Case{3.0, 0.4, 0.35, 0.15, 0.1, 1.0, 1.0}}) {
    const FrictionPair dry{c.mu_s, c.mu_k, 0.0, 0.0}, oiled{c.oiled_mu_s, c.oiled_mu_k, 0.0, 0.0};
    double x = 0.0, v = 0.0;
    const double bounds[] = {0.0, c.from, c.until, 4.0};
    for (int stretch = 0; stretch < 3; ++stretch) {
      const double length = bounds[stretch + 1] - bounds[stretch];
      if (length <= 0.0) continue;
      OneDofBlock line;
      line.mass = mass;
      line.normal_force = mass * g;
      line.constant_force = c.pull;
      line.pair = stretch == 1 ? oiled : dry;
      line.x0 = x;
      line.v0 = v;
      const Trajectory numeric = solve_event_rk4(line, length, 1e-4);
      for (const double fraction : {0.25, 0.5, 1.0}) {
        const double t = bounds[stretch] + fraction * length;
        const IntermittentSlide exact = intermittent_slide(mass, c.pull, dry, oiled, c.from, c.until, t, g);
        EXPECT_NEAR(exact.distance, numeric.position(fraction * length), 1e-9) << "pull " << c.pull << " at " << t;
        EXPECT_NEAR(exact.speed, numeric.velocity(fraction * length), 1e-9) << "pull " << c.pull << " at " << t;
      }
      x = numeric.position(length);
      v = numeric.velocity(length);
    }
  }
}

// The driven wheel obeys Newton's laws on both sides of the traction limit: rolling, a = α·r,
// f = m·a and I·α = torque − f·r with f within the static limit; spinning, f = mu_k·m·g and the
// contact point's backward slip grows (α·r > a). At the limit the two agree on the friction,
// and a wheel of no inertia has the article's limit mu_s·m·g·r.
TEST(ClosedForms, DrivenWheelObeysNewtonOnBothSidesOfTheTractionLimit) {
  const double mass = 2.0, radius = 0.3, inertia = 0.5 * mass * radius * radius, mu_s = 0.6, mu_k = 0.5;
  const double limit = driven_wheel(mass, radius, inertia, 0.0, mu_s, mu_k, g).traction_limit;
  EXPECT_NEAR(limit, 1.5 * mu_s * mass * g * radius, 1e-12);
  for (const double torque : {0.0, 0.3 * limit, limit, 1.0001 * limit, 3.0 * limit}) {
    const DrivenWheel wheel = driven_wheel(mass, radius, inertia, torque, mu_s, mu_k, g);
    EXPECT_EQ(wheel.rolls, torque <= limit) << torque;
    EXPECT_NEAR(mass * wheel.acceleration, wheel.friction, 1e-12) << torque;
    EXPECT_NEAR(inertia * wheel.angular_acceleration, torque - wheel.friction * radius, 1e-12) << torque;
    if (wheel.rolls) {
      EXPECT_NEAR(wheel.angular_acceleration * radius, wheel.acceleration, 1e-12) << torque;
      EXPECT_LE(wheel.friction, mu_s * mass * g * (1.0 + 1e-12)) << torque;
    } else {
      EXPECT_NEAR(wheel.friction, mu_k * mass * g, 1e-12) << torque;
      EXPECT_GT(wheel.angular_acceleration * radius, wheel.acceleration) << torque;
    }
  }
  EXPECT_NEAR(driven_wheel(mass, radius, inertia, limit, mu_s, mu_k, g).friction, mu_s * mass * g, 1e-9);
  EXPECT_NEAR(driven_wheel(mass, radius, 0.0, 0.0, mu_s, mu_k, g).traction_limit, mu_s * mass * g * radius, 1e-12);
  // With mu_k above mu_s it rolls up to the larger coefficient, as the listener holds.
  EXPECT_TRUE(driven_wheel(mass, radius, inertia, 1.2 * limit, mu_s, 0.8, g).rolls);
}

}  // namespace
}  // namespace frictionlab
