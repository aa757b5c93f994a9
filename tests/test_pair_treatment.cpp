// Friction treatment per pair: one world holds a stick-slip block beside a regularized one
// beside Box2D's own, each pair keeping its treatment whatever the run's is, and a pair with
// none following the run's. The slope is made by tilting gravity, so every block sees the same
// slope on one flat floor; tan(20°) = 0.364 lies between mu_k = 0.3 and mu_s = 0.6.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/scene.h"

using namespace frictionlab;

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

TEST(PairTreatment, BadTreatmentsAndEpsilonsAreRefusedAndLeaveThePairAsItWas) {
  PairTable table;
  table.add_material({"a", 1.0, ""});
  table.add_material({"b", 1.0, ""});
  auto message = [&](auto&& call) {
    try {
      call();
    } catch (const InvalidInput& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(message([&] { table.set_treatment("a", "b", FrictionTreatment::regularized, 0.05); }),
            "pair a–b: set its friction values before its treatment");
  table.set_pair("a", "b", {mu_s, mu_k, 0.0, 0.0});
  EXPECT_EQ(message([&] { table.set_treatment("a", "b", FrictionTreatment::box2d, 0.05); }),
            "pair a–b: epsilon is for the threshold and regularized treatments, not box2d");
  EXPECT_EQ(message([&] { table.set_treatment("a", "b", FrictionTreatment::threshold, -1.0); }),
            "pair a–b: epsilon = -1 m/s is outside the allowed range (0, 100]");
  EXPECT_EQ(message([&] { parse_treatment("coulomb"); }),
            "unknown friction treatment 'coulomb'; allowed: stick-slip, threshold, regularized, box2d");
  EXPECT_FALSE(table.treatment(0, 1).own);
  table.set_treatment("b", "a", FrictionTreatment::threshold, 0.2);
  EXPECT_TRUE(table.treatment(0, 1).own);
  EXPECT_EQ(table.treatment(0, 1).epsilon, 0.2);
}
