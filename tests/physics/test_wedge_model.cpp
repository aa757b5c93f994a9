// The reduced wedge model (physics/wedge_model.h) against an independent solution of the same
// equations: Moreau's time stepping at a fine step, which knows nothing of phases or events.
// Each step it takes the impulse the surface must give to stop the block falling into it, and
// friction's impulse bounded by μ times that impulse (held if that is enough, sliding with μk
// otherwise). It is first order: at 2·10⁻⁶ s the two agree to 4 µm over 5 s (63 µm with a
// flight, whose lift-off and landing the stepping finds only to its step).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/materials.h"
#include "physics/wedge_model.h"

namespace frictionlab {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

struct Fine {
  double s = 0, v = 0, d = 0, dd = 0;
  double work_friction = 0;
};

// Moreau's scheme for the reduced model, steps of h to t_end; `at` is called after each step.
template <class At>
void time_step(const WedgeDrive& drive, WedgeLaw law, double t_end, double h, At at) {
  Fine x;
  const double m = drive.mass, mu_break = std::max(drive.mu_s, drive.mu_k);
  const auto steps = static_cast<long>(std::llround(t_end / h));
  for (long i = 0; i < steps; ++i) {
    const double t = (static_cast<double>(i) + 0.5) * h;  // forces at mid-step
    const double force = drive.driving_force(t), normal = drive.normal_force(t);
    double v_free = x.v + h * force / m;
    double dd_free = x.dd - h * normal / m;
    double impulse = 0.0;  // the surface's normal impulse this step
    if (x.d <= 0.0 && dd_free <= 0.0) {
      impulse = -m * dd_free;
      dd_free = 0.0;
    }
    double v_new = v_free;
    if (impulse > 0.0) {
      if (law == WedgeLaw::article) {
        v_new = v_free - (force < 0 ? -1.0 : 1.0) * drive.mu_k * impulse / m;
      } else if (x.v == 0.0 && std::abs(m * v_free) <= mu_break * impulse) {
        v_new = 0.0;
      } else {
        const double sense = x.v != 0.0 ? (x.v < 0 ? -1.0 : 1.0) : (v_free < 0 ? -1.0 : 1.0);
        v_new = v_free - sense * drive.mu_k * impulse / m;
        if (v_new * sense < 0.0) v_new = 0.0;  // friction stops it within the step
      }
      x.work_friction += (m * (v_new - v_free)) * 0.5 * (x.v + v_new);
    }
    x.v = v_new;
    x.dd = dd_free;
    x.s += h * x.v;
    x.d = std::max(0.0, x.d + h * x.dd);
    at(static_cast<double>(i + 1) * h, x);
  }
}

// Positions of the two over [0, t_end], compared every millisecond.
double worst_slide_difference(const WedgeDrive& drive, WedgeLaw law, double t_end) {
  const WedgeRun run = solve_wedge(drive, law, t_end, 1e-3);
  double worst = 0.0;
  const double h = 2e-6;
  time_step(drive, law, t_end, h, [&](double t, const Fine& x) {
    const double k = t / 1e-3;
    if (std::abs(k - std::round(k)) < 1e-6) {
      const auto index = static_cast<std::size_t>(std::llround(k));
      worst = std::max(worst, std::abs(run.samples[index].slide - x.s));
    }
  });
  return worst;
}

// The article's worked example 2: 1.5 kg, θ = 10°·sin 3t, a = 2·cos 2t, μs 0.25, μk 0.18.
WedgeDrive example_two() {
  return {1.5, 10 * degree, 3.0, 2.0, 2.0, 0.25, 0.18};
}
// Worked example 1: 2 kg, 15°, 4 rad/s, a constant 3 m/s², μk 0.25 (its μs is not given: 0.25).
WedgeDrive example_one() {
  return {2.0, 15 * degree, 4.0, 3.0, 0.0, 0.25, 0.25};
}

TEST(WedgeModel, DriveIsTheArticlesForces) {
  const WedgeDrive drive = example_two();
  const double t = 0.7, theta = 10 * degree * std::sin(2.1), a = 2.0 * std::cos(1.4);
  EXPECT_NEAR(drive.driving_force(t), 1.5 * (9.81 * std::sin(theta) + a * std::cos(theta)), 1e-12);
  EXPECT_NEAR(drive.normal_force(t), 1.5 * (9.81 * std::cos(theta) - a * std::sin(theta)), 1e-12);
  // The pivot starts at rest: x = a_x(1 − cos ω_a t)/ω_a², and ½a_x t² for a constant a_x.
  EXPECT_NEAR(drive.wedge_position(t), 2.0 * (1 - std::cos(1.4)) / 4.0, 1e-12);
  EXPECT_NEAR(example_one().wedge_position(t), 0.5 * 3.0 * t * t, 1e-12);
}

TEST(WedgeModel, MatchesFineTimeSteppingWithinAMillimetre) {
  EXPECT_LT(worst_slide_difference(example_two(), WedgeLaw::coulomb, 5.0), 2e-5);
  EXPECT_LT(worst_slide_difference(example_one(), WedgeLaw::coulomb, 5.0), 2e-5);
  EXPECT_LT(worst_slide_difference(example_one(), WedgeLaw::article, 5.0), 2e-5);
  EXPECT_LT(worst_slide_difference(example_two(), WedgeLaw::article, 5.0), 2e-5);
}

// With a_x large the wedge falls away from the block at the steep end of each swing: N < 0.
TEST(WedgeModel, LosesContactFliesAndLandsAsFineTimeStepping) {
  const WedgeDrive drive{1.0, 30 * degree, 2.0, 25.0, 3.0, 0.5, 0.4};
  const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 5.0, 1e-3);
  const auto count = [&](WedgeEventKind kind) {
    return std::count_if(run.events.begin(), run.events.end(), [&](const WedgeEvent& e) { return e.kind == kind; });
  };
  ASSERT_GE(count(WedgeEventKind::lift_off), 1);
  ASSERT_GE(count(WedgeEventKind::landing), 1);
  // It lifts where N(t) = m(g cos θ − a sin θ) reaches 0.
  for (const WedgeEvent& e : run.events) {
    if (e.kind == WedgeEventKind::lift_off) {
      EXPECT_NEAR(drive.normal_force(e.t), 0.0, 1e-9);
    }
  }
  EXPECT_LT(worst_slide_difference(drive, WedgeLaw::coulomb, 5.0), 2e-4);
  EXPECT_LT(worst_slide_difference(drive, WedgeLaw::article, 5.0), 2e-4);
}

