#include "bench/run_check.h"

#include <algorithm>
#include <cmath>

namespace frictionlab {
namespace {

// A blow-up is this many times the exact motion's largest distance or speed. (Box2D moves a
// body at most 2 m a step, so at a low step rate even a runaway stays below any fixed speed.)
constexpr double blown_up = 100.0;
// Eight flips in a row whose amplitude has not halved: the regularized law past its stability
// boundary flips every step for good; inside it a flip dies by at least a factor per step.
constexpr int flips_to_judge = 8;

}  // namespace

ExpectedMotion expected_motion(const Trajectory& exact, double t_end) {
  ExpectedMotion expected;
  expected.moves = false;
  for (const Phase& phase : exact.phases()) {
    if (phase.t_start < t_end) expected.moves = expected.moves || phase.kind != PhaseKind::stick;
  }
  for (const Event& event : exact.events()) {
    if (event.kind == EventKind::stop && event.t <= t_end) expected.stop_times.push_back(event.t);
  }
  expected.scale = 0.0;
  const double end = std::min(t_end, exact.t_end());
  for (int i = 0; i <= 1000; ++i) {
    const BlockState state = exact.state(end * i / 1000.0);
    expected.scale = std::max({expected.scale, std::abs(state.x), std::abs(state.v)});
  }
  return expected;
}

void RunCheck::add(double t, double x, double v) {
  if (!std::isfinite(x) || !std::isfinite(v) || !std::isfinite(t)) {
    finite_ = false;
    return;
  }
  if (!started_) {
    started_ = true;
    first_t_ = t;
    start_x_ = x;
    moving_ = std::abs(v) > 10.0 * stop_speed_;
  }
  last_t_ = t;
  largest_ = std::max({largest_, std::abs(x), std::abs(v)});
  farthest_ = std::max(farthest_, std::abs(x - start_x_));
  speeds_.emplace_back(t, std::abs(v));

  if (moving_ && std::abs(v) < stop_speed_) {
    moving_ = false;
    stop_times_.push_back(t);
  } else if (!moving_ && std::abs(v) > 10.0 * stop_speed_) {
    moving_ = true;
  }

  const double noise = 0.1 * stop_speed_;
  const bool flipped = std::abs(v) > noise && std::abs(last_v_) > noise && (v > 0.0) != (last_v_ > 0.0);
  if (flipped) {
    if (flipping_ % flips_to_judge == 0) {
      // A window of flips ends here: sustained if it kept half its amplitude.
      if (flipping_ > 0 && std::abs(v) >= 0.5 * flip_start_amplitude_) sustained_flipping_ = true;
      flip_start_amplitude_ = std::abs(v);
    }
    ++flipping_;
  } else {
    flipping_ = 0;
  }
  last_v_ = v;
}

std::string RunCheck::failure(const ExpectedMotion& expected) const {
  if (!finite_) return "not a number";
  if (largest_ > blown_up * std::max(expected.scale, 1.0)) return "blew up";
  if (sustained_flipping_) return "chatters";
  if (!expected.moves) {
    if (farthest_ <= 1e-3) return "";
    // Speeding up between the middle of the run and its end: sliding; else a steady creep.
    const double middle = speeds_[speeds_.size() / 2].second, end = speeds_.back().second;
    return end > 1.5 * middle + stop_speed_ ? "slides" : "creeps";
  }
  if (farthest_ <= 1e-3) return "sticks";
  // Each stop is paired with an exact one near its time, in order: within half the shortest
  // time between two exact stops (a quarter of the run when there are fewer than two). A stop
  // within the last tenth of the run may fall either side of its end and is not held against
  // either side.
  const std::vector<double>& exact = expected.stop_times;
  double window = 0.25 * (last_t_ - first_t_);
  for (std::size_t i = 1; i < exact.size(); ++i) window = std::min(window, 0.5 * (exact[i] - exact[i - 1]));
  const double late = last_t_ - 0.1 * (last_t_ - first_t_);
  int spurious = 0, missed = 0;
  std::size_t next = 0;
  for (const double stop : stop_times_) {
    while (next < exact.size() && exact[next] < stop - window) missed += exact[next++] <= late;
    if (next < exact.size() && std::abs(exact[next] - stop) <= window) {
      ++next;
    } else {
      spurious += stop <= late;
    }
  }
  for (; next < exact.size(); ++next) missed += exact[next] <= late;
  if (spurious > 0) return "spurious stick-slip";
  if (missed > 0) return exact.size() == 1 ? "never comes to rest" : "misses stick-slip";
  return "";
}

}  // namespace frictionlab
