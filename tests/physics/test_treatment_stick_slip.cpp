// The driven spring–block on Box2D against the exact event-driven solution: the stick-slip
// treatment converges as the step halves; the velocity threshold and Box2D's single
// coefficient stall, so the comparison is real.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "physics/scenarios.h"
#include "physics/scene.h"
#include "physics/wedge_model.h"

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

// A block that touches the floor through several fixtures (a box on feet) under the stick-slip
// treatment: being rigid it sticks or slides as a whole, so it must hold until the pull reaches
// mu_s·m·g, not creep while it holds, and break away then, like a block on one face does.
// The pull grows from zero at `rate` and acts at the height of the floor, as in the lesson
// contact_area, so it cannot tip the block or shift its load between the feet.
namespace {

constexpr double g = 9.81;
constexpr double mass = 1.0;
constexpr double rate = 2.0;  // N/s, the lesson's default pull_rate
constexpr float width = 0.4f, height = 0.08f, foot = 0.02f;

struct PulledBlock {
  std::unique_ptr<Scene> scene;
  b2Body* block = nullptr;
};

// feet = 0: the same block lying on its own face, one fixture and one contact.
PulledBlock make_block(int feet, double mu_s, double mu_k, double hz, double pull_rate = rate, double slope = 0.0) {
  PairTable table;
  table.add_material({"floor", 600.0, ""});
  table.add_material({"block", 1.0, ""});
  table.set_pair("block", "floor", {mu_s, mu_k, 0.0, 0.0});
  table.set_pair("block", "block", {mu_s, mu_k, 0.0, 0.0});
  StepSettings settings;
  settings.hz = hz;
  PulledBlock made;
  // A slope is made by tilting gravity: downhill is -x.
  const b2Vec2 gravity{static_cast<float>(-g * std::sin(slope)), static_cast<float>(-g * std::cos(slope))};
  made.scene = std::make_unique<Scene>(std::move(table), settings, gravity);
  Scene& scene = *made.scene;
  scene.add_box("floor", b2_staticBody, "floor", {0.0f, -0.5f}, 20.0f, 1.0f);
  const float lift = feet > 0 ? foot : 0.0f;
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  definition.position = {0.0f, 0.5f * height + lift + resting_gap};
  made.block = scene.add_body("block", definition);
  b2PolygonShape body;
  body.SetAsBox(0.5f * width, 0.5f * height);
  scene.add_fixture(made.block, body, "block");
  for (int i = 0; i < feet; ++i) {
    const float x = -0.5f * width + 0.5f * foot + static_cast<float>(i) * (width - foot) / static_cast<float>(feet - 1);
    b2PolygonShape shape;
    shape.SetAsBox(0.5f * foot, 0.5f * foot, {x, -0.5f * height - 0.5f * foot}, 0.0f);
    scene.add_fixture(made.block, shape, "block");
  }
  const double area = double{width} * height + feet * double{foot} * foot;
  for (b2Fixture* part = made.block->GetFixtureList(); part != nullptr; part = part->GetNext()) {
    part->SetDensity(static_cast<float>(mass / area));
  }
  made.block->ResetMassData();
  // At the floor's height (the middle of the resting gap): no moment about the contact.
  const b2Vec2 at{0.0f, -0.5f * height - lift - 0.5f * resting_gap};
  scene.add_applied_force({"pull", made.block, at, [pull_rate](double t) { return b2Vec2{static_cast<float>(pull_rate * t), 0.0f}; }});
  return made;
}

// How many of the block's contacts with the floor touch, and how many of those slip.
struct Touches {
  int touching = 0;
  int slipping = 0;
};
Touches touches(const Scene& scene, const b2Body* block) {
  Touches count;
  for (const b2ContactEdge* edge = block->GetContactList(); edge != nullptr; edge = edge->next) {
    if (!edge->contact->IsTouching()) continue;
    const ContactRecord* record = scene.friction().record(edge->contact);
    if (record == nullptr) continue;
    ++count.touching;
    if (record->friction.state == ContactState::slipping) ++count.slipping;
  }
  return count;
}

// What a pulled block did: the pull in the step that ended with it slipping, how far it moved
// before, its speed at `until`, and how many steps ended with its feet disagreeing.
struct PullRun {
  double breakaway_pull = -1.0;  // N, rate·t at the start of that step (-1: it never slipped)
  double crept = 0.0;            // m, the largest |x - x0| before that step
  double final_speed = 0.0;      // m/s, at `until`
  int split_steps = 0;           // steps that ended with some feet slipping and some stuck
};

// For a block made with the default pull rate.
PullRun pull_until(PulledBlock& made, double until) {
  Scene& scene = *made.scene;
  const float x0 = made.block->GetPosition().x;
  PullRun run;
  while (scene.time() < until - 1e-9) {
    const double pull = rate * scene.time();
    scene.step();
    const Touches now = touches(scene, made.block);
    if (now.slipping > 0 && now.slipping < now.touching) ++run.split_steps;
    if (run.breakaway_pull < 0.0) {
      if (now.slipping > 0) {
        run.breakaway_pull = pull;
      } else {
        run.crept = std::max(run.crept, static_cast<double>(std::abs(made.block->GetPosition().x - x0)));
      }
    }
  }
  run.final_speed = made.block->GetLinearVelocity().x;
  return run;
}

std::string feet_and_rate_name(const testing::TestParamInfo<std::tuple<int, double>>& info) {
  return std::to_string(std::get<0>(info.param)) + "_feet_at_" + std::to_string(static_cast<int>(std::get<1>(info.param))) +
         "_hz";
}

}  // namespace

