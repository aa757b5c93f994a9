#include <gtest/gtest.h>

#include <cmath>

#include "physics/scenarios.h"

using namespace frictionlab;

namespace {
std::string message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}
}  // namespace

TEST(StepSettings, RejectsOutOfRangeNamingTheSettingAndRange) {
  StepSettings bad;
  bad.hz = 0.0;
  std::string message = message_of([&] { validate(bad); });
  EXPECT_NE(message.find("hz"), std::string::npos) << message;
  EXPECT_NE(message.find("(0, 100000]"), std::string::npos) << message;
  bad = StepSettings{};
  bad.substeps = 0;
  EXPECT_NE(message_of([&] { validate(bad); }).find("substeps"), std::string::npos);
  bad = StepSettings{};
  bad.velocity_iterations = -3;
  EXPECT_NE(message_of([&] { validate(bad); }).find("velocity iterations"), std::string::npos);
  bad = StepSettings{};
  bad.threshold_speed = NAN;
  EXPECT_NE(message_of([&] { validate(bad); }).find("threshold speed"), std::string::npos);
  EXPECT_THROW(Scene(PairTable{}, bad), InvalidInput);
}

TEST(Scene, RejectsABodyWhoseMaterialHasNoPairWithTheOthers) {
  PairTable table;
  table.add_material({"wood", 600.0, ""});
  table.add_material({"ice", 900.0, ""});
  Scene scene(std::move(table));
  scene.add_box("floor", b2_staticBody, "ice", {0, -0.5f}, 10, 1);
  const std::string message =
      message_of([&] { scene.add_box("crate", b2_dynamicBody, "wood", {0, 0.5f}, 1, 1); });
  EXPECT_NE(message.find("wood–ice"), std::string::npos) << message;
  EXPECT_NE(message_of([&] { scene.add_box("crate", b2_dynamicBody, "steel", {0, 0.5f}, 1, 1); }).find("unknown material"),
            std::string::npos);
  EXPECT_NE(message_of([&] { scene.add_box("floor", b2_staticBody, "ice", {0, 5}, 1, 1); }).find("defined twice"),
            std::string::npos);
  EXPECT_NE(message_of([&] { scene.add_box("thin", b2_dynamicBody, "ice", {0, 5}, 0, 1); }).find("(0, 1000]"),
            std::string::npos);
}

TEST(Scene, RejectsBadSpringsForcesAndDrivers) {
  Scene scene(block_on_ground(Block{}));
  b2Body* block = scene.add_box("block", b2_dynamicBody, "block", {0, 1}, 0.4f, 0.2f);
  Spring spring{"s", block, {0, 0}, nullptr, {0, 0}, [](double) { return b2Vec2{1, 1}; }, -5.0, 0.5};
  EXPECT_NE(message_of([&] { scene.add_spring(spring); }).find("stiffness k"), std::string::npos);
  spring.stiffness = 5.0;
  spring.hand = nullptr;
  EXPECT_NE(message_of([&] { scene.add_spring(spring); }).find("far end"), std::string::npos);
  EXPECT_THROW(scene.add_applied_force({"push", block, {0, 0}, nullptr}), InvalidInput);
  EXPECT_THROW(scene.drive(block, [](double) { return b2Vec2{0, 0}; }, nullptr), InvalidInput);
  EXPECT_NE(message_of([&] { scene.body("nobody"); }).find("block"), std::string::npos);
  EXPECT_NE(message_of([&] { scene.probe("nothing"); }).find("unknown probe"), std::string::npos);
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
  scene.drive(plate, [speed](double t) { return b2Vec2{static_cast<float>(speed * t), -0.5f}; }, nullptr);
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

TEST(Treatments, NamesRoundTripAndUnknownNamesListTheAllowed) {
  for (FrictionTreatment t : {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                              FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    EXPECT_EQ(parse_treatment(treatment_name(t)), t);
  }
  EXPECT_NE(message_of([] { parse_treatment("sticky"); }).find("stick-slip, threshold, regularized, box2d"),
            std::string::npos);
}
