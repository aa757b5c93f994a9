// The scene: the step settings and the bodies, springs, forces and drivers it refuses, runs that
// repeat bit for bit, and the energy ledger it keeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "physics/closed_forms.h"
#include "physics/scenarios.h"
#include "tests/assertions.h"

using namespace frictionlab;

TEST(StepSettings, RejectsOutOfRangeNamingTheSettingAndRange) {
  auto with = [](auto change) {
    StepSettings settings;
    change(settings);
    return [settings] { validate(settings); };
  };
  expect_invalid(with([](StepSettings& s) { s.hz = 0.0; }), "hz", "[1, 100000]");
  expect_invalid(with([](StepSettings& s) { s.hz = 1e-300; }), "hz", "[1, 100000]");
  expect_invalid(with([](StepSettings& s) { s.substeps = 0; }), "substeps", "[1, 1000]");
  expect_invalid(with([](StepSettings& s) { s.velocity_iterations = -3; }), "velocity iterations", "[1, 1000]");
  expect_invalid(with([](StepSettings& s) { s.threshold_speed = NAN; }), "threshold speed", "(0, 100]");
  StepSettings bad;
  bad.hz = -1.0;
  EXPECT_THROW(Scene(PairTable{}, bad), InvalidInput);
  expect_invalid([] { Scene(PairTable{}, StepSettings{}, b2Vec2{0.0f, NAN}); }, "gravity y", "[-1000, 1000]");
}

TEST(Scene, RejectsABodyWhoseMaterialHasNoPairWithTheOthers) {
  PairTable table;
  table.add_material({"wood", 600.0, ""});
  table.add_material({"ice", 900.0, ""});
  Scene scene(std::move(table));
  scene.add_box("floor", b2_staticBody, "ice", {0, -0.5f}, 10, 1);
  expect_invalid([&] { scene.add_box("crate", b2_dynamicBody, "wood", {0, 0.5f}, 1, 1); }, "wood–ice", "set them");
  expect_invalid([&] { scene.add_box("crate", b2_dynamicBody, "steel", {0, 0.5f}, 1, 1); }, "unknown material", "ice");
  expect_invalid([&] { scene.add_box("floor", b2_staticBody, "ice", {0, 5}, 1, 1); }, "floor", "there is already a body of that name");
  EXPECT_EQ(scene.bodies().size(), 1u) << "refused boxes leave nothing behind";
}

TEST(Scene, RejectsPlacementsAndSizesBox2DWouldAbortOn) {
  Scene scene(block_on_ground(Block{}));
  expect_invalid([&] { scene.add_box("thin", b2_dynamicBody, "block", {0, 5}, 0, 1); }, "width", "[0.02, 1000]");
  expect_invalid([&] { scene.add_box("speck", b2_dynamicBody, "block", {0, 5}, 1e-6f, 1e-6f); }, "width", "[0.02, 1000]");
  expect_invalid([&] { scene.add_box("lost", b2_dynamicBody, "block", {NAN, 5}, 1, 1); }, "'lost': x", "[-100000, 100000]");
  expect_invalid([&] { scene.add_box("spun", b2_dynamicBody, "block", {0, 5}, 1, 1, INFINITY); }, "angle", "[-10000, 10000]");
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  definition.linearDamping = -1.0f;
  expect_invalid([&] { scene.add_body("sticky", definition); }, "linear damping", "[0, 10000]");
  expect_invalid([] { PairTable t; t.add_material({"dust", 1e-300, ""}); }, "density", "[0.001, 1e6]");
  EXPECT_TRUE(scene.bodies().empty());
}