// The closed form: a block pulled by r·t holds until r·t = mu_s·m·g and breaks away then, how
// ever many feet it stands on. The first slipping step is the one whose pull (sampled at its
// start) has passed the limit, so the measured pull lies within one step's growth r·h above
// it (and a hair below, for the solver's 1e-5 breakaway tolerance). Before the group kept one
// state, the six-footed block broke away at 7.2 N instead of 9.8 N (mu_s = 1, 240 Hz) after
// creeping 0.25 mm.
class FeetUnderAGrowingPull : public testing::TestWithParam<std::tuple<int, double>> {};

TEST_P(FeetUnderAGrowingPull, HoldWithoutCreepingUntilMuSTimesTheWeightThenSlideLikeAFace) {
  const auto [feet, hz] = GetParam();
  const double h = 1.0 / hz;
  for (double mu_s : {0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0}) {  // 2 is the lessons' slider maximum
    SCOPED_TRACE("mu_s = " + std::to_string(mu_s));
    const double mu_k = 0.7 * mu_s;
    const double limit = mu_s * mass * g;
    const double until = limit / rate + 0.5;  // half a second of sliding
    PulledBlock on_feet = make_block(feet, mu_s, mu_k, hz);
    const PullRun run = pull_until(on_feet, until);
    EXPECT_GE(run.breakaway_pull, limit * (1.0 - 1e-4));
    EXPECT_LE(run.breakaway_pull, limit + rate * h);
    // Held, it stays put to within a micrometre (one face: 1e-8 m).
    EXPECT_LT(run.crept, 1e-6);
    // One body, one state: every foot, loaded or not, says the same after every step.
    EXPECT_EQ(run.split_steps, 0);
    // Sliding, the feet give mu_k·m·g between them, as the face does: the same speed after
    // half a second, to 0.1 % (about 0.6 m/s at mu_s = 1).
    PulledBlock on_a_face = make_block(0, mu_s, mu_k, hz);
    const PullRun face = pull_until(on_a_face, until);
    EXPECT_NEAR(run.final_speed, face.final_speed, 1e-3 * face.final_speed);
  }
}

// Launched and left to slide, a block on feet stops where kinetic friction stops it,
// v0²/(2·mu_k·g), and stays there: the group re-sticks as one.
TEST_P(FeetUnderAGrowingPull, LaunchedSlideToRestAtTheKineticDistance) {
  const auto [feet, hz] = GetParam();
  const double mu_s = 0.5, mu_k = 0.4, v0 = 1.0;
  PulledBlock made = make_block(feet, mu_s, mu_k, hz, 0.0);
  made.block->SetLinearVelocity({static_cast<float>(v0), 0.0f});
  const float x0 = made.block->GetPosition().x;
  int split_steps = 0;
  Scene& scene = *made.scene;
  while (scene.time() < 1.0) {
    scene.step();
    const Touches now = touches(scene, made.block);
    if (now.slipping > 0 && now.slipping < now.touching) ++split_steps;
  }
  const double distance = v0 * v0 / (2.0 * mu_k * g);
  EXPECT_NEAR(made.block->GetPosition().x - x0, distance, 1e-3 * distance);
  EXPECT_EQ(touches(scene, made.block).slipping, 0);
  EXPECT_EQ(split_steps, 0);
}

