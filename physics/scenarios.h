// The standard situations of the seed articles as ready-made scenes, with the measurements
// that compare them with theory. Tests, the demonstration table and the benchmarks share them.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "physics/reduced_model.h"
#include "physics/scene.h"

namespace frictionlab {

constexpr double standard_gravity = 9.81;

// A rectangular block of a given mass; its material "block" meets the material "ground".
struct Block {
  double mass = 1.0;    // kg
  double width = 0.4;   // m
  double height = 0.2;  // m
  FrictionPair pair{0.6, 0.4, 0.0, 0.0};
};
// Materials "block" (dense enough to give the block its mass) and "ground", with their pair.
PairTable block_on_ground(const Block& block);

// The spring article: a spring at rest length pulls the block; its far end (the hand) moves
// at pull_speed from t = 0.
struct SpringPull {
  Block block;
  double stiffness = 50.0;   // k, N/m
  double pull_speed = 0.1;   // m/s
  double rest_length = 0.5;  // m
};
std::unique_ptr<Scene> make_spring_pull(const SpringPull& setup, const StepSettings& settings);
// Its one-degree-of-freedom twin: x is the block's centre, the hand starts rest_length ahead.
OneDofBlock spring_pull_model(const SpringPull& setup);

// A block released at rest on an incline of `angle` radians; probes "distance" and "speed"
// along the slope, downhill positive.
struct Incline {
  Block block;
  double angle = 0.5;
};
std::unique_ptr<Scene> make_incline(const Incline& setup, const StepSettings& settings);

// A block launched along flat ground at launch_speed; probe "distance".
struct Slide {
  Block block;
  double launch_speed = 3.0;
};
std::unique_ptr<Scene> make_slide(const Slide& setup, const StepSettings& settings);

// The tribology article's box pushed horizontally on its side at push_height above the
// ground, by a force growing at push_rate from zero; probes "push" (N), "tilt" (rad) and
// "slide" (m, of the front bottom corner, which stays put while the box tips about it).
struct PushedBox {
  Block block{10.0, 0.5, 1.0, {0.5, 0.4, 0.0, 0.0}};
  double push_height = 0.3;
  double push_rate = 20.0;  // N/s
};
std::unique_ptr<Scene> make_pushed_box(const PushedBox& setup, const StepSettings& settings);

// One comparison of simulation with theory, as the tables show it.
struct Measurement {
  std::string name;
  std::string unit;
  double predicted = 0.0;
  double measured = 0.0;
  double tolerance = 0.0;  // allowed |measured - predicted|, in the same unit
  double error() const { return measured - predicted; }
  bool passes() const { return std::abs(error()) <= tolerance; }
};

// What a spring-pull run showed: each breakaway (time, spring force) and re-stick (spring
// force) as the listener saw them, and the largest |x_sim - x_exact| of the block over the run
// against the exact event-driven solution of its twin (metres).
struct StickSlipObservation {
  std::vector<double> breakaway_times;
  std::vector<double> breakaway_forces;
  std::vector<double> restick_forces;
  double max_error = 0.0;
};
StickSlipObservation observe_spring_pull(const SpringPull& setup, const StepSettings& settings, double duration);
double spring_pull_max_error(const SpringPull& setup, const StepSettings& settings, double duration);
// Breakaway force, re-stick force and period against theory, and the position error against
// the exact solution (tolerance 5 mm).
std::vector<Measurement> spring_pull_measurements(const SpringPull& setup, const StepSettings& settings,
                                                  double duration);

// Measurements for the demonstration table and the tests.
Measurement measure_incline_creep(const Incline& setup, const StepSettings& settings, double duration);
Measurement measure_incline_acceleration(const Incline& setup, const StepSettings& settings);
// A block pulled by a force growing slowly at its centre: the force when it breaks away, and
// the friction while it slides.
Measurement measure_breakaway_force(const Block& block, const StepSettings& settings);
Measurement measure_sliding_friction(const Block& block, const StepSettings& settings);
Measurement measure_slide_distance(const Slide& setup, const StepSettings& settings);
// Which comes first as the push grows: 1 = tips, 0 = slides; and the push force when it does.
struct PushResult {
  bool tipped = false;
  double force = 0.0;
};
PushResult run_pushed_box(const PushedBox& setup, const StepSettings& settings, double duration);

// A pyramid of boxes `rows` high on static ground (rows·(rows+1)/2 boxes), for the cost of
// the listener. With `use_listener` false the world is plain Box2D with its own mixer and
// every fixture's friction 0.6, the mu_s that holds the resting pile in the listener's world.
struct Pyramid {
  std::unique_ptr<Scene> scene;      // with the listener
  std::unique_ptr<b2World> plain;    // without
  int boxes = 0;
};
Pyramid make_pyramid(int rows, bool use_listener, const StepSettings& settings);

}  // namespace frictionlab