// Landing while sliding, only kinetic friction's impulse acts: a block with μs 1 and μk 0.3 that
// lands sliding faster than μk times its fall goes on sliding (the model stopped it with μs, and
// ended 2.09 m from the fine stepping).
TEST(WedgeModel, ALandingStopsTheBlockOnlyByKineticFriction) {
  const WedgeDrive drive{1.0, 40 * degree, 1.0, 30.0, 5.0, 1.0, 0.3};
  const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 5.0, 1e-3);
  ASSERT_GE(std::count_if(run.events.begin(), run.events.end(),
                          [](const WedgeEvent& e) { return e.kind == WedgeEventKind::landing; }),
            1);
  EXPECT_LT(worst_slide_difference(drive, WedgeLaw::coulomb, 5.0), 2e-4);
}

// ΔK = W_gravity + W_pseudo + W_friction (+ what landings take), state by state.
TEST(WedgeModel, EnergyBooksBalance) {
  WedgeDrive turning = example_two();
  turning.rotation = true, turning.centre_height = 0.07, turning.start = 0.5;
  WedgeDrive flying_turning{1.0, 30 * degree, 2.0, 25.0, 3.0, 0.5, 0.4};
  flying_turning.rotation = true, flying_turning.centre_height = 0.07;
  for (const WedgeDrive& drive : {example_one(), example_two(), WedgeDrive{1.0, 30 * degree, 2.0, 25.0, 3.0, 0.5, 0.4},
                                  turning, flying_turning}) {
    const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 5.0, 1e-2);
    for (const WedgeState& state : run.samples) {
      const double books = state.work_gravity + state.work_pseudo + state.work_friction + state.work_landings +
                           state.work_rotation;
      EXPECT_NEAR(kinetic_energy(drive, state), books, 1e-9 * (1 + std::abs(state.work_gravity)));
      EXPECT_LE(state.work_friction, 1e-12);  // Coulomb's friction only takes energy
    }
  }
}