INSTANTIATE_TEST_SUITE_P(Rates, FeetUnderAGrowingPull,
                         testing::Combine(testing::Values(3, 6), testing::Values(120.0, 240.0, 1000.0)), feet_and_rate_name);

// On a slope the load along the floor is there from the first step. Below atan(mu_s) the block
// on feet stays put; above it, it slides down at g·(sin θ - mu_k·cos θ), as one face does.
TEST_P(FeetUnderAGrowingPull, OnASlopeHoldBelowTheStaticAngleAndSlideAtTheKineticRateAbove) {
  const auto [feet, hz] = GetParam();
  const double mu_s = 0.6, mu_k = 0.4;
  const double below = std::atan(mu_s) - 0.05, above = std::atan(mu_s) + 0.05;  // 26° and 36°
  PulledBlock held = make_block(feet, mu_s, mu_k, hz, 0.0, below);
  const float x0 = held.block->GetPosition().x;
  while (held.scene->time() < 2.0) held.scene->step();
  EXPECT_LT(std::abs(held.block->GetPosition().x - x0), 1e-6f);
  EXPECT_EQ(touches(*held.scene, held.block).slipping, 0);

  PulledBlock slides = make_block(feet, mu_s, mu_k, hz, 0.0, above);
  PulledBlock face = make_block(0, mu_s, mu_k, hz, 0.0, above);
  while (slides.scene->time() < 1.0) {
    slides.scene->step();
    face.scene->step();
  }
  const double t = slides.scene->time();
  const double a = g * (std::sin(above) - mu_k * std::cos(above));
  // The breakaway correction reads the load as having grown during the first step, while here
  // it was all there at t = 0, so kinetic friction is credited with up to half a step too
  // little ((mu_s - mu_k)·g·cos θ·h/2 of speed; on one face as on feet).
  EXPECT_NEAR(-slides.block->GetLinearVelocity().x, a * t, (mu_s - mu_k) * g * std::cos(above) * 0.5 / hz);
  EXPECT_NEAR(slides.block->GetLinearVelocity().x, face.block->GetLinearVelocity().x, 1e-4 * a * t);
}

// A block held by a steady pull P while a lift r·t takes its weight off: the demand stays P and
// the limit, mu_s·(m·g − r·t), falls to it at t_b = (m·g − P/mu_s)/r. After it the block slides
// under P − mu_k·(m·g − r·t), so from rest at t_b its speed is a_b·τ + mu_k·r·τ²/(2m),
// τ = t − t_b, a_b = P·(1 − mu_k/mu_s)/m. Both forces act at the floor's height under the
// centre (no moment), evaluated at each step's start, where Box2D's velocities are those of the
// middles of the steps: the speed after a step is the exact one half a step earlier, for a force
// linear in time. The margin (demand less limit) is linear in time too, so the listener's
// placing of the crossing inside its step is exact and what is left is single precision and
// the breakaway tolerance: friction within 1e-5 of mu_s·N is taken for the limit, which moves
// the crossing by up to 1e-5·mu_s·N/(mu_s·r) and the speed by a_b times that; and each step's
// float velocity rounds by up to 6e-8 of the speed. Placed by the demand alone (which does not
// grow here), the crossing was put at the half step whatever it was: the speed was off by
// 8.3e-3, 7.5e-4, 5.2e-4 and 5.2e-4 m/s at 240, 330, 480 and 960 Hz.
TEST(StickSlipBreakaway, WhereTheLimitFallsUnderASteadyPullTheCrossingIsPlacedInsideTheStep) {
  constexpr double mu_s = 0.8, mu_k = 0.3, pull = 4.0, lift_rate = 3.0;  // N, N/s
  const double t_b = (mass * g - pull / mu_s) / lift_rate;
  const double a_b = pull * (1.0 - mu_k / mu_s) / mass;
  for (double hz : {240.0, 330.0, 480.0, 960.0}) {
    SCOPED_TRACE(hz);
    PulledBlock made = make_block(0, mu_s, mu_k, hz, 0.0);
    const b2Vec2 at{0.0f, -0.5f * height - 0.5f * resting_gap};
    made.scene->add_applied_force({"steady pull and lift", made.block, at, [](double t) {
                                     return b2Vec2{static_cast<float>(pull), static_cast<float>(lift_rate * t)};
                                   }});
    const double until = t_b + 0.5;
    while (made.scene->time() < until - 1e-9) made.scene->step();
    const double h = 1.0 / hz;
    const double tau = made.scene->time() - 0.5 * h - t_b;
    const double exact = a_b * tau + mu_k * lift_rate * tau * tau / (2.0 * mass);
    const double steps = made.scene->time() * hz;
    const double tolerance = a_b * 1e-5 * mass * g / lift_rate + steps * 6e-8 * exact;
    EXPECT_NEAR(made.block->GetLinearVelocity().x, exact, tolerance);
  }
}

