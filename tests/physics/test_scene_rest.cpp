// The scene's rest: a block stuck by static friction with nothing but gravity on it is let
// sleep where it stopped, and woken when its friction changes; blocks held by a force or creeping
// under a regularized law stay awake (physics/scene_rest.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "physics/scenarios.h"

using namespace frictionlab;

// A block that has slid to rest on the ground, stuck by static friction with nothing but
// gravity on it, is let sleep: Box2D stops solving it, it stays exactly where it stopped, and
// its contact keeps reading the load it carries. (Without the scene's rest it stays awake.)
TEST(SceneRest, ABlockThatHasSlidToRestSleepsWhereItStopped) {
  Slide setup;  // 3 m/s, mu_k = 0.4: at rest after 0.76 s, 1.15 m on
  auto scene = make_slide(setup, StepSettings{});
  b2Body* block = scene->body("block");
  while (scene->time() < 1.0) scene->step();
  EXPECT_FALSE(block->IsAwake());
  const double stopped = scene->probe("distance").history.back();
  EXPECT_NEAR(stopped, 9.0 / (2.0 * 0.4 * standard_gravity), 0.01);
  while (scene->time() < 2.0) scene->step();
  EXPECT_EQ(scene->probe("distance").history.back(), stopped);
  const ContactRecord* touch = scene->friction().find(block, scene->body("ground"));
  ASSERT_NE(touch, nullptr);
  EXPECT_NEAR(touch->solver.normal_force, setup.block.mass * standard_gravity, 1e-3);
  EXPECT_EQ(touch->friction.state, ContactState::sticking);
}

// Friction values changed under a resting block (a teacher's slider): wake() lets it go, and
// it slides down the slope its new mu_s no longer holds it on.
TEST(SceneRest, ABlockRestingOnASlopeSlidesOnceWokenWithLowerFriction) {
  Incline setup;
  setup.angle = 0.3;  // below atan 0.6
  auto scene = make_incline(setup, StepSettings{});
  b2Body* block = scene->body("block");
  while (scene->time() < 0.5) scene->step();
  ASSERT_FALSE(block->IsAwake());
  const double held = scene->probe("distance").history.back();
  EXPECT_LT(std::abs(held), 1e-4);
  scene->pairs().set_pair("block", "ground", FrictionPair{0.1, 0.05, 0.0, 0.0});
  scene->wake();
  while (scene->time() < 1.0) scene->step();
  // Sliding from rest for 0.5 s at g·(sin θ − mu_k·cos θ): 0.30 m.
  const double a = standard_gravity * (std::sin(0.3) - 0.05 * std::cos(0.3));
  EXPECT_NEAR(scene->probe("distance").history.back() - held, 0.5 * a * 0.25, 0.01);
}

// Only a block stuck under the stick-slip law with nothing else on it rests: a regularized
// contact creeps (its friction is a force of the sliding speed, never a hold), and a pushed
// block is held by what pushes it, which may change at any time.
TEST(SceneRest, BlocksHeldByAForceOrCreepingUnderARegularizedLawStayAwake) {
  StepSettings regularized;
  regularized.treatment = FrictionTreatment::regularized;
  Incline setup;
  setup.angle = 0.3;
  auto creeping = make_incline(setup, regularized);
  auto pushed = make_slide(Slide{Block{}, 0.0}, StepSettings{});
  b2Body* block = pushed->body("block");
  pushed->add_applied_force({"push", block, {0, 0}, [](double) { return b2Vec2{1.0f, 0.0f}; }});  // below mu_s·N
  for (int i = 0; i < 240; ++i) {
    creeping->step();
    pushed->step();
  }
  EXPECT_TRUE(creeping->body("block")->IsAwake());
  EXPECT_GT(creeping->probe("distance").history.back(), 0.0);
  EXPECT_TRUE(block->IsAwake());
}

// On a frictionless floor the listener may call a touch slipping however slowly the block goes;
// still, a block at rest there is on level ground and stays: it rests too. On a frictionless
// slope it never comes to rest.
TEST(SceneRest, ABlockAtRestOnAFrictionlessFloorRestsButOneOnAFrictionlessSlopeSlides) {
  Block frictionless;
  frictionless.pair = FrictionPair{0.0, 0.0, 0.0, 0.0};
  auto flat = make_slide(Slide{frictionless, 0.0}, StepSettings{});
  Incline setup{frictionless, 0.3};
  auto slope = make_incline(setup, StepSettings{});
  for (int i = 0; i < 120; ++i) {
    flat->step();
    slope->step();
  }
  EXPECT_FALSE(flat->body("block")->IsAwake());
  EXPECT_EQ(flat->probe("distance").history.back(), 0.0);
  EXPECT_TRUE(slope->body("block")->IsAwake());
  EXPECT_NEAR(slope->probe("distance").history.back(), 0.5 * standard_gravity * std::sin(0.3) * 0.25, 0.01);
}

// A block whose speed a script takes away a little each step (terrain's velocity hack) on a
// frictionless floor is put to rest while it still crept at a micrometre a second: where it is,
// a float's spacing rounds that creep to no move at all. Box2D no longer solves a sleeping
// body's contact, so the touch's last reading (sliding at that creep) would stand for the rest of
// the run, and the plots shaded the whole run "slipping" (terrain, at the run's end). At rest,
// the touch slides no more.
TEST(SceneRest, AFrictionlessTouchOfABlockPutToRestNoLongerSlips) {
  Block frictionless;
  frictionless.pair = FrictionPair{0.0, 0.0, 0.0, 0.0};
  auto scene = make_slide(Slide{frictionless, 1e-3}, StepSettings{});
  b2Body* block = scene->body("block");
  block->SetTransform(b2Vec2(40.0f, block->GetPosition().y), 0.0f);  // far enough out for float rounding to matter
  // The hack's keep per step: the speed falls from 1 mm/s to under a micrometre a second in 2.9 s.
  for (int i = 0; i < 240 * 4 && block->IsAwake(); ++i) {
    block->SetLinearVelocity(0.99f * block->GetLinearVelocity());
    scene->step();
  }
  ASSERT_FALSE(block->IsAwake()) << "the block never came to rest";
  for (int i = 0; i < 24; ++i) scene->step();
  const ContactRecord* touch = scene->friction().find(block, scene->body("ground"));
  ASSERT_NE(touch, nullptr);
  EXPECT_FALSE(touch->seen_slipping()) << "sliding at " << touch->solver.sliding_velocity << " m/s while asleep";
  EXPECT_EQ(scene->slipping().back(), 0);
}
