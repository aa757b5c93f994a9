// What a script reads from the handles it holds (lessons/runtime/handles.cpp): a contact's
// state, forces and loads, a body's position, speed and acceleration at a point and along a
// direction, read by the runtime (probe{ read = ... }) or by the script's own function, and the
// instant of the step each belongs to; each against a closed form or the body's own state.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/scenarios.h"
#include "tests/assertions.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

constexpr double g = standard_gravity;

double probe_now(const Lesson& lesson, const std::string& name) { return lesson.scene().probe(name).history.back(); }

TEST(Readings, ContactReportsTheListenersStateAndForces) {
  // A 2 kg block: N = m g. Pulled at 80 % of mu_s·N it sticks and friction balances the
  // pull; at 120 % it slips and friction is mu_k·N.
  for (const double share : {0.8, 1.2}) {
    ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, mass = 2 }
force { "pull", on = block, force = { )" + std::to_string(share * 0.5 * 2 * g) + R"(, 0 } }
probe { "friction", unit = "N", function() return contact(block, floor).fx end }
probe { "normal", unit = "N", function() return contact(block, floor).normal end }
probe { "loads", unit = "N", function() local c = contact(block, floor) return c.load1 + c.load2 end }
probe { "slipping", function() return contact(block, floor).state == "slipping" and 1 or 0 end }
)"));
    Lesson lesson(script.path());
    run_for(lesson, 0.5);
    EXPECT_RELATIVE(probe_now(lesson, "normal"), 2 * g, 1e-3);
    EXPECT_RELATIVE(probe_now(lesson, "loads"), 2 * g, 1e-3);
    if (share < 1.0) {
      EXPECT_EQ(probe_now(lesson, "slipping"), 0.0);
      EXPECT_RELATIVE(probe_now(lesson, "friction"), -share * 0.5 * 2 * g, 1e-3);
    } else {
      EXPECT_EQ(probe_now(lesson, "slipping"), 1.0);
      EXPECT_RELATIVE(probe_now(lesson, "friction"), -0.4 * 2 * g, 1e-3);
    }
  }
}

TEST(Readings, ProbesReadByTheRuntimeMatchTheScriptsOwnReading) {
  // A 1 kg block sliding with mu_k = 0.4 and c = 2 N·s/m: the contact's friction on it is all
  // the surface does along itself, −(mu_k·m·g + c·v), and its drag part is −c·v.
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4, c = 2 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, mass = 1, velocity = { 3, 0 } }
local touch = contact(block, floor)
probe { "fx_read", unit = "N", read = { touch, "fx" } }
probe { "fx_lua", unit = "N", function() return touch.fx end }
probe { "drag_read", unit = "N", read = { touch, "drag_x" } }
probe { "vx_read", unit = "m/s", read = { block, "vx" } }
probe { "vx_lua", unit = "m/s", function() return block.vx end }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 0.25);
  EXPECT_EQ(probe_now(lesson, "fx_read"), probe_now(lesson, "fx_lua"));
  EXPECT_EQ(probe_now(lesson, "vx_read"), probe_now(lesson, "vx_lua"));
  const double v = probe_now(lesson, "vx_read");
  ASSERT_GT(v, 1.0);
  // The drag acted over the step just taken: c times a speed between the step's end speed v
  // and its start speed v + h·a.
  const double h = 1.0 / 240.0, a = 0.4 * g + 2.0 * v;
  const double drag = -probe_now(lesson, "drag_read");
  EXPECT_GE(drag, 2.0 * v);
  EXPECT_LE(drag, 2.0 * (v + h * a));
  EXPECT_RELATIVE(-probe_now(lesson, "fx_read"), 0.4 * g + drag, 1e-4);
}