namespace {
// A block on a level plank that a drive shakes sideways, x(t) = (a/ω²)·(1 − cos ω·t), hard
// enough that static friction cannot hold it at most of its stops (|a| > mu_s·g): in the
// plank's frame it slides back and forth, its sliding reversing where the plank's
// acceleration turns it, often between two steps (the driven plank's velocity changes once a
// step). The exact reduced model is the wedge's event solver on a level wedge (theory.wedge at
// theta0 = 0): s'' = -a(t) - friction/m along the plank, stuck while |a| <= mu_s·g, which a
// rigid block on a level plank that does not turn follows exactly. The sweep's failing wedge
// setting: it ended 0.069 m off the model at 240 Hz.
struct PlankShake {
  double mass = 0.4852, mu_s = 1.761, mu_k = 1.247;
  double a = -30.0, omega = 7.371;  // m/s², rad/s
};
// A dry block of this mass and these coefficients resting on a plank, stepped at hz.
Scene block_on_a_plank(double block_mass, double mu_s, double mu_k, double hz) {
  Block block;
  block.mass = block_mass;
  block.pair = FrictionPair{mu_s, mu_k, 0.0, 0.0};
  StepSettings settings;
  settings.hz = hz;
  return Scene(block_on_ground(block), settings);
}
struct ShakenPlankRun {
  double gap = 0.0;        // m: the largest gap between the world's slide and the model's
  double tolerance = 0.0;  // m: see below
};
ShakenPlankRun shaken_plank(const PlankShake& shake, double hz, double run_time) {
  Scene scene = block_on_a_plank(shake.mass, shake.mu_s, shake.mu_k, hz);
  const double amplitude = shake.a / (shake.omega * shake.omega);
  auto plank_x = [&](double t) { return amplitude * (1.0 - std::cos(shake.omega * t)); };
  b2Body* plank = scene.add_box("plank", b2_kinematicBody, "ground", {0, -0.5f}, 20, 1);
  scene.drive(plank, [&](double t) { return std::array<double, 2>{plank_x(t), -0.5}; }, nullptr);
  b2Body* body = scene.add_box("block", b2_dynamicBody, "block", {0, 0.1f + resting_gap}, 0.4f, 0.2f);
  // The drive moves the plank through its first step at that step's mean velocity, and the
  // block starts with it, as wedge.lua's does (the model's start, below, allows for it).
  const double h = scene.frame_step();
  scene.set_velocity(body, {static_cast<float>(plank_x(h) / h), 0.0f});
  WedgeDrive drive;
  drive.mass = shake.mass;
  drive.a_x = shake.a;
  drive.a_x_omega = shake.omega;
  drive.mu_s = shake.mu_s;
  drive.mu_k = shake.mu_k;
  // The model starts as the world's block does, not at rest, by wedge.lua's start_speed rule on
  // a level plank: the world's block moves with the plank through its first step, at its mean
  // velocity then (a·h/2 along x, against s), where the model's would start at rest on a plank
  // at rest. The world then holds the block through the first step that asks friction of it
  // (the second: in the first the plank moves at the block's own velocity) at the limit mu·N,
  // mu = max(mu_s, mu_k), where the model's slides at mu_k·N from t = 0; the breakaway
  // correction gives back (mu - mu_k)·N for a span late + h/2, placing the crossing of mu·N
  // `late` before the step's end as if the demand D had grown evenly through the step from what
  // the step before held (m·g·|sin θ|, 0 on a level plank): late = h·(D - mu·N)/D. But D came
  // all at once, so the block keeps (mu - mu_k)·g·(h/2 - late) more of its start than a·h/2
  // (0.0016 m/s here at 240 Hz, where the half step alone gave 0.0105: the world's slide at
  // 0.1 s is 1.2 mm from this model's, 0.8 mm from that one's: the world's start differs from
  // both rules by a residual not yet explained, which the tolerance's 3 mm covers). With the
  // start carried by the model, the tolerance has no start allowance of its own (it was a_x·h/2
  // + (mu_s - mu_k)·g·h/2 over the time to the first stop, 0.021 m of the 0.043 m allowed at
  // 240 Hz).
  const double mu = std::max(shake.mu_s, shake.mu_k);
  const double demand = std::abs(shake.a * std::cos(shake.omega * h));  // D/m, the drive at h
  const double late = demand > 0.0 ? std::clamp(h * (demand - mu * g) / demand, 0.0, h) : 0.0;
  const double kept = (mu - shake.mu_k) * g * (0.5 * h - late);
  drive.start_speed = (shake.a > 0.0 ? -1.0 : 1.0) * (std::abs(plank_x(h) / h) + kept);
  const WedgeRun model = solve_wedge(drive, WedgeLaw::coulomb, run_time, h);
  const double x0 = body->GetPosition().x - plank->GetPosition().x;
  ShakenPlankRun run;
  double path = 0.0;
  for (std::size_t k = 1; k < model.samples.size(); ++k) {
    scene.step();
    // The model's s runs down the slope, which on a level wedge is against the drive's +x.
    const double slide = -(body->GetPosition().x - plank->GetPosition().x - x0);
    run.gap = std::max(run.gap, std::abs(slide - model.samples[k].slide));
    path += std::abs(model.samples[k].slide - model.samples[k - 1].slide);
  }
  // The tolerance is the wedge lesson's for its slide, less its start (above): each stop,
  // reversal and breakaway is found within a step, which leaves the sliding between two events
  // off by what a step of the drive and of friction's switch change it; 0.2 % of the path slid
  // back and forth at 240 Hz, scaled with the step (first order: the gaps measured were 0.0174,
  // 0.0069 and 0.0029 m at 240, 480 and 960 Hz, each under half of the step before's; with each
  // reversal placed inside its step they are 0.0034, 0.0017 and 0.00085 m, what the start's
  // residual leaves, halving with the step), and 3 mm.
  run.tolerance = 0.002 * (240.0 * h) * path + 3e-3;
  return run;
}
}  // namespace

