// Functions that read the world, velocities a script sets, and the readings that say which
// instant of a step they belong to: each against a closed form or an exact reduced model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "physics/scenarios.h"
#include "tests/assertions.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

constexpr double g = standard_gravity;

double probe_now(const Lesson& lesson, const std::string& name) { return lesson.scene().probe(name).history.back(); }

StepSettings at_rate(double hz) {
  StepSettings settings;
  settings.hz = hz;
  return settings;
}

// A block of 2 kg on a frictionless floor, pulled back to x = 0 by a force −k·x that its
// function reads from block.x: simple harmonic motion, x0·cos(ωt) with ω = √(k/m). Returns the
// largest error over two periods and checks that the ledger closes.
double harmonic_error(double hz) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0.3, mass = 2 }
force { "restoring", on = block, force = function(t) return -50 * block.x, 0 end }
probe { "x", unit = "m", read = { block, "x" } }
)"));
  Lesson lesson(script.path(), {}, at_rate(hz));
  const double omega = std::sqrt(50.0 / 2.0);
  double worst = 0.0, largest_kinetic = 0.0;
  while (lesson.scene().time() < 4.0 * std::numbers::pi / omega) {
    lesson.step();
    worst = std::max(worst, std::abs(probe_now(lesson, "x") - 0.3 * std::cos(omega * lesson.scene().time())));
    largest_kinetic = std::max(largest_kinetic, lesson.scene().ledger().kinetic);
  }
  // The force is booked as applied work, F·h·(v_start + v_end)/2: exactly the kinetic energy
  // it gives, so nothing is left unexplained but float round-off.
  EXPECT_LT(std::abs(lesson.scene().ledger().residual()), 1e-5 * largest_kinetic) << "at " << hz << " Hz";
  EXPECT_NEAR(largest_kinetic, 0.5 * 50.0 * 0.3 * 0.3, 0.02 * 0.5 * 50.0 * 0.3 * 0.3);
  return worst;
}

TEST(WorldFunctions, AForceReadingThePositionGivesSimpleHarmonicMotion) {
  // The force sees x at the start of its step; the error comes from the block starting at rest
  // (held until t = 0, so Box2D's half-step velocity is not set ahead): O(h), measured 3.2 mm
  // at 240 Hz and 0.78 mm at 960 Hz on a 0.3 m swing.
  const double coarse = harmonic_error(240.0), fine = harmonic_error(960.0);
  EXPECT_LT(coarse, 0.5 * 5.0 * 0.3 / 240.0 * 1.5);  // (h/2)·ω·x0, with half again to spare
  EXPECT_LT(fine, coarse / 3.0);                     // shrinks with the step
}

// A block launched at 2 m/s on a frictionless floor under a drag −c·vx read from block.vx:
// v0·exp(−c·t/m). Returns the error at t = 1 s.
double drag_error(double hz) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, mass = 2,
                    velocity = { 2, 0 } }
local drag = force { "drag", on = block, force = function(t) return -3 * block.vx, 0 end }
probe { "vx", unit = "m/s", read = { block, "vx" } }
probe { "drag", unit = "N", read = { drag, "fx" } }
)"));
  Lesson lesson(script.path(), {}, at_rate(hz));
  for (int frame = 0; lesson.scene().time() < 1.0 - 0.5 / hz; ++frame) {
    const double before = lesson.scene().body("block")->GetLinearVelocity().x;
    lesson.step();
    // The step applied the force for the velocity at its start, and the reading after the
    // frame is the force for the velocity now: what the next step will apply.
    EXPECT_EQ(lesson.scene().forces_applied()[0].x, static_cast<float>(-3.0 * before)) << "frame " << frame;
    EXPECT_EQ(probe_now(lesson, "drag"), static_cast<float>(-3.0 * probe_now(lesson, "vx")));
  }
  EXPECT_LT(std::abs(lesson.scene().ledger().residual()), 1e-5 * 0.5 * 2.0 * 4.0);
  return std::abs(probe_now(lesson, "vx") - 2.0 * std::exp(-3.0 * lesson.scene().time() / 2.0));
}

TEST(WorldFunctions, AForceReadingTheVelocityIsAViscousDrag) {
  const double coarse = drag_error(240.0), fine = drag_error(960.0);
  // An explicit step of v' = −γ·v (γ = c/m = 1.5 /s) errs by at most γ²·h·t/2 of v (2.1 mm/s at
  // 240 Hz after 1 s); measured 0.70 mm/s, and 0.17 mm/s at 960 Hz.
  EXPECT_LT(coarse, (1.5 * 1.5 / 240.0 * 1.0 / 2.0) * 2.0 * std::exp(-1.5));
  EXPECT_LT(fine, coarse / 3.0);
}