TEST(Readings, ReadingsAtAPointAlongADirectionAndScaled) {
  // A frictionless 1 kg puck pushed along x by 2 N: each reading is checked against the body's
  // own position and velocity, read along x (a direction not of unit length), along the
  // diagonal, at a corner, and turned round.
  ScriptFile script(with_heading(R"(
material { "puck", density = 100 }
pair { "puck", "ice", mu_s = 0, mu_k = 0 }
local floor = ground { material = "ice" }
local puck = box { "puck", material = "puck", width = 0.2, height = 0.1, on = floor, at = 1, mass = 1, spin = 0 }
force { "push", on = puck, force = { 2, 0 } }
probe { "along_x", unit = "m", read = { puck, "distance", along = { 3, 0 } } }
probe { "along_diagonal", unit = "m", read = { puck, "distance", along = { 1, 1 } } }
probe { "speed_x", unit = "m/s", read = { puck, "speed", along = { 1, 0 } } }
probe { "corner_x", unit = "m", read = { puck, "x", at = { 0.1, -0.05 } } }
probe { "minus_x", unit = "m", read = { puck, "x", scale = -1 } }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 1.0);
  const double x = lesson.scene().body("puck")->GetPosition().x;
  EXPECT_NEAR(probe_now(lesson, "along_x"), x - 1.0, 1e-6);
  EXPECT_NEAR(probe_now(lesson, "along_diagonal"), (x - 1.0) / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(probe_now(lesson, "speed_x"), 2.0, 1e-4);  // v = F t / m
  EXPECT_NEAR(probe_now(lesson, "corner_x"), x + 0.1, 1e-6);
  EXPECT_NEAR(probe_now(lesson, "minus_x"), -x, 1e-6);
}

TEST(Readings, AnAccelerationReadingIsTheChangeOfSpeedAlongADirection) {
  // A frictionless 1 kg puck launched at 1 m/s and pushed along x by 2 N, and a ball falling
  // freely: every sample, the first included, reads the constant acceleration (2 m/s² along x,
  // g along −y and 0 across it), and a spring's block reads −(k/m)·x at the sample before, to
  // O(h²). In Lua the field needs a probe's direction, as distance and speed do.
  ScriptFile script(on_frictionless_ice(R"(local puck = box { "puck", material = "puck", width = 0.2, height = 0.1, on = floor, at = 1, mass = 1, velocity = { 1, 0 } }
force { "push", on = puck, force = { 2, 0 } }
local ball = circle { "ball", material = "puck", radius = 0.1, x = -3, y = 50 }
local bob = box { "bob", material = "puck", width = 0.2, height = 0.1, on = floor, at = -10, mass = 2 }
spring { "spring", from = bob, to = function(t) return -10.5, bob.y end, k = 8, rest_length = 0 }
probe { "push_acceleration", unit = "m/s²", read = { puck, "acceleration", along = { 4, 0 } } }
probe { "fall", unit = "m/s²", read = { ball, "acceleration", along = { 0, -1 } } }
probe { "across_fall", unit = "m/s²", read = { ball, "acceleration", along = { 1, 0 } } }
probe { "bob_acceleration", unit = "m/s²", read = { bob, "acceleration", along = { 1, 0 } } }
probe { "bob_x", unit = "m", read = { bob, "x" } }
)"));
  Lesson lesson(script.path());
  const double h = lesson.scene().frame_step();
  run_for(lesson, 1.0);
  const auto& push = lesson.scene().probe("push_acceleration").history;
  const auto& fall = lesson.scene().probe("fall").history;
  const auto& across = lesson.scene().probe("across_fall").history;
  const auto& bob = lesson.scene().probe("bob_acceleration").history;
  const auto& bob_x = lesson.scene().probe("bob_x").history;
  ASSERT_GT(push.size(), 200u);
  for (std::size_t i = 0; i < push.size(); ++i) {
    EXPECT_NEAR(push[i], 2.0, 2e-3) << "sample " << i;
    EXPECT_NEAR(fall[i], g, 2e-2) << "sample " << i;  // float velocities of up to 10 m/s
    EXPECT_NEAR(across[i], 0.0, 1e-9) << "sample " << i;
  }
  // The spring pulls the bob towards x = -10.5 with −(k/m)·(x + 10.5); sample i reads the
  // acceleration at the instant of sample i − 1, whose position bob_x[i − 1] gives.
  const double omega_squared = 8.0 / 2.0;
  for (std::size_t i = 2; i < bob.size(); ++i) {
    const double expected = -omega_squared * (bob_x[i - 1] + 10.5);
    EXPECT_NEAR(bob[i], expected, omega_squared * 0.5 * omega_squared * h * h + 1e-4) << "sample " << i;
  }
  ScriptFile in_lua(with_heading(R"(
pair { "wood", "wood", mu_s = 0.4, mu_k = 0.3 }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0 }
probe { "a", unit = "m/s²", function() return block.acceleration end }
)"));
  const std::string message = error_of([&] {
    Lesson broken(in_lua.path());
    run_for(broken, 0.1);
  });
  EXPECT_NE(message.find(":6: a body's acceleration needs a direction: read it in a probe"), std::string::npos) << message;
}

TEST(Readings, AReadWithoutAPointIsWhatTheCsvShows) {
  // A spinning triangle whose origin is a corner: x and y are that origin, vx and vy the
  // velocity of its centre of mass, as in the CSV; with at = {0, 0} they are the corner's.
  ScriptFile script(with_heading(R"(
material { "puck", density = 100 }
local corner = polygon { "corner", material = "puck", points = { { 0, 0 }, { 1, 0 }, { 0, 1 } }, x = 0, y = 5,
                         spin = 2 }
probe { "vx", unit = "m/s", read = { corner, "vx" } }
probe { "corner_vx", unit = "m/s", read = { corner, "vx", at = { 0, 0 } } }
)"));
  Lesson lesson(script.path(), {}, StepSettings{240.0});
  lesson.step();
  const b2Body* body = lesson.scene().body("corner");
  EXPECT_EQ(probe_now(lesson, "vx"), body->GetLinearVelocity().x);
  EXPECT_EQ(probe_now(lesson, "corner_vx"), body->GetLinearVelocityFromLocalPoint({0.0f, 0.0f}).x);
  EXPECT_GT(std::abs(probe_now(lesson, "corner_vx") - probe_now(lesson, "vx")), 0.1);
}

TEST(Readings, ContactTellsWhichEdgeCarriesTheLoadAndWhetherItSlips) {
  // A 10 kg box 0.5 m wide pushed at its left side, low and gently: it neither slides nor tips,
  // but the push's moment shifts the load forward, to the right edge. Moments about the front
  // (right) edge: back load = (W·d/2 − P·h) / d with the push P at height h above the contact plane.
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local crate = box { "crate", material = "wood", width = 0.5, height = 1, on = floor, mass = 10 }
force { "push", on = crate, at = { -0.25, 0.3 - 0.5 - resting_gap / 2 }, force = { 20, 0 } }
local touch = contact(crate, floor)
probe { "back", unit = "N", read = { touch, "load_left" } }
probe { "front", unit = "N", read = { touch, "load_right" } }
probe { "slipping", read = { touch, "slipping" } }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 0.5);
  const double weight = 10 * g;
  EXPECT_NEAR(probe_now(lesson, "back") + probe_now(lesson, "front"), weight, 0.01 * weight);
  EXPECT_NEAR(probe_now(lesson, "back"), (weight * 0.25 - 20 * 0.3) / 0.5, 0.01 * weight);
  EXPECT_EQ(probe_now(lesson, "slipping"), 0.0);
}

// The guide's table of instants (lessons/reference/reading.md, section 8), as a lesson's tolerance must allow
// for them: a body falling from rest is ½·g·t·(t + h) below its start, half a step ahead of
// ½·g·t²; the step in which a stuck contact breaks away reads μs·N and already slipping, the
// next μk·N.
TEST(Readings, ReadingsBelongToTheInstantsTheGuideGives) {
  ScriptFile falling(with_heading(R"(
local stone = box { "stone", material = "wood", width = 0.1, height = 0.1, x = 0, y = 10 }
probe { "height", unit = "m", read = { stone, "y" } }
)"));
  Lesson fall(falling.path());
  const double h = fall.scene().frame_step();
  run_for(fall, 1.0);
  const double t = fall.scene().time(), gravity = -fall.scene().world().GetGravity().y;
  const double dropped = 10.0 - probe_now(fall, "height");
  // Float positions and velocities, each step rounding each by at most half an ulp (ulp 9.5e-7
  // for numbers below 16): n·ulp/2 on the height, and h·n²/2·ulp/2 from the velocity's.
  const double n = t / h, rounding = n * 4.8e-7 + h * n * n / 2.0 * 4.8e-7;
  EXPECT_NEAR(dropped, 0.5 * gravity * t * (t + h), rounding);
  EXPECT_GT(dropped - 0.5 * gravity * t * t, 0.5 * gravity * h * t - rounding);  // 2 cm at 240 Hz

  ScriptFile pushed(with_heading(R"(
pair { "wood", "wood", mu_s = 0.4, mu_k = 0.3 }
local table_top = ground { "table", material = "wood" }
local block = box { "block", material = "wood", width = 0.3, height = 0.1, on = table_top, at = 0, mass = 1 }
force { "push", on = block, grows = { 2, 0 } }
local touch = contact(block, table_top)
probe { "friction", unit = "N", read = { touch, "friction" } }
probe { "normal", unit = "N", read = { touch, "normal" } }
probe { "slipping", read = { touch, "slipping" } }
)"));
  Lesson push(pushed.path());
  const auto& slipping = push.scene().probe("slipping").history;
  // The push reaches μs·N = 3.92 N at 1.96 s: 3 s is ample.
  while ((slipping.empty() || slipping.back() == 0.0) && push.scene().time() < 3.0) push.step();
  ASSERT_EQ(slipping.back(), 1.0) << "the block never broke away";
  const double breakaway_friction = probe_now(push, "friction"), normal = probe_now(push, "normal");
  push.step();
  const double next_friction = probe_now(push, "friction");
  // Float sums of a few impulses: a few float ulps of the 4 N they come to.
  EXPECT_NEAR(breakaway_friction, 0.4 * normal, 4e-6);
  EXPECT_NEAR(next_friction, 0.3 * normal, 4e-6);
}

}  // namespace
}  // namespace frictionlab::lessons
