// Box2D through the friction listener at 240 Hz with 8 velocity iterations, against the
// closed forms, with the tolerances the physics-core issue sets.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/closed_forms.h"
#include "physics/scenarios.h"
#include "physics/scene.h"

using namespace frictionlab;

namespace {
const StepSettings at_240_hz;  // the defaults: 240 Hz, 8 velocity iterations, stick-slip
}

class InclineAtMuS : public ::testing::TestWithParam<double> {};

TEST_P(InclineAtMuS, SticksJustBelowTheStickingAngle) {
  Incline incline;
  incline.block.pair = {GetParam(), 0.7 * GetParam(), 0.0, 0.0};
  incline.angle = 0.98 * theory::sticking_angle(GetParam());
  const Measurement creep = measure_incline_creep(incline, at_240_hz, 3.0);
  EXPECT_LT(std::abs(creep.measured), 1e-4) << "creep over 3 s, m";
}

TEST_P(InclineAtMuS, SlidesJustAboveWithKineticAcceleration) {
  Incline incline;
  incline.block.pair = {GetParam(), 0.7 * GetParam(), 0.0, 0.0};
  incline.angle = 1.02 * theory::sticking_angle(GetParam());
  const Measurement a = measure_incline_acceleration(incline, at_240_hz);
  EXPECT_NEAR(a.measured, a.predicted, 0.01 * a.predicted);
  EXPECT_GT(a.predicted, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Coefficients, InclineAtMuS, ::testing::Values(0.3, 0.6, 1.0));

TEST(Incline, RegularizedLawCreepsWhereStickSlipHolds) {
  // The tribology article's warning: with F = mu_s·N·v/eps a block below the sticking angle
  // never rests; it creeps at the speed where that force balances the slope, eps·tanθ/mu_s.
  // (eps is chosen so that 240 Hz is inside the explicit law's stable range h < 2·eps/(mu_s·g).)
  Incline incline;
  incline.angle = 0.98 * theory::sticking_angle(incline.block.pair.mu_s);
  StepSettings regularized = at_240_hz;
  regularized.treatment = FrictionTreatment::regularized;
  regularized.threshold_speed = 0.05;
  auto scene = make_incline(incline, regularized);
  for (int i = 0; i < 720; ++i) scene->step();
  const double creep_speed = scene->probe("speed").history.back();
  const double predicted = regularized.threshold_speed * std::tan(incline.angle) / incline.block.pair.mu_s;
  EXPECT_NEAR(creep_speed, predicted, 0.05 * predicted) << "regularized friction creeps at eps·tanθ/mu_s";
}

TEST(PulledBlock, BreaksAwayAtMuSNAndSlidesAgainstMuKN) {
  for (const FrictionPair pair : {FrictionPair{0.6, 0.4, 0, 0}, FrictionPair{0.3, 0.22, 0, 0}}) {
    Block block;
    block.pair = pair;
    const Measurement breakaway = measure_breakaway_force(block, at_240_hz);
    EXPECT_NEAR(breakaway.measured, breakaway.predicted, 0.01 * breakaway.predicted);
    const Measurement sliding = measure_sliding_friction(block, at_240_hz);
    EXPECT_NEAR(sliding.measured, sliding.predicted, 0.01 * sliding.predicted);
  }
}

TEST(PulledBlock, PlainBox2DBreaksAwayTooEarly) {
  // One coefficient for both: the block lets go at mu_k·N, so the test above is not trivial.
  StepSettings box2d = at_240_hz;
  box2d.treatment = FrictionTreatment::box2d;
  Block block;
  const Measurement breakaway = measure_breakaway_force(block, box2d);
  EXPECT_LT(breakaway.measured, 0.8 * breakaway.predicted);
}

TEST(SlideToRest, DistanceWithViscousTermWithinOnePercent) {
  Slide slide;
  slide.block.pair.c = 2.0;
  const Measurement d = measure_slide_distance(slide, at_240_hz);
  EXPECT_NEAR(d.measured, d.predicted, 0.01 * d.predicted);
}

TEST(SlideToRest, DistanceWithQuadraticTermWithinOnePercent) {
  Slide slide;
  slide.block.pair.b = 0.5;
  const Measurement d = measure_slide_distance(slide, at_240_hz);
  EXPECT_NEAR(d.measured, d.predicted, 0.01 * d.predicted);
}

TEST(SlideToRest, DistanceWithBothTermsAndCoulombAlone) {
  Slide slide;
  const Measurement dry = measure_slide_distance(slide, at_240_hz);
  EXPECT_NEAR(dry.measured, dry.predicted, 0.01 * dry.predicted);
  slide.block.pair.c = 1.0;
  slide.block.pair.b = 0.3;
  const Measurement wet = measure_slide_distance(slide, at_240_hz);
  EXPECT_NEAR(wet.measured, wet.predicted, 0.01 * wet.predicted);
  EXPECT_LT(wet.measured, 0.8 * dry.measured) << "the damping terms really act";
}

TEST(PushedBox, TipsAboveHalfWidthOverMuSAndSlidesBelowAtThePredictedPush) {
  // Below d/(2 mu_s) it slides when the push reaches mu_s·W; above, it tips when the push's
  // moment about the front edge, F·h, reaches the weight's, W·d/2: both within 1 %.
  for (double mu_s : {0.4, 0.8}) {
    PushedBox box;
    box.block.pair = {mu_s, 0.8 * mu_s, 0.0, 0.0};
    const double weight = box.block.mass * standard_gravity;
    const double tip = theory::tip_height(box.block.width, mu_s);
    ASSERT_LT(1.2 * tip, box.block.height) << "the push must land on the box's side";
    for (double factor : {0.8, 1.2}) {
      box.push_height = factor * tip;
      const theory::PushOutcome expected = theory::push_outcome(weight, box.block.width, box.push_height, mu_s);
      const PushResult seen = run_pushed_box(box, at_240_hz, 20.0);
      EXPECT_EQ(seen.tipped, factor > 1.0) << "mu_s " << mu_s << ", pushed at " << factor << " × d/(2 mu_s)";
      EXPECT_EQ(seen.tipped, expected.tips);
      EXPECT_NEAR(seen.force, expected.force, 0.01 * expected.force) << "mu_s " << mu_s << ", factor " << factor;
    }
  }
}

TEST(ViscousTerm, StableAtHcOverMOfOneHundred) {
  // An explicit drag force would reverse the velocity in one step here (h·c/m >= 2).
  Slide slide;
  slide.block.pair = {0.0, 0.0, 100.0 * slide.block.mass * at_240_hz.hz, 0.0};
  slide.launch_speed = 1.0;
  auto scene = make_slide(slide, at_240_hz);
  b2Body* block = scene->body("block");
  double previous = slide.launch_speed;
  for (int i = 0; i < 240; ++i) {
    scene->step();
    const double v = block->GetLinearVelocity().x;
    // Round-off of Box2D's float solver is allowed; a reversal of any size is not.
    ASSERT_GE(v, -1e-6 * slide.launch_speed) << "reversed at step " << i;
    ASSERT_LE(std::abs(v), std::abs(previous) + 1e-6 * slide.launch_speed) << "grew at step " << i;
    previous = v;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(ViscousTerm, DecaysExponentiallyOnFrictionlessGround) {
  // mu = 0: only c acts, v(t) = v0·exp(-c t / m). Box2D's velocities belong to the middle of
  // the step just taken, t - h/2; the drag step is exact, so only the leapfrog start (second
  // order) and float round-off remain.
  Slide slide;
  slide.block.pair = {0.0, 0.0, 2.0, 0.0};
  auto scene = make_slide(slide, at_240_hz);
  for (int i = 0; i < 240; ++i) scene->step();
  const double t = scene->time() - 0.5 * scene->frame_step();
  const double predicted = slide.launch_speed * std::exp(-2.0 * t / slide.block.mass);
  EXPECT_NEAR(scene->body("block")->GetLinearVelocity().x, predicted, 1e-3 * predicted);
}

TEST(PulledBlock, KineticAboveStaticBreaksAwayAtMuKN) {
  // mu_k > mu_s is allowed: a push between mu_s·N and mu_k·N could not keep the block moving,
  // so it breaks away only at mu_k·N, and slides against mu_k·N without flickering back.
  Block block;
  block.pair = {0.3, 0.5, 0.0, 0.0};
  const Measurement breakaway = measure_breakaway_force(block, at_240_hz);
  EXPECT_NEAR(breakaway.measured, 0.5 * block.mass * standard_gravity, 0.01 * breakaway.predicted);
  const Measurement sliding = measure_sliding_friction(block, at_240_hz);
  EXPECT_NEAR(sliding.measured, sliding.predicted, 0.01 * sliding.predicted);
}

namespace {
// A disk on flat ground touches it at one point, where rotation is free.
b2Body* add_disk(Scene& scene, float radius, b2Vec2 velocity, bool fixed_rotation) {
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  definition.position = {0.0f, radius + resting_gap};
  definition.linearVelocity = velocity;
  definition.fixedRotation = fixed_rotation;
  b2Body* disk = scene.add_body("disk", definition);
  b2CircleShape circle;
  circle.m_radius = radius;
  scene.add_fixture(disk, circle, "block");
  return disk;
}
}  // namespace

TEST(ViscousTerm, StableAndExactAtOnePointContactsToo) {
  // A sliding puck that cannot turn (fixed rotation) under viscous drag alone decays as
  // v0·exp(-c t/m); with h·c/m = 100 it must neither reverse nor grow.
  for (const double c_over_m_h : {0.5, 100.0}) {
    Block block;
    block.pair = {0.0, 0.0, 0.0, 0.0};
    PairTable table = block_on_ground(block);
    Scene scene(std::move(table));
    scene.add_box("ground", b2_staticBody, "ground", {0, -0.5f}, 400, 1);
    b2Body* puck = add_disk(scene, 0.2f, {2.0f, 0.0f}, true);
    const double mass = puck->GetMass();
    const double c = c_over_m_h * mass * at_240_hz.hz;
    scene.pairs().set_pair("block", "ground", {0.0, 0.0, c, 0.0});
    double previous = 2.0;
    for (int i = 0; i < 48; ++i) {
      scene.step();
      const double v = puck->GetLinearVelocity().x;
      ASSERT_GE(v, -1e-6) << "reversed at step " << i;
      ASSERT_LE(std::abs(v), std::abs(previous) + 1e-6) << "grew at step " << i;
      previous = v;
    }
    const double t = scene.time() - 0.5 * scene.frame_step();
    const double predicted = 2.0 * std::exp(-c * t / mass);
    EXPECT_NEAR(previous, predicted, 1e-3 * 2.0) << "h·c/m = " << c_over_m_h;
  }
}

TEST(ViscousTerm, LargeQuadraticTermOnARollingDiskStaysStable) {
  // A free disk under a huge quadratic drag: the contact point's velocity (slide plus spin)
  // is damped towards rolling, never past it.
  Block block;
  block.pair = {0.0, 0.0, 0.0, 1e5};
  Scene scene(block_on_ground(block));
  scene.add_box("ground", b2_staticBody, "ground", {0, -0.5f}, 400, 1);
  b2Body* disk = add_disk(scene, 0.2f, {2.0f, 0.0f}, false);
  for (int i = 0; i < 240; ++i) {
    scene.step();
    const float slip = disk->GetLinearVelocity().x + disk->GetAngularVelocity() * 0.2f;  // contact point speed
    ASSERT_TRUE(std::isfinite(slip));
    // The drag acts at the manifold point, a few millimetres inside the rim, so the rim's slip
    // may end a hair past zero: 1e-3 of the launch speed allows for that, a reversal does not.
    ASSERT_GE(slip, -2e-3f) << "slip reversed at step " << i;
    ASSERT_LE(disk->GetLinearVelocity().x, 2.0f + 1e-4f);
  }
  EXPECT_GT(disk->GetLinearVelocity().x, 0.5f) << "drag on the contact spins the disk up; it keeps rolling";
}

// A rigid block standing on three feet touches the floor through three contacts, and how it
// shares its weight between three feet in a row is not decided by statics (the solver puts
// most on the middle one). Being rigid it sticks or slides as a whole: it must break away when
// the pull reaches mu_s times its whole weight, not when the most lightly loaded foot reaches
// mu_s times its own share. Judged foot by foot it went 0.2 N early (4.22 N against 4.41 N).
TEST(BlockOnFeet, BreaksAwayAtMuSTimesItsWholeWeightHoweverTheLoadIsShared) {
  for (const int feet : {3, 6}) {
    PairTable pairs;
    pairs.add_material({"block", 500.0, ""});
    pairs.add_material({"floor", 500.0, ""});
    pairs.set_pair("block", "floor", {0.45, 0.35, 0.0, 0.0});
    pairs.set_pair("block", "block", {0.45, 0.35, 0.0, 0.0});
    Scene scene(std::move(pairs), at_240_hz);
    scene.add_box("floor", b2_staticBody, "floor", {0.0f, -0.5f}, 400.0f, 1.0f);
    const float half_width = 0.2f, half_height = 0.04f, foot = 0.02f;
    b2BodyDef definition;
    definition.type = b2_dynamicBody;
    definition.position = {0.0f, half_height + foot + resting_gap};
    b2Body* block = scene.add_body("block", definition);
    b2PolygonShape shape;
    shape.SetAsBox(half_width, half_height);
    scene.add_fixture(block, shape, "block");
    for (int i = 0; i < feet; ++i) {
      const float x = -half_width + 0.5f * foot + static_cast<float>(i) * (2.0f * half_width - foot) / static_cast<float>(feet - 1);
      shape.SetAsBox(0.5f * foot, 0.5f * foot, {x, -half_height - 0.5f * foot}, 0.0f);
      scene.add_fixture(block, shape, "block");
    }
    const float area = 4.0f * half_width * half_height + static_cast<float>(feet) * foot * foot;
    for (b2Fixture* part = block->GetFixtureList(); part != nullptr; part = part->GetNext()) part->SetDensity(1.0f / area);
    block->ResetMassData();
    const double rate = 2.0;
    // At the height of the contacts, so the pull cannot tip the block.
    scene.add_applied_force({"pull", block, {0.0f, -half_height - foot - 0.5f * resting_gap},
                             [rate](double t) { return b2Vec2{static_cast<float>(rate * t), 0.0f}; }});
    double breakaway = -1.0;
    while (breakaway < 0.0 && scene.time() < 4.0) {
      const double pull_before = rate * scene.time();
      scene.step();
      if (scene.slipping().back() != 0) breakaway = pull_before;
    }
    const double limit = 0.45 * 9.81;
    EXPECT_NEAR(breakaway, limit, 0.005 * limit + rate * scene.frame_step()) << feet << " feet";
  }
}

// A body standing on two steps at two heights: a slab on the high step and a leg down to the
// low one, one group of contacts whose tangents agree at two heights. Pulled sideways at its top
// with a growing pull r·t, away from the riser, it tips about the leg's outer foot as soon as
// the pull's moment there passes its weight's, F·y = m·g·(x_c − x_foot); friction
// (μs·m·g, far more) cannot stop that, for as the slab's load on the high step goes, Coulomb's
// law leaves it no friction either. Past the tipping pull the body turns about the foot with
// I_foot·θ'' = r·(t − t_tip)·y, so it has turned θ by the pull F_tip + r·(6·I_foot·θ/(r·y))^(1/3).
// Held up by friction the solver had left on the unloading high step, it stood unturned at
// 1.5 times the tipping pull.
namespace {

b2Fixture* add_true_box(Scene& scene, b2Body* body, float left, float right, float bottom, float top, const std::string& material) {
  b2PolygonShape shape;
  shape.SetAsBox(0.5f * (right - left), 0.5f * (top - bottom), {0.5f * (left + right), 0.5f * (bottom + top)}, 0.0f);
  shape.m_radius = true_skin;
  return scene.add_fixture(body, shape, material);
}

}  // namespace

TEST(BodyOnTwoSteps, TipsAboutItsLowFootWhenThePullsMomentPassesItsWeights) {
  for (const double mu_s : {0.5, 1.0}) {
    SCOPED_TRACE("mu_s = " + std::to_string(mu_s));
    PairTable pairs;
    pairs.add_material({"stairs", 600.0, ""});
    pairs.add_material({"body", 500.0, ""});
    pairs.set_pair("body", "stairs", {mu_s, 0.7 * mu_s, 0.0, 0.0});
    pairs.set_pair("body", "body", {mu_s, 0.7 * mu_s, 0.0, 0.0});
    Scene scene(std::move(pairs), at_240_hz);
    const float rise = 0.5f;  // the high step's top; the low step's is at 0
    b2BodyDef fixed;
    fixed.type = b2_staticBody;
    b2Body* stairs = scene.add_body("stairs", fixed);
    add_true_box(scene, stairs, -2.0f, 0.0f, -0.5f, 0.0f, "stairs");
    add_true_box(scene, stairs, 0.0f, 2.0f, -0.5f, rise, "stairs");
    b2BodyDef moving;
    moving.type = b2_dynamicBody;
    b2Body* body = scene.add_body("body", moving);
    add_true_box(scene, body, -0.3f, 0.3f, rise, rise + 0.1f, "body");  // the slab, on the high step
    add_true_box(scene, body, -0.3f, -0.1f, 0.0f, rise, "body");        // the leg, on the low step
    const double rate = 20.0;                                           // N/s
    const float pull_height = rise + 0.1f;                              // the slab's top
    scene.add_applied_force({"pull", body, body->GetLocalPoint({0.0f, pull_height}),
                             [rate](double t) { return b2Vec2{static_cast<float>(-rate * t), 0.0f}; }});

    const double m = body->GetMass();
    const b2Vec2 centre = body->GetWorldCenter();
    const b2Vec2 foot{-0.3f, 0.0f};  // the leg's outer corner, which it tips about
    const double tipping_pull = m * standard_gravity * (centre.x - foot.x) / pull_height;
    ASSERT_LT(tipping_pull, mu_s * m * standard_gravity) << "the scene must tip before it slides";
    const double inertia_at_foot = body->GetInertia() - m * b2Dot(body->GetLocalCenter(), body->GetLocalCenter()) +
                                   m * b2DistanceSquared(centre, foot);
    const double turned = 1e-3;  // rad
    const double turned_by = tipping_pull + rate * std::cbrt(6.0 * inertia_at_foot * turned / (rate * pull_height));

    double still_to = 0.0, turned_at = -1.0;  // the pulls: the last with the body unturned, and at `turned`
    while (turned_at < 0.0 && scene.time() < 1.5 * tipping_pull / rate) {
      const double pull = rate * scene.time();
      scene.step();
      if (std::abs(body->GetAngle()) < 1e-6f) still_to = pull;
      if (std::abs(body->GetAngle()) > turned) turned_at = pull;
      ASSERT_EQ(scene.slipping().back(), 0) << "slid at a pull of " << pull << " N, under mu_s·m·g";
    }
    // Held below the tipping pull: the pull is sampled at the step's start, so the last still
    // step's pull lies within one step's growth r·h below it.
    EXPECT_GE(still_to, tipping_pull - rate * scene.frame_step());
    // The turn's start lies within a step, and the velocity step puts the angle up to half a step
    // behind the exact θ(t): a step and a half's growth of the pull.
    EXPECT_NEAR(turned_at, turned_by, 1.5 * rate * scene.frame_step()) << "tipping pull " << tipping_pull << " N";
  }
}

// Friction treatment per pair: one world holds a stick-slip block beside a regularized one
// beside Box2D's own, each pair keeping its treatment whatever the run's is, and a pair with
// none following the run's. The slope is made by tilting gravity, so every block sees the same
// slope on one flat floor; tan(20°) = 0.364 lies between mu_k = 0.3 and mu_s = 0.6.
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double angle = 20.0 * pi / 180.0;
constexpr double g = 9.81;
constexpr double mu_s = 0.6, mu_k = 0.3, epsilon = 0.05;

struct Slope {
  std::unique_ptr<Scene> scene;
  b2Body* held = nullptr;     // its pair: stick-slip
  b2Body* creeps = nullptr;   // regularized, epsilon
  b2Body* slides = nullptr;   // box2d
  b2Body* follows = nullptr;  // no treatment of its own: the run's
};

Slope make_slope(FrictionTreatment run_treatment) {
  PairTable table;
  table.add_material({"floor", 1.0, ""});
  // A 0.4 × 0.2 m block of 1 kg.
  for (const char* name : {"held", "creeps", "slides", "follows"}) {
    table.add_material({name, 12.5, ""});
    table.set_pair(name, "floor", {mu_s, mu_k, 0.0, 0.0});
  }
  // They stand 10 m apart and never touch, but every pair that could must have values.
  const char* blocks[] = {"held", "creeps", "slides", "follows"};
  for (const char* a : blocks) {
    for (const char* b : blocks) table.set_pair(a, b, {mu_s, mu_k, 0.0, 0.0});
  }
  table.set_treatment("held", "floor", FrictionTreatment::stick_slip);
  table.set_treatment("creeps", "floor", FrictionTreatment::regularized, epsilon);
  table.set_treatment("slides", "floor", FrictionTreatment::box2d);
  StepSettings settings;
  settings.treatment = run_treatment;
  Slope slope;
  slope.scene = std::make_unique<Scene>(std::move(table), settings,
                                        b2Vec2{static_cast<float>(-g * std::sin(angle)), static_cast<float>(-g * std::cos(angle))});
  Scene& scene = *slope.scene;
  scene.add_box("floor", b2_staticBody, "floor", {0.0f, -0.5f}, 60.0f, 1.0f);
  float x = -20.0f;
  for (b2Body** body : {&slope.held, &slope.creeps, &slope.slides, &slope.follows}) {
    const char* name = body == &slope.held ? "held" : body == &slope.creeps ? "creeps" : body == &slope.slides ? "slides" : "follows";
    *body = scene.add_box(name, b2_dynamicBody, name, {x, 0.1f + resting_gap}, 0.4f, 0.2f);
    x += 10.0f;
  }
  return slope;
}

void run(Scene& scene, double seconds) {
  while (scene.time() < seconds - 1e-9) scene.step();
}

// Downhill is -x.
double downhill_speed(const b2Body* body) { return -body->GetLinearVelocity().x; }

// Runs the slope 2 s and checks the three pairs with treatments of their own, whatever the
// run's: returns the speed Box2D's single coefficient gives by then, g(sinθ − mu_k cosθ)·t.
double run_and_check_own_treatments(Slope& slope) {
  const float held_x = slope.held->GetPosition().x;
  run(*slope.scene, 2.0);
  // Stick-slip holds below atan(mu_s): not a micrometre in 2 s.
  EXPECT_LT(std::abs(slope.held->GetPosition().x - held_x), 1e-6f);
  // Regularized creeps at the speed where mu_s·N·v/eps balances the slope: eps·tanθ/mu_s.
  const double creep = epsilon * std::tan(angle) / mu_s;
  EXPECT_NEAR(downhill_speed(slope.creeps), creep, 0.01 * creep);
  // Box2D's single coefficient (mu_k) cannot hold it: it slides at g(sinθ - mu_k cosθ).
  const double sliding = g * (std::sin(angle) - mu_k * std::cos(angle)) * slope.scene->time();
  EXPECT_NEAR(downhill_speed(slope.slides), sliding, 0.01 * sliding);
  return sliding;
}

}  // namespace

TEST(PairTreatment, EachPairKeepsItsOwnBehaviourSideBySide) {
  Slope slope = make_slope(FrictionTreatment::stick_slip);
  run_and_check_own_treatments(slope);
  // The run's treatment (stick-slip) for the pair without its own.
  EXPECT_LT(std::abs(downhill_speed(slope.follows)), 1e-6);
  EXPECT_EQ(slope.scene->friction().treatment_of(slope.scene->pairs().material_id("follows"),
                                                 slope.scene->pairs().material_id("floor")),
            FrictionTreatment::stick_slip);
}

TEST(PairTreatment, TheLedgerClosesOnTheCreepingBlock) {
  // The regularized dry force is counted on the step's new velocity, as Box2D's semi-implicit
  // step moves the block: in a steady creep the slope's work and the friction's cancel.
  Slope slope = make_slope(FrictionTreatment::stick_slip);
  run(*slope.scene, 2.0);
  const EnergyLedger& ledger = slope.scene->ledger();
  EXPECT_LT(std::abs(ledger.residual()), 0.01 * ledger.dissipated()) << ledger.residual() << " J of " << ledger.dissipated();
}

TEST(PairTreatment, APairsTreatmentSurvivesTheRunsAndTheOthersFollowIt) {
  Slope slope = make_slope(FrictionTreatment::box2d);
  const double expected = run_and_check_own_treatments(slope);
  // Without a treatment of its own the pair now follows the run's box2d and slides too.
  EXPECT_NEAR(downhill_speed(slope.follows), expected, 0.01 * expected);
}

TEST(PairTreatment, ARegularizedPairWithoutEpsilonUsesTheRunsThresholdSpeed) {
  PairTable table;
  table.add_material({"a", 1.0, ""});
  table.add_material({"b", 1.0, ""});
  table.set_pair("a", "b", {mu_s, mu_k, 0.0, 0.0});
  table.set_treatment("a", "b", FrictionTreatment::regularized);
  StepSettings settings;
  settings.threshold_speed = 0.03;
  Scene scene(std::move(table), settings);
  EXPECT_EQ(scene.friction().epsilon_of(0, 1), 0.03);
}
