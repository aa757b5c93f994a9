// How a run of a block along a line went wrong, judged from its position and velocity at
// each frame against what the exact answer does. A benchmark keeps failed runs and marks them
// (a wrong picture of the physics is worse than a large error), so it needs the failure named:
// not a number, blown up, chattering, stick-slip that is not there or is missing, a block that
// should stay put creeping or sliding.
#pragma once

#include <string>
#include <vector>

#include "physics/reduced_model.h"

namespace frictionlab {

// What the exact motion does over the run.
struct ExpectedMotion {
  std::vector<double> stop_times;  // when it comes to rest (and sticks)
  bool moves = true;               // false: it should never leave its place
  double scale = 1.0;              // its largest |x| (m) and |v| (m/s): a blow-up is far beyond
};
// From an exact (or any event-driven) trajectory: its stops up to t_end, whether it slides,
// its scale.
ExpectedMotion expected_motion(const Trajectory& exact, double t_end);

class RunCheck {
 public:
  // At rest below stop_speed; moving again only above ten times that, so noise about zero
  // does not count as stops and starts. Velocity reversals count above a tenth of it.
  explicit RunCheck(double stop_speed = 1e-3) : stop_speed_(stop_speed) {}
  void add(double t, double x, double v);

  // "" when the run did what the exact motion does; else the first of "not a number", "blew
  // up" (a hundred times the exact motion's scale), "chatters", "slides" or "creeps" (a block
  // that should have stayed put, speeding up or at a steady speed), "sticks" (one that should
  // have moved), "spurious stick-slip" (a stop the exact motion has not near that time),
  // "misses stick-slip" (an exact stop the run has not near its time) or "never comes to
  // rest" (the exact motion's one stop missed).
  std::string failure(const ExpectedMotion& expected) const;

  const std::vector<double>& stop_times() const { return stop_times_; }

 private:
  double stop_speed_;
  bool finite_ = true;
  double largest_ = 0.0;  // of |x| and |v|
  double first_t_ = 0.0, last_t_ = 0.0, start_x_ = 0.0, farthest_ = 0.0;
  bool started_ = false, moving_ = false;
  std::vector<double> stop_times_;
  // Chatter: the velocity alternating in sign frame after frame without dying away.
  double last_v_ = 0.0;
  int flipping_ = 0;
  double flip_start_amplitude_ = 0.0;
  bool sustained_flipping_ = false;
  // Speed at the middle and at the end, to tell a slide (speeding up) from a creep.
  std::vector<std::pair<double, double>> speeds_;
};

}  // namespace frictionlab