TEST(WorldFunctions, AHandReadingTheWorldIsPlannedOneStepAhead) {
  // A hand held 0.3 m ahead of a 2 kg block on a frictionless floor (spring k = 50 N/m, rest
  // length 0.2 m). The hand's place at the end of a step is asked before the step, from where
  // the block is at its start: the stretch the next step feels is 0.1 m − h·v, so
  // m·v' = k·(0.1 − h·v) and v = (0.1/h)·(1 − exp(−k·h·t/m)). Were the hand to see the end of the
  // step, the stretch would stay 0.1 m and v = 2.5·t: 10 % more at t = 1 s.
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, mass = 2 }
spring { "lead", from = block, to = function(t) return block.x + 0.3, block.y end, k = 50, rest_length = 0.2 }
probe { "vx", unit = "m/s", read = { block, "vx" } }
)"));
  const double h = 1.0 / 240.0;
  Lesson lesson(script.path(), {}, at_rate(240.0));
  run_for(lesson, 1.0);
  const double t = lesson.scene().time();
  EXPECT_RELATIVE(probe_now(lesson, "vx"), 0.1 / h * -std::expm1(-50.0 * h * t / 2.0), 0.005);
  // The hand's work is booked as it moves its end. What the books leave is any explicit
  // spring's: the step applies the pull from its start, F·h·(v_end − v_start)/2 a step against
  // the kinetic energy Box2D's velocities give, F·h·v/2 in all (0.024 J here, 0.4 % of the
  // hand's work); nothing more for a hand that reads the world.
  const double v = probe_now(lesson, "vx");
  EXPECT_LT(std::abs(lesson.scene().ledger().residual()), 1.2 * 0.5 * 50.0 * 0.1 * h * v);
}

constexpr const char* velocity_hack = R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, mass = 2,
                    velocity = { 2, 0 } }
every_step(function(t) block:scale_velocity(1 - 0.02) end)
probe { "x", unit = "m", read = { block, "x" } }
)";

TEST(WorldFunctions, AVelocityCutEveryFrameSumsToTheGeometricSeries) {
  // The first frame moves at v0, then each at (1 − f) times the last: h·v0·Σ(1 − f)^n = h·v0/f.
  ScriptFile script(with_heading(velocity_hack));
  Lesson lesson(script.path(), {}, at_rate(240.0));
  run_for(lesson, 6.0);
  EXPECT_NEAR(probe_now(lesson, "x"), 2.0 / 240.0 / 0.02, 2e-5);
  const EnergyLedger& ledger = lesson.scene().ledger();
  // All of the launch's kinetic energy was taken by the script, none by friction.
  EXPECT_NEAR(ledger.work_script, -0.5 * 2.0 * 4.0, 1e-6);
  EXPECT_EQ(ledger.work_friction, 0.0);
  EXPECT_LT(std::abs(ledger.residual()), 1e-6);
}

TEST(WorldFunctions, AVelocitySetByTheScriptIsWhatTheNextStepsForceSees) {
  // A probe reads the force after the frame (for the velocity then); every_step then sets the
  // velocity: the step that follows must apply the force for the new velocity, not the answer
  // the probe was given.
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, mass = 2,
                    velocity = { 2, 0 } }
local drag = force { "drag", on = block, force = function(t) return -3 * block.vx, 0 end }
probe { "drag", unit = "N", function() return drag.fx end }  -- Lua probes run before every_step
every_step(function(t) block:set_velocity(1, 0) end)
)"));
  Lesson lesson(script.path());
  for (int frame = 0; frame < 5; ++frame) lesson.step();
  lesson.step();
  EXPECT_EQ(lesson.scene().forces_applied()[0].x, -3.0f);
}

TEST(WorldFunctions, SetVelocityIsRefusedOutsideEveryStep) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0 }
force { "push", on = block, force = function(t) block:set_velocity(1, 0) return 0, 0 end }
)"));
  Lesson lesson(script.path());
  EXPECT_NE(error_of([&] { lesson.step(); }).find("set_velocity works only inside an every_step function"),
            std::string::npos);
}

// Two boxes hanging from one pulley (1 kg and 3 kg): T = 2·m1·m2·g/(m1 + m2).
TEST(WorldFunctions, AnAtwoodMachinesRopeReadsItsTension) {
  ScriptFile script(with_heading(R"(
local light = box { "light", material = "wood", width = 0.08, height = 0.08, x = -0.1, y = 0, mass = 1 }
local heavy = box { "heavy", material = "wood", width = 0.08, height = 0.08, x = 0.1, y = 0, mass = 3 }
local cord = rope { "cord", from = light, over = { 0, 2 }, to = heavy }
probe { "tension", unit = "N", read = { cord, "tension" } }
probe { "tension_in_lua", unit = "N", function() return cord.tension end }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 0.25);
  EXPECT_RELATIVE(probe_now(lesson, "tension"), 2.0 * 1.0 * 3.0 * g / 4.0, 0.01);
  EXPECT_EQ(probe_now(lesson, "tension_in_lua"), probe_now(lesson, "tension"));
}

// A 2 kg block on a frictionless table tied over its edge to a hanging 1 kg weight:
// T = m_b·m_h·g/(m_b + m_h).
TEST(WorldFunctions, ABlockTiedToAHangingWeightReadsItsRopesTension) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0 }
local table_top = box { "table", material = "metal", kind = "static", width = 6, height = 1, x = 0, y = -0.5 }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = table_top, at = 0, mass = 2 }
local weight = box { "weight", material = "wood", width = 0.2, height = 0.2, x = 3.2, y = -1, mass = 1 }
local cord = rope { "cord", from = block, over = { 3.2, block.y }, to = weight }
probe { "tension", unit = "N", read = { cord, "tension" } }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 0.5);
  EXPECT_RELATIVE(probe_now(lesson, "tension"), 2.0 * 1.0 * g / 3.0, 0.01);
}

