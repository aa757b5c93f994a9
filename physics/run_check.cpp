#include "physics/run_check.h"

#include <algorithm>
#include <cmath>

namespace frictionlab {
namespace {

// Beyond these a block on a lesson's bench has left the physics behind (Box2D itself moves a
// body at most 2 m per step, so a blow-up shows in the speed first).
constexpr double blown_up = 1e3;     // m and m/s
// Eight flips in a row whose amplitude has not halved: the regularized law past its stability
// boundary flips every step for good; inside it a flip dies by at least a factor per step.
constexpr int flips_to_judge = 8;

}  // namespace

ExpectedMotion expected_motion(const Trajectory& exact) {
  ExpectedMotion expected;
  expected.moves = false;
  for (const Phase& phase : exact.phases()) expected.moves = expected.moves || phase.kind != PhaseKind::stick;
  for (const Event& event : exact.events()) {
    if (event.kind == EventKind::stop) expected.stop_times.push_back(event.t);
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
    longest_flipping_ = std::max(longest_flipping_, flipping_);
  } else {
    flipping_ = 0;
  }
  last_v_ = v;
}

std::string RunCheck::failure(const ExpectedMotion& expected) const {
  if (!finite_) return "not a number";
  if (largest_ > blown_up) return "blew up";
  if (sustained_flipping_) return "chatters";
  if (!expected.moves) {
    if (farthest_ <= 1e-3) return "";
    // Speeding up between the middle of the run and its end: sliding; else a steady creep.
    const double middle = speeds_[speeds_.size() / 2].second, end = speeds_.back().second;
    return end > 1.5 * middle + stop_speed_ ? "slides" : "creeps";
  }
  // A stop within the last tenth of the run may fall either side of its end.
  const double margin = 0.1 * (last_t_ - first_t_);
  const std::size_t seen = stop_times_.size(), exact = expected.stop_times.size();
  if (seen > exact && !(seen == exact + 1 && stop_times_.back() > last_t_ - margin)) return "spurious stick-slip";
  if (seen < exact && !(seen + 1 == exact && expected.stop_times.back() > last_t_ - margin)) return "misses stick-slip";
  return "";
}

}  // namespace frictionlab