// Friction's work against the fine stepping's own sum of impulse × mean velocity.
TEST(WedgeModel, FrictionWorkMatchesFineTimeStepping) {
  const WedgeDrive drive = example_two();
  const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 5.0, 1e-3);
  double fine = 0.0;
  time_step(drive, WedgeLaw::coulomb, 5.0, 2e-6, [&](double, const Fine& x) { fine = x.work_friction; });
  EXPECT_NEAR(run.samples.back().work_friction, fine, 1e-5 * std::abs(fine));
}

// Sticking: the block stays exactly put while |F| <= μs·N, and slips as soon as it is not.
TEST(WedgeModel, SlipWindowsAreWhereStaticFrictionIsNotEnough) {
  const WedgeDrive drive = example_two();
  const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 5.0, 1e-3);
  ASSERT_FALSE(run.slip_windows.empty());
  // Each window opens at a breakaway, where |F| = μs·N.
  for (const auto& [from, to] : run.slip_windows) {
    EXPECT_NEAR(std::abs(drive.driving_force(from)), drive.mu_s * drive.normal_force(from), 1e-9);
    EXPECT_GT(to, from);
  }
  for (const WedgeState& state : run.samples) {
    if (state.contact == WedgeContact::stick) {
      EXPECT_EQ(state.speed, 0.0);
      EXPECT_LE(std::abs(drive.driving_force(state.t)), drive.mu_s * drive.normal_force(state.t) + 1e-12);
    }
  }
}

// The article's equation never sticks, and its friction, opposing the driving force rather than
// the sliding, pushes the block along whenever the two disagree: over example 2 it gives energy
// (+2.2 J by 5 s), where Coulomb's friction only ever takes it.
TEST(WedgeModel, ArticleLawFrictionGivesEnergy) {
  const WedgeRun article = solve_wedge(example_two(), WedgeLaw::article, 5.0, 1e-3);
  for (const WedgeState& state : article.samples) EXPECT_NE(state.contact, WedgeContact::stick);
  EXPECT_GT(article.samples.back().work_friction, 1.0);
  const WedgeRun right = solve_wedge(example_two(), WedgeLaw::coulomb, 5.0, 1e-3);
  EXPECT_LT(right.samples.back().work_friction, -1.0);
}

// The turning frame's terms on a held block: the surface's push is the reduced one less m·θ'²·z
// (the block's centre is z above the surface line) and plus m·θ''·ρ a distance ρ up the slope;
// friction holds against F less m(θ''·z + θ'²·ρ).
TEST(WedgeModel, RotationTermsActOnAHeldBlockAsTheyShould) {
  // Held (μs large), a block ρ up the slope: N = N_reduced + m(θ''·ρ − θ'²·z).
  WedgeDrive held{1.0, 10 * degree, 3.0, 0.0, 0.0, 5.0, 4.0};
  held.rotation = true, held.centre_height = 0.07, held.start = 0.4;
  const WedgeRun run = solve_wedge(held, WedgeLaw::coulomb, 2.0, 1e-2);
  for (const WedgeState& state : run.samples) {
    ASSERT_EQ(state.contact, WedgeContact::stick);
    const double t = state.t, rate = held.angular_velocity(t);
    EXPECT_NEAR(state.normal, held.normal_force(t) + held.angular_acceleration(t) * 0.4 - rate * rate * 0.07, 1e-12);
    // and friction holds against F + m(−θ''·z − θ'²·ρ)
    EXPECT_NEAR(-state.friction, held.driving_force(t) - held.angular_acceleration(t) * 0.07 - rate * rate * 0.4, 1e-12);
  }
}