TEST(WorldFunctions, ABoxPlacedOnABoxStartsAtRestOnItsTopFace) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local bottom = box { "bottom", material = "wood", width = 0.6, height = 0.3, on = floor, at = 1 }
box { "top", material = "wood", width = 0.2, height = 0.1, on = bottom, at = 0.15 }
)"));
  Lesson lesson(script.path());
  const b2Body* bottom = lesson.scene().body("bottom");
  const b2Body* top = lesson.scene().body("top");
  EXPECT_NEAR(top->GetPosition().x, 1.15, 1e-6);
  EXPECT_NEAR(top->GetPosition().y, bottom->GetPosition().y + 0.15 + 0.05, 1e-6);
  lesson.step();
  EXPECT_LT(top->GetLinearVelocity().Length(), 1e-4);
  EXPECT_LT(bottom->GetLinearVelocity().Length(), 1e-4);
  run_for(lesson, 1.0);
  EXPECT_LT(top->GetLinearVelocity().Length(), 1e-4);
  EXPECT_NEAR(top->GetPosition().x, 1.15, 1e-5);
}

TEST(WorldFunctions, AContactReadsNoneInTheFrameItsBodiesPartAndNotBefore) {
  // A block thrown up off the floor: Box2D notices the contact ended only when it next
  // collides the pair, a step later; the view must say so in the frame the shapes part.
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, velocity = { 0, 1 } }
local touch = contact(block, floor)
probe { "touching", function() return touch.state == "none" and 0 or 1 end }
probe { "normal", unit = "N", read = { touch, "normal" } }
)"));
  Lesson lesson(script.path());
  const b2Body* block = lesson.scene().body("block");
  int parted = 0, joined = 0;
  for (int frame = 0; frame < 30; ++frame) {
    lesson.step();
    // Box2D's polygons touch while they are nearer than their two skins (a script's: true_skin).
    const double gap = block->GetPosition().y - 0.05, touching = 2.0 * true_skin;
    if (gap > touching + 1e-4) {
      ++parted;
      EXPECT_EQ(probe_now(lesson, "touching"), 0.0) << "frame " << frame << ", gap " << gap;
      EXPECT_EQ(probe_now(lesson, "normal"), 0.0) << "frame " << frame;
    } else if (gap < touching - 1e-4) {
      ++joined;
      EXPECT_EQ(probe_now(lesson, "touching"), 1.0) << "frame " << frame;
    }
  }
  EXPECT_GT(parted, 5);
  EXPECT_GT(joined, 0);
}

// The drag a contact reads is the impulse the step's exact viscous solution gave, over h: the
// mean force over the step, m·Δv/h, and c·v at mid-step to O(h²).
TEST(WorldFunctions, TheDragReadingIsTheMeanForceOverTheStep) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0, mu_k = 0, c = 4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0, mass = 2,
                    velocity = { 2, 0 } }
probe { "drag", unit = "N", read = { contact(block, floor), "drag_x" } }
probe { "vx", unit = "m/s", read = { block, "vx" } }
)"));
  const double hz = 240.0, h = 1.0 / hz, c = 4.0, m = 2.0, x = c * h / m;
  Lesson lesson(script.path(), {}, at_rate(hz));
  run_for(lesson, 0.1);
  for (int frame = 0; frame < 100; ++frame) {
    const double before = probe_now(lesson, "vx");
    lesson.step();
    const double after = probe_now(lesson, "vx"), drag = probe_now(lesson, "drag");
    EXPECT_RELATIVE(drag, m * (after - before) / h, 2e-4);  // float velocities: Δv to ~1e-5 of v
    const double mid = before * std::exp(-0.5 * x);          // exact v at the middle of the step
    EXPECT_NEAR(drag, -c * mid, c * mid * x * x / 20.0);     // differs by (x²/24)·c·v
    EXPECT_GT(std::abs(drag + c * mid), c * mid * x * x / 40.0);  // ...and is not c·v(mid) exactly
  }
}

}  // namespace
}  // namespace frictionlab::lessons