// Before the fix a stop the drive carried the block past was held for a step at mu_s·N and broke
// away with a correction for a span read from the last hold (0.02 m/s off at such stops), and
// the block ended 0.0697 m off at 240 Hz at its farthest (0.069 m at the end); against the model
// started as the world's block starts, 0.062 m at its farthest (0.0225 m allowed; 0.0174 after
// that fix, 0.0034 since a reversal inside a step is placed within it).
TEST(ShakenPlank, SlideFollowsTheExactModelWithinWhatFindingEachEventWithinAStepAllows) {
  for (double hz : {240.0, 480.0, 960.0}) {
    const ShakenPlankRun run = shaken_plank(PlankShake{}, hz, 5.0);
    EXPECT_LT(run.gap, run.tolerance) << hz << " Hz";
  }
}

namespace {
// A block on a level plank that starts at rest and is shaken sideways from rest, the plank's
// acceleration a(t) = A·sin(ω·t) along +x, so the world starts exactly as the model does: held,
// then it breaks away where |a| first passes mu_s·g, and from then on, with A well past mu_s·g,
// its sliding reverses at every stop (|a| is past mu_s·g at each). The exact reduced model, in
// the plank's frame (s: the block's place on the plank, u = s'):
//   held:      u = 0 while |a(t)| <= mu_s·g;
//   sliding d: u' = -a(t) - d·mu_k·g, so u(t) = u0 + (A/ω)(cos ωt - cos ωt0) - d·mu_k·g·(t - t0),
// each phase's end found by bisection to 1e-13 s.
struct SineShake {
  double mass, mu_s, mu_k;
  double a, omega;  // m/s², rad/s
};
struct ShakePhase {
  double t0, s0, u0;
  int way;  // 0 held, else the sign of u
};
class ShakenPlankModel {
 public:
  ShakenPlankModel(const SineShake& shake, double t_end) : shake_(shake) {
    const double limit = std::max(shake.mu_s, shake.mu_k) * g;
    phases_.push_back({0.0, 0.0, 0.0, 0});
    const double scan = 1e-4;  // s: well under the time between two events (0.3 s)
    for (;;) {
      const ShakePhase p = phases_.back();
      auto ended = [&](double t) { return p.way == 0 ? std::abs(acceleration(t)) > limit : p.way * speed(p, t) <= 0.0; };
      double lo = p.t0, hi = p.t0 + scan;
      while (hi < t_end && !ended(hi)) lo = std::exchange(hi, hi + scan);
      if (hi >= t_end) break;
      while (hi - lo > 1e-13) (ended(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
      const bool slides = std::abs(acceleration(hi)) > limit;
      if (p.way != 0 && slides) reversals_.push_back(hi);
      phases_.push_back({hi, place(p, hi), 0.0, slides ? (acceleration(hi) > 0.0 ? -1 : 1) : 0});
    }
  }
  double acceleration(double t) const { return shake_.a * std::sin(shake_.omega * t); }
  double jerk(double t) const { return shake_.a * shake_.omega * std::cos(shake_.omega * t); }
  double place(double t) const {
    std::size_t i = phases_.size() - 1;
    while (i > 0 && phases_[i].t0 > t) --i;
    return place(phases_[i], t);
  }
  const std::vector<double>& reversals() const { return reversals_; }
  const std::vector<ShakePhase>& phases() const { return phases_; }

 private:
  double speed(const ShakePhase& p, double t) const {
    if (p.way == 0) return 0.0;
    const double w = shake_.omega, k = shake_.mu_k * g;
    return p.u0 + (shake_.a / w) * (std::cos(w * t) - std::cos(w * p.t0)) - p.way * k * (t - p.t0);
  }
  double place(const ShakePhase& p, double t) const {
    if (p.way == 0) return p.s0;
    const double w = shake_.omega, k = shake_.mu_k * g, dt = t - p.t0;
    return p.s0 + (p.u0 - (shake_.a / w) * std::cos(w * p.t0)) * dt +
           (shake_.a / (w * w)) * (std::sin(w * t) - std::sin(w * p.t0)) - 0.5 * p.way * k * dt * dt;
  }
  SineShake shake_;
  std::vector<ShakePhase> phases_;
  std::vector<double> reversals_;
};

struct ReversalErrors {
  double largest = 0.0;  // m/s: the largest |error a reversal added| over the run
  double sum = 0.0;      // m/s: their sum
  double worst_share = 0.0;  // the largest error over its bound
  int count = 0;
};

// Runs the shaken block for run_time at hz and measures, at each reversal, the error it adds to
// the block's sliding speed: the world's sliding speed in a step (its velocity less the plank's:
// both are the step's means, x_{n+1} = x_n + h·v) against the exact mean over the same step,
// three steps after the reversal, less what the error three steps before it becomes across an
// exact reversal: a block sliding δ faster reaches the stop δ/(|a| + mu_k·g) later and slides
// back for that much less time, (|a| - mu_k·g)/(|a| + mu_k·g) of δ. Between events the sliding
// adds no error (a constant friction and the drive's exact change of velocity each step).
ReversalErrors reversal_errors(const SineShake& shake, double hz, double run_time) {
  Scene scene = block_on_a_plank(shake.mass, shake.mu_s, shake.mu_k, hz);
  // Centred on the origin over the run (the plank drifts at A/ω on average), where floats are
  // finest.
  const double x_start = -0.5 * (shake.a / shake.omega) * run_time;
  auto plank_x = [&](double t) {
    return x_start + (shake.a / shake.omega) * (t - std::sin(shake.omega * t) / shake.omega);
  };
  const float x0 = static_cast<float>(x_start);
  b2Body* plank = scene.add_box("plank", b2_kinematicBody, "ground", {x0, -0.5f}, 20, 1);
  scene.drive(plank, [&](double t) { return std::array<double, 2>{plank_x(t), -0.5}; }, nullptr);
  b2Body* body = scene.add_box("block", b2_dynamicBody, "block", {x0, 0.1f + resting_gap}, 0.4f, 0.2f);
  const ShakenPlankModel model(shake, run_time);
  const double h = scene.frame_step();
  std::vector<double> speed_error{0.0};  // per step, m/s
  while (scene.time() < run_time - 0.5 * h) {
    scene.step();
    const double t = scene.time();
    const double sliding = body->GetLinearVelocity().x - plank->GetLinearVelocity().x;
    speed_error.push_back(sliding - (model.place(t) - model.place(t - h)) / h);
  }
  ReversalErrors errors;
  const double k = shake.mu_k * g;
  const std::size_t away = 3;
  for (double t : model.reversals()) {
    const auto step = static_cast<std::size_t>(t / h) + 1;  // the step the reversal falls in
    if (step <= away || step + away >= speed_error.size()) continue;
    const double a = std::abs(model.acceleration(t));
    const double carried = (a - k) / (a + k) * speed_error[step - away];
    const double added = std::abs(speed_error[step + away] - carried);
    // The bound, from the method's error: the listener finds the stop from the sliding at the
    // step's span start and the drive's change over the span, h·a at its middle, as if the drive
    // were even through it. The drive's integral up to the stop τ is then off by |a'|·τ·(h - τ)/2
    // (at most |a'|·h²/8), and the step's mean sliding, read as the span start's, by |a'|·h²/24
    // (u'' = -a'); each moves the stop by itself over |a| + mu_k·g, the rate the sliding falls at,
    // and kinetic friction turns the other way that much early or late: 2·mu_k·g times it.
    // Together at most mu_k·g·|a'|·h²/(3·(|a| + mu_k·g)), second order. And the floats: Box2D's
    // velocities, a few metres a second, hold 7 digits (1e-6 m/s).
    const double bound = k * std::abs(model.jerk(t)) * h * h / (3.0 * (a + k)) + 1e-6;
    errors.largest = std::max(errors.largest, added);
    errors.sum += added;
    errors.worst_share = std::max(errors.worst_share, added / bound);
    ++errors.count;
  }
  return errors;
}
}  // namespace

// Before the fix the listener found a stop on a driven plank as if the drive's change of velocity
// between two steps came all at once at the step's start, and after the stop left the block the
// step's kinetic friction without the drive that carries it on: each reversal left the block's
// sliding off by up to mu_k·g·h (0.3 of it on average), which nothing took back while it slid,
// a first-order error (0.038 m/s at 240 Hz, 0.018 at 480 and 0.0045 at 960 at the worst
// reversal of the first shake, 200 to 800 times the bound; the sums fell by 2 or less a
// halving). Now each reversal is placed within its step, and the error it adds falls by about
// four each time the step halves (0.00018, 0.000043 and 0.000012 m/s; 0.97 of the bound at most).
TEST(ShakenPlank, EachReversalInsideAStepAddsAnErrorOfTheStepSquared) {
  // The wedge lesson's failing setting's block and friction, shaken at 20 m/s² (twice mu_s·g)
  // and 10 rad/s; and a lighter block with kinetic friction a third of static.
  for (const SineShake& shake : {SineShake{10.0, 0.9692, 0.7089, 20.0, 10.0}, SineShake{5.0, 1.2, 0.4, 18.0, 12.0}}) {
    std::map<double, ReversalErrors> errors;
    for (double hz : {240.0, 480.0, 960.0}) {
      errors[hz] = reversal_errors(shake, hz, 2.0);
      const std::string at = std::to_string(static_cast<int>(shake.a)) + "_at_" + std::to_string(static_cast<int>(hz)) + "_hz";
      RecordProperty("largest_reversal_error_m_per_s_shake_" + at, std::to_string(errors[hz].largest));
      RecordProperty("worst_share_of_bound_shake_" + at, std::to_string(errors[hz].worst_share));
      EXPECT_GE(errors[hz].count, 5) << hz << " Hz";
      EXPECT_LE(errors[hz].worst_share, 1.0) << hz << " Hz: the largest error a reversal added, "
                                             << errors[hz].largest << " m/s, is past its bound";
    }
    // Second order: a quarter each halving, allowing for where in its step each reversal falls.
    EXPECT_LT(errors[480.0].sum, errors[240.0].sum / 3.0);
    EXPECT_LT(errors[960.0].sum, errors[480.0].sum / 3.0);
  }
}