TEST(Scene, AFixtureWithoutPairValuesFailsTheStepWithoutBreakingTheWorld) {
  // A fixture made behind the scene's back has no material: the contact is switched off,
  // the step reports it, and the world is left usable (Box2D would abort if an exception
  // had unwound through its step).
  Scene scene(block_on_ground(Block{}));
  scene.add_box("ground", b2_staticBody, "ground", {0, -0.5f}, 10, 1);
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  definition.position = {0.0f, 0.1f + resting_gap};
  b2Body* stray = scene.add_body("stray", definition);
  b2PolygonShape shape;
  shape.SetAsBox(0.2f, 0.1f);
  stray->CreateFixture(&shape, 1.0f);
  expect_invalid([&] { for (int i = 0; i < 3; ++i) scene.step(); }, "no friction values for the pair ground–(no material)", "give every fixture");
  EXPECT_NO_THROW(scene.add_box("another", b2_dynamicBody, "block", {3, 1}, 0.4f, 0.2f));
}

TEST(Scene, FunctionsOfTimeThatReturnNaNAreRefusedAtTheirTime) {
  Scene scene(block_on_ground(Block{}));
  scene.add_box("ground", b2_staticBody, "ground", {0, -0.5f}, 10, 1);
  b2Body* block = scene.add_box("block", b2_dynamicBody, "block", {0, 0.1f + resting_gap}, 0.4f, 0.2f);
  scene.add_applied_force({"push", block, {0, 0}, [](double t) {
                             return b2Vec2{t > 0.1 ? NAN : 1.0f, 0.0f};
                           }});
  expect_invalid([&] { for (int i = 0; i < 100; ++i) scene.step(); }, "applied force 'push' at t = 0.1", "finite");
  EXPECT_TRUE(std::isfinite(block->GetPosition().x));
}

TEST(Scene, RefusesASpringTooStiffForTheStep) {
  Scene scene(block_on_ground(Block{}));  // 1 kg block, 240 Hz: explicit springs need k < 4·m·240² N/m
  b2Body* block = scene.add_box("block", b2_dynamicBody, "block", {0, 1}, 0.4f, 0.2f);
  Spring spring{"stiff", block, {0, 0}, nullptr, {0, 0}, [](double) { return b2Vec2{1, 1}; }, 1e6, 0.5};
  expect_invalid([&] { scene.add_spring(spring); }, "stiffness k = 1e+06", "k < 4·m/h² = 230400");
  spring.stiffness = 2e5;
  EXPECT_NO_THROW(scene.add_spring(spring));
}

TEST(Scene, RejectsBadSpringsForcesAndDrivers) {
  Scene scene(block_on_ground(Block{}));
  b2Body* block = scene.add_box("block", b2_dynamicBody, "block", {0, 1}, 0.4f, 0.2f);
  Spring spring{"s", block, {0, 0}, nullptr, {0, 0}, [](double) { return b2Vec2{1, 1}; }, -5.0, 0.5};
  expect_invalid([&] { scene.add_spring(spring); }, "stiffness k", "(0, 1e+09]");
  spring.stiffness = 5.0;
  spring.hand = nullptr;
  expect_invalid([&] { scene.add_spring(spring); }, "spring 's'", "far end");
  EXPECT_THROW(scene.add_applied_force({"push", block, {0, 0}, nullptr}), InvalidInput);
  EXPECT_THROW(scene.drive(block, [](double) { return std::array<double, 2>{0, 0}; }, nullptr), InvalidInput);
  expect_invalid([&] { scene.body("nobody"); }, "unknown body 'nobody'", "block");
  expect_invalid([&] { scene.probe("nothing"); }, "unknown probe", "nothing");
}

TEST(Scene, FramesAdvanceByOneOverHzWhateverTheSubsteps) {
  StepSettings settings;
  settings.hz = 60.0;
  settings.substeps = 4;
  auto scene = make_slide(Slide{}, settings);
  for (int i = 0; i < 30; ++i) scene->step();
  EXPECT_DOUBLE_EQ(scene->time(), 0.5);
  EXPECT_EQ(scene->times().size(), 30u);
  EXPECT_EQ(scene->probe("distance").history.size(), 30u);
  EXPECT_GT(scene->probe("distance").history.back(), 0.5) << "the launched block moved";
}

