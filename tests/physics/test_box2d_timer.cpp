// Box2D's step timer as FrictionLab links it (physics/box2d_timer.cpp).
#include <gtest/gtest.h>

#include <algorithm>

#include <box2d/box2d.h>

// Box2D times every step for its profile with the system clock, 14 readings or more a step;
// FrictionLab never reads the profile, and its timer (physics/box2d_timer.cpp) reads no clock,
// in every program that links the physics library. Box2D's own, which counts microseconds, reads
// more than 0 ms for some of 200 steps that take a few microseconds each. (This test names no
// b2Timer itself, so it also checks that the library makes the program link the timer.)
TEST(Box2DTimer, ReadsNoClockWhileAWorldSteps) {
  b2World world({0.0f, -9.81f});
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  b2PolygonShape box;
  box.SetAsBox(0.1f, 0.1f);
  world.CreateBody(&definition)->CreateFixture(&box, 1.0f);
  float longest = 0.0f;
  for (int i = 0; i < 200; ++i) {
    world.Step(1.0f / 240.0f, 8, 3);
    longest = std::max(longest, world.GetProfile().step);
  }
  EXPECT_EQ(longest, 0.0f);
}