// A slipping block's normal force on the turning surface: N_reduced + m(θ''·ρ − θ'²·z) − 2m·θ'·s'
// (ρ up the slope from the pivot, z the centre's height, s' the slide down the slope). The
// Coriolis term is the last: the block sliding across a turning surface is pressed or lifted.
TEST(WedgeModel, ASlippingBlockOnTheTurningSurfaceFeelsCoriolis) {
  WedgeDrive drive = example_two();
  drive.theta0 = 20 * degree, drive.mu_s = drive.mu_k = 0.1;
  drive.rotation = true, drive.centre_height = 0.09, drive.start = 0.3;
  const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 3.0, 1e-2);
  int slipping = 0;
  double largest_coriolis = 0.0;
  for (const WedgeState& state : run.samples) {
    if (state.contact != WedgeContact::slip) continue;
    ++slipping;
    const double t = state.t, rate = drive.angular_velocity(t), rho = drive.start - state.slide;
    const double coriolis = -2.0 * drive.mass * rate * state.speed;
    largest_coriolis = std::max(largest_coriolis, std::abs(coriolis));
    EXPECT_NEAR(state.normal,
                drive.normal_force(t) +
                    drive.mass * (drive.angular_acceleration(t) * rho - rate * rate * drive.centre_height) + coriolis,
                1e-9);
  }
  EXPECT_GT(slipping, 100);
  EXPECT_GT(largest_coriolis, 0.5);  // newtons: the term is there to be seen
}

// An event on a sample's instant (a breakaway at exactly t = 1 s, sampled every ms): recorded, not
// stepped over in zero-length steps until the million-event limit. μs a few ulps either side.
TEST(WedgeModel, AnEventOnASampleInstantIsRecordedOnce) {
  WedgeDrive drive{1.0, 0.6, 1.0, 0.0, 0.0, 0.0, 0.2};
  const double held_to = std::tan(0.6 * std::sin(1.0));
  double mu_s = held_to;
  for (int i = 0; i < 20; ++i) mu_s = std::nextafter(mu_s, 0.0);
  for (int i = 0; i < 40; ++i, mu_s = std::nextafter(mu_s, 1.0)) {
    drive.mu_s = mu_s;
    EXPECT_NO_THROW(solve_wedge(drive, WedgeLaw::coulomb, 2.0, 1e-3)) << "mu_s " << mu_s;
  }
}

// A block started moving (start_speed) on a level, still plank slides to rest under kinetic
// friction alone: v0²/(2·μk·g) in v0/(μk·g), either way, and stays there; and with the turn's
// terms on a plank that does not turn, the same. This is what the wedge lesson's ΔK row runs to
// see what the world's start does.
TEST(WedgeModel, ABlockStartedMovingSlidesToRestAsKineticFrictionSays) {
  for (const bool rotation : {false, true}) {
    for (const double v0 : {0.8, -0.5}) {
      WedgeDrive drive{2.0, 0.0, 0.0, 0.0, 0.0, 0.4, 0.25};
      drive.rotation = rotation;
      drive.start_speed = v0;
      const double g = drive.g;
      const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 1.0, 1e-3);
      EXPECT_EQ(run.samples.front().speed, v0);
      EXPECT_EQ(run.samples.front().contact, WedgeContact::slip);
      const double stop = std::abs(v0) / (0.25 * g);
      ASSERT_FALSE(run.events.empty());
      EXPECT_EQ(run.events.front().kind, WedgeEventKind::stop);
      // Events are located to 1e-13 s; RK4 is exact on a constant deceleration.
      EXPECT_NEAR(run.events.front().t, stop, 1e-12);
      EXPECT_NEAR(run.samples.back().slide, v0 * std::abs(v0) / (2 * 0.25 * g), 1e-12);
      EXPECT_EQ(run.samples.back().speed, 0.0);
      // The books: all the kinetic energy it started with went to friction.
      EXPECT_NEAR(run.samples.back().work_friction, -0.5 * 2.0 * v0 * v0, 1e-12);
    }
  }
}