TEST(Scene, SubstepsApproachTheSameAnswerAsAHigherRate) {
  // Four sub-steps at 60 Hz take the same world steps as 240 Hz: the same numbers.
  StepSettings sub;
  sub.hz = 60.0;
  sub.substeps = 4;
  StepSettings fine;
  fine.hz = 240.0;
  auto a = make_spring_pull(SpringPull{}, sub);
  auto b = make_spring_pull(SpringPull{}, fine);
  for (int i = 0; i < 300; ++i) {
    a->step();
    for (int j = 0; j < 4; ++j) b->step();
  }
  EXPECT_NEAR(a->body("block")->GetPosition().x, b->body("block")->GetPosition().x, 1e-6);
}

TEST(Scene, KinematicPlateDragsABlockUpToItsSpeed) {
  // A plate that starts moving at 0.5 m/s under a resting block: kinetic friction drags the
  // block up to the plate's speed, falling behind by v²/(2·mu_k·g), and dissipates exactly the
  // kinetic energy it gives (the plate's work is twice the block's final kinetic energy).
  const Block block;
  Scene scene(block_on_ground(block));
  const double speed = 0.5;
  b2Body* plate = scene.add_box("plate", b2_kinematicBody, "ground", {0, -0.5f}, 20, 1);
  scene.drive(plate, [speed](double t) { return std::array<double, 2>{speed * t, -0.5}; }, nullptr);
  b2Body* body = scene.add_box("block", b2_dynamicBody, "block", {0, 0.1f + resting_gap}, 0.4f, 0.2f);
  for (int i = 0; i < 480; ++i) scene.step();
  EXPECT_NEAR(plate->GetPosition().x, 2.0 * speed, 1e-5);
  const double lag = speed * speed / (2.0 * block.pair.mu_k * standard_gravity);
  // The plate's jump in speed lands on a step boundary: a first-order error of about v·h/2.
  EXPECT_NEAR(plate->GetPosition().x - body->GetPosition().x, lag, speed * scene.frame_step());
  EXPECT_NEAR(body->GetLinearVelocity().x, speed, 1e-4) << "stuck to the plate again";
  const EnergyLedger& e = scene.ledger();
  EXPECT_NEAR(e.kinetic, 0.5 * block.mass * speed * speed, 1e-4);
  EXPECT_NEAR(e.work_drivers, 2.0 * e.kinetic, 0.01 * e.kinetic);
  EXPECT_NEAR(-e.work_friction, e.kinetic, 0.01 * e.kinetic);
}

TEST(Scene, RunsAreBitForBitRepeatable) {
  auto run = [] {
    StepSettings settings;
    settings.treatment = FrictionTreatment::regularized;
    Slide slide;
    slide.block.pair.c = 1.0;
    auto scene = make_slide(slide, settings);
    for (int i = 0; i < 600; ++i) scene->step();
    return scene->body("block")->GetPosition();
  };
  const b2Vec2 first = run();
  const b2Vec2 second = run();
  EXPECT_EQ(first.x, second.x);
  EXPECT_EQ(first.y, second.y);
}

TEST(Scene, APileIsRepeatableWhereverTheHeapPutsItsContacts) {
  // Contacts are keyed by address in the listener; nothing that changes a number may depend on
  // that. The second run starts with the heap shuffled by other allocations.
  auto run = [] {
    StepSettings settings;
    settings.treatment = FrictionTreatment::regularized;  // explicit impulses from the listener
    Pyramid pile = make_pyramid(8, true, settings);
    for (int i = 0; i < 240; ++i) pile.scene->step();
    std::vector<float> state;
    for (const auto& [name, body] : pile.scene->bodies()) {
      state.push_back(body->GetPosition().x);
      state.push_back(body->GetPosition().y);
      state.push_back(body->GetAngle());
    }
    return state;
  };
  const std::vector<float> first = run();
  std::vector<std::unique_ptr<char[]>> clutter;
  for (int i = 0; i < 5000; ++i) clutter.emplace_back(new char[static_cast<size_t>(16 + (i * 37) % 300)]);
  const std::vector<float> second = run();
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) ASSERT_EQ(first[i], second[i]) << "value " << i;
}

// The energy ledger: what went in (applied work), where it went (kinetic, potential,
// spring) and what friction took, closing to within 1 % of the energy dissipated.
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