// The article's friction opposes F: with no F at all (a level, still surface) there is none,
// and the block stays put.
TEST(WedgeModel, ArticleLawWithoutADrivingForceLeavesTheBlockAlone) {
  const WedgeRun run = solve_wedge(WedgeDrive{1.0, 0.0, 3.0, 0.0, 0.0, 0.3, 0.2}, WedgeLaw::article, 1.0, 1e-2);
  for (const WedgeState& state : run.samples) EXPECT_EQ(state.slide, 0.0);
}

// The reduced equations stepped as a Box2D world with the listener steps them, on a level plank
// shaken at a constant 5 m/s² (μs 0.3, μk 0.2, so it slips from the start): the first step
// asks nothing (the plank moves at the block's velocity), so it is held with the margin −μs·m·g;
// the second breaks away, and is paid (a − μs·g)·h and (μs − μk)·g·(late + h/2), late =
// h·(a − μs·g)/a from the margin's growth; from then on A = a − μk·g a step. So after N steps
// the speed is A·t less 2·h·A and plus that payment, exactly; the slide (at each step's end
// speed) is first order off ½·A·t², halving with the step.
TEST(WedgeModel, SteppedAsTheWorldTheBreakawayIsPaidAndTheSlideIsFirstOrder) {
  const double a = 5.0, mu_s = 0.3, mu_k = 0.2;
  const WedgeDrive drive{1.0, 0.0, 0.0, a, 0.0, mu_s, mu_k};
  const double g = drive.g, big_a = a - mu_k * g;
  double gaps[2];
  for (const int rate : {240, 480}) {
    const double h = 1.0 / rate;
    const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 1.0, h);
    ASSERT_EQ(run.samples[1].contact, WedgeContact::slip);
    const WedgeStepped stepped = step_as_the_world(drive, run, h);
    ASSERT_EQ(stepped.speed.size(), run.samples.size());
    const double late = h * (a - mu_s * g) / a;
    const double paid = (a - mu_s * g) * h + (mu_s - mu_k) * g * (late + 0.5 * h);
    const std::size_t last = run.samples.size() - 1;
    const double t = static_cast<double>(last) * h;
    // Sums of a few hundred steps of doubles: 1e-12 m/s.
    EXPECT_NEAR(stepped.speed[last], big_a * t - 2.0 * h * big_a + paid, 1e-12) << rate << " Hz";
    EXPECT_EQ(stepped.speed[1], 0.0) << "the first step is held";
    gaps[rate == 240 ? 0 : 1] = stepped.slide[last] - 0.5 * big_a * t * t;
  }
  // First order: the gap halves with the step (to 5 %: the next order's share at these steps).
  EXPECT_NEAR(gaps[0] / gaps[1], 2.0, 0.1) << gaps[0] << " m at 240 Hz, " << gaps[1] << " m at 480 Hz";
}

// The stepped lists end where the model's block first leaves the surface.
TEST(WedgeModel, SteppedAsTheWorldEndsAtTheFirstFlight) {
  const WedgeDrive drive{1.0, 30 * degree, 2.0, 25.0, 3.0, 0.5, 0.4};
  const double h = 1.0 / 240;
  const WedgeRun run = solve_wedge(drive, WedgeLaw::coulomb, 5.0, h);
  std::size_t first_flight = 0;
  while (first_flight < run.samples.size() && run.samples[first_flight].contact != WedgeContact::flight) ++first_flight;
  ASSERT_LT(first_flight, run.samples.size()) << "no flight to end at";
  EXPECT_EQ(step_as_the_world(drive, run, h).slide.size(), first_flight);
}

TEST(WedgeModel, RefusesBadParameters) {
  WedgeDrive drive = example_two();
  drive.mass = 0;
  EXPECT_THROW(solve_wedge(drive, WedgeLaw::coulomb, 1.0, 1e-3), InvalidInput);
  drive = example_two();
  drive.mu_k = -0.1;
  EXPECT_THROW(solve_wedge(drive, WedgeLaw::coulomb, 1.0, 1e-3), InvalidInput);
  EXPECT_THROW(solve_wedge(example_two(), WedgeLaw::coulomb, 10.0, 1e-9), InvalidInput);
}

}  // namespace
}  // namespace frictionlab
