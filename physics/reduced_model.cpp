#include "physics/reduced_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <utility>

#include "physics/friction_laws.h"
#include "physics/validation.h"

namespace frictionlab {
namespace {

using validation::reject;
using validation::require_finite;
using validation::require_non_negative;
using validation::require_positive;

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double event_tolerance = 1e-13;  // s: how closely events are located
constexpr std::size_t max_events = 1'000'000;
constexpr double max_steps = 1e9;

void require_block(const char* where, const OneDofBlock& block) {
  require_positive(where, "mass", block.mass);
  require_non_negative(where, "normal_force", block.normal_force);
  for (const PairCoefficient& coefficient : pair_coefficients) {
    require_non_negative(where, coefficient.name, block.pair.*coefficient.value);
  }
  require_finite(where, "constant_force", block.constant_force);
  require_non_negative(where, "spring_k", block.spring_k);
  require_finite(where, "anchor_start", block.anchor_start);
  require_finite(where, "pull_speed", block.pull_speed);
  require_finite(where, "rest_length", block.rest_length);
  require_finite(where, "x0", block.x0);
  require_finite(where, "v0", block.v0);
}

void require_step(const char* where, double h, double t_end) {
  require_positive(where, "h", h);
  if (t_end / h > max_steps) {
    std::ostringstream range;
    range << ">= t_end / 1e9 = " << t_end / max_steps << " s (at most 1e9 steps)";
    reject(where, "h", range.str().c_str(), h);
  }
}

// See the header: with μk > μs a push between μs·N and μk·N cannot keep the block sliding.
double breakaway_threshold(const OneDofBlock& block) {
  return std::max(block.pair.mu_s, block.pair.mu_k) * block.normal_force;
}

// Bisection for the first time the predicate turns true inside (lo, hi], given it is false at
// lo (or lo is the phase start) and true at hi.
template <class Predicate>
double bisect(double lo, double hi, Predicate turned) {
  while (hi - lo > event_tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (turned(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct SlipResult {
  Phase phase;
  BlockState final_state;
  bool stopped;
};
struct Breakaway {
  double t;          // infinity when the push never wins
  double direction;  // ±1
};

// The phase logic shared by both event-driven solvers; they differ only in how a phase is
// solved: stick(t0, x, t_limit) finds the breakaway, slip(t0, start, s, t_limit) the stop.
template <class StickSolver, class SlipSolver>
Trajectory drive(const OneDofBlock& block, double t_end, StickSolver stick, SlipSolver slip) {
  std::vector<Phase> phases;
  std::vector<Event> events;
  const double threshold = breakaway_threshold(block);
  double t = 0.0, direction = sign(block.v0);
  BlockState now{block.x0, block.v0};
  bool sliding = direction != 0.0;
  if (!sliding) {
    const double push = applied_force(block, 0.0, now.x);
    if (std::abs(push) > threshold) {
      sliding = true;
      direction = sign(push);
      events.push_back({0.0, now.x, 0.0, EventKind::breakaway});
    }
  }
  while (true) {
    if (events.size() > max_events) reject("solve", "t_end", "short enough for at most 1e6 events", t_end);
    if (!sliding) {
      const Breakaway next = stick(t, now.x, t_end);
      const double x_stuck = now.x;
      phases.push_back({t, std::min(next.t, t_end), PhaseKind::stick, [x_stuck](double) {
                          return BlockState{x_stuck, 0.0};
                        }});
      if (!(next.t < t_end)) break;
      t = next.t;
      direction = next.direction;
      sliding = true;
      events.push_back({t, now.x, 0.0, EventKind::breakaway});
      continue;
    }
    SlipResult result = slip(t, now, direction, t_end);
    phases.push_back(std::move(result.phase));
    now = result.final_state;
    if (!result.stopped) break;
    t = phases.back().t_end;
    now.v = 0.0;
    const double push = applied_force(block, t, now.x);
    if (std::abs(push) <= threshold) {
      sliding = false;
      events.push_back({t, now.x, 0.0, EventKind::stop});
    } else {
      const double next_direction = sign(push);
      events.push_back({t, now.x, 0.0, next_direction == direction ? EventKind::breakaway : EventKind::reversal});
      direction = next_direction;
    }
  }
  const BlockState last = phases.back().state(t_end);
  events.push_back({t_end, last.x, last.v, EventKind::end});
  return Trajectory(std::move(phases), std::move(events));
}

PhaseKind slip_kind(double direction) { return direction > 0.0 ? PhaseKind::slip_right : PhaseKind::slip_left; }

// One slip phase in closed form: m x'' + c x' + k x = P + k V t, with P gathering the constant
// force, the spring's fixed offset and kinetic friction −s μk N. With k > 0 it is the ramp
// x_p = (P − cV)/k + V t plus a free damped oscillation y; with k = 0 a drift to terminal speed.
class SlipClosedForm {
 public:
  SlipClosedForm(const OneDofBlock& block, double t0, BlockState start, double direction)
      : m_(block.mass), k_(block.spring_k), c_(block.pair.c), pull_speed_(block.pull_speed), start_(start) {
    p_ = block.constant_force + k_ * (block.anchor_start - block.rest_length) -
         direction * block.pair.mu_k * block.normal_force;
    if (k_ == 0.0) return;
    lambda_ = -c_ / (2.0 * m_);
    const double squared = (4.0 * m_ * k_ - c_ * c_) / (4.0 * m_ * m_);  // ω0² − λ²
    rate_ = std::sqrt(std::abs(squared));
    shape_ = squared > 0.0 ? Shape::under : squared == 0.0 ? Shape::critical : Shape::over;
    ramp_start_ = (p_ - c_ * pull_speed_) / k_ + pull_speed_ * t0;
    y0_ = start.x - ramp_start_;
    w_ = (start.v - pull_speed_) - lambda_ * y0_;
    // λ ± μ without the cancellation of a strongly overdamped λ + μ: their product is k/m.
    fast_ = lambda_ - rate_;
    slow_ = (k_ / m_) / fast_;
  }

  BlockState at(double tau) const {
    if (k_ == 0.0) {
      if (c_ == 0.0) {
        const double a = p_ / m_;
        return {start_.x + start_.v * tau + a * tau * tau / 2.0, start_.v + a * tau};
      }
      const double gamma = c_ / m_, terminal = p_ / c_;
      return {start_.x + terminal * tau - (start_.v - terminal) * std::expm1(-gamma * tau) / gamma,
              terminal + (start_.v - terminal) * std::exp(-gamma * tau)};
    }
    // y = e^{λτ}(y0·C + w·S), with C' = σS and S' = C: σ = −ω² (cos, sin/ω), +μ² (cosh, sinh/μ), 0.
    double ec = 0.0, es = 0.0, sigma = 0.0;  // e^{λτ}C and e^{λτ}S
    if (shape_ == Shape::under) {
      const double decay = std::exp(lambda_ * tau);
      ec = decay * std::cos(rate_ * tau);
      es = decay * std::sin(rate_ * tau) / rate_;
      sigma = -rate_ * rate_;
    } else if (shape_ == Shape::critical) {
      ec = std::exp(lambda_ * tau);
      es = ec * tau;
    } else {
      if (rate_ * tau < 1.0) {
        const double decay = std::exp(lambda_ * tau);
        ec = decay * std::cosh(rate_ * tau);
        es = decay * std::sinh(rate_ * tau) / rate_;
      } else {  // the separate exponentials never overflow, and no longer cancel
        const double slow = std::exp(slow_ * tau), fast = std::exp(fast_ * tau);
        ec = 0.5 * (slow + fast);
        es = (slow - fast) / (2.0 * rate_);
      }
      sigma = rate_ * rate_;
    }
    const double y = y0_ * ec + w_ * es;
    const double y_rate = lambda_ * y + sigma * y0_ * es + w_ * ec;
    return {ramp_start_ + pull_speed_ * tau + y, pull_speed_ + y_rate};
  }

  // First τ in (0, tau_max] at which s·v reaches 0, or infinity.
  double first_stop(double direction, double tau_max) const {
    if (k_ == 0.0) return drift_stop(direction, tau_max);
    // Scan finely enough to resolve the oscillation and the fast transient, with steps growing
    // geometrically once past it: over- and critically damped velocities have at most two zeros.
    double shortest = 0.0, longest = infinity;
    if (shape_ == Shape::under) {
      longest = 2.0 * std::numbers::pi / rate_ / 32.0;
      shortest = lambda_ == 0.0 ? longest : std::min(longest, 1.0 / (32.0 * -lambda_));
    } else {
      shortest = 1.0 / (32.0 * -fast_);
    }
    const auto stopped = [&](double tau) { return direction * at(tau).v <= 0.0; };
    // The speed can dip below zero and back between two scan points: a block that follows a
    // fast hand, its spring swinging, touches v = 0 for a sliver of each swing. So where the
    // speed turns from falling to rising within a scan step, its lowest point is found (by
    // bisection on the slope's sign) and tested too.
    const double nudge = 1e-6 * shortest;
    const auto rising = [&](double tau) { return direction * (at(tau + nudge).v - at(tau).v) > 0.0; };
    double tau = 0.0;
    while (tau < tau_max) {
      const double next = std::min(tau + std::clamp(0.05 * tau, shortest, longest), tau_max);
      if (stopped(next)) return bisect(tau, next, stopped);
      if (!rising(tau) && rising(next)) {
        const double lowest = bisect(tau, next, rising);
        if (stopped(lowest)) return bisect(tau, lowest, stopped);
      }
      tau = next;
    }
    return infinity;
  }

 private:
  enum class Shape { under, critical, over };

  double drift_stop(double direction, double tau_max) const {
    double tau = infinity;
    if (c_ == 0.0) {
      if (direction * p_ < 0.0) tau = -start_.v / (p_ / m_);
    } else {
      const double terminal = p_ / c_;
      if (direction * terminal < 0.0) tau = std::log1p(-start_.v / terminal) / (c_ / m_);
    }
    return tau <= tau_max ? std::max(tau, 0.0) : infinity;
  }

  double m_, k_, c_, pull_speed_;
  BlockState start_;
  double p_ = 0.0, lambda_ = 0.0, rate_ = 0.0, fast_ = 0.0, slow_ = 0.0;
  double ramp_start_ = 0.0, y0_ = 0.0, w_ = 0.0;
  Shape shape_ = Shape::under;
};

// One classical RK4 step of x'' = acceleration(t, x, v).
template <class Acceleration>
BlockState rk4_step(double t, BlockState s, double dt, Acceleration acceleration) {
  const double k1x = s.v, k1v = acceleration(t, s.x, s.v);
  const double k2x = s.v + 0.5 * dt * k1v, k2v = acceleration(t + 0.5 * dt, s.x + 0.5 * dt * k1x, k2x);
  const double k3x = s.v + 0.5 * dt * k2v, k3v = acceleration(t + 0.5 * dt, s.x + 0.5 * dt * k2x, k3x);
  const double k4x = s.v + dt * k3v, k4v = acceleration(t + dt, s.x + dt * k3x, k4x);
  return {s.x + dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x), s.v + dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v)};
}

// The slip-phase right-hand side with the direction of kinetic friction held fixed: the
// engineering model's kinetic branch, with its sign taken from the phase, not from v (which
// is zero at the phase's start).
BlockState rk4_step(const OneDofBlock& block, double direction, double t, BlockState s, double dt) {
  return rk4_step(t, s, dt, [&](double time, double x, double v) {
    return (applied_force(block, time, x) - direction * block.pair.mu_k * block.normal_force +
            damping_force(v, block.pair)) /
           block.mass;
  });
}

}  // namespace

double applied_force(const OneDofBlock& block, double t, double x) {
  return block.constant_force +
         block.spring_k * (block.anchor_start + block.pull_speed * t - x - block.rest_length);
}

Trajectory::Trajectory(std::vector<Phase> phases, std::vector<Event> events)
    : phases_(std::move(phases)), events_(std::move(events)) {
  if (phases_.empty()) throw InvalidInput("Trajectory: needs at least one phase");
}

BlockState Trajectory::state(double t) const {
  if (!(t >= 0.0 && t <= t_end())) {
    std::ostringstream range;
    range << "in [0, t_end] = [0, " << t_end() << "] s";
    reject("Trajectory", "t", range.str().c_str(), t);
  }
  const auto later = std::upper_bound(phases_.begin(), phases_.end(), t,
                                      [](double time, const Phase& phase) { return time < phase.t_start; });
  return std::prev(later)->state(t);
}

double Trajectory::position(double t) const { return state(t).x; }
double Trajectory::velocity(double t) const { return state(t).v; }

Trajectory solve_exact(const OneDofBlock& block, double t_end) {
  require_block("solve_exact", block);
  require_non_negative("solve_exact", "t_end", t_end);
  if (block.pair.b != 0.0) reject("solve_exact", "b", "0 (use solve_event_rk4 for quadratic drag)", block.pair.b);
  const double threshold = breakaway_threshold(block);
  // Stuck, the push changes linearly, at k·V per second, until it reaches ±threshold.
  const auto stick = [&block, threshold](double t0, double x, double) -> Breakaway {
    const double push = applied_force(block, t0, x), rate = block.spring_k * block.pull_speed;
    if (rate > 0.0) return {t0 + std::max((threshold - push) / rate, 0.0), 1.0};
    if (rate < 0.0) return {t0 + std::max((-threshold - push) / rate, 0.0), -1.0};
    return {infinity, 0.0};
  };
  const auto slip = [&block](double t0, BlockState start, double direction, double t_limit) -> SlipResult {
    const SlipClosedForm form(block, t0, start, direction);
    const double tau = form.first_stop(direction, t_limit - t0);
    const bool stopped = tau < infinity;
    const double t1 = stopped ? t0 + tau : t_limit;
    return {{t0, t1, slip_kind(direction), [form, t0](double t) { return form.at(t - t0); }},
            form.at(t1 - t0),
            stopped};
  };
  return drive(block, t_end, stick, slip);
}

Trajectory solve_event_rk4(const OneDofBlock& block, double t_end, double h) {
  require_block("solve_event_rk4", block);
  require_non_negative("solve_event_rk4", "t_end", t_end);
  require_step("solve_event_rk4", h, t_end);
  const double threshold = breakaway_threshold(block);
  // Stuck, only the push matters: scan it and bisect the scan step where it wins. The push is
  // linear in t (a constant force and a spring whose end moves steadily), so no crossing hides
  // between two scan points, and a long stick is scanned in at most about 1000 steps of h or more.
  const auto stick = [&block, threshold, h](double t0, double x, double t_limit) -> Breakaway {
    const auto wins = [&](double t) { return std::abs(applied_force(block, t, x)) > threshold; };
    const double scan = std::isfinite(t_limit) ? std::max(h, (t_limit - t0) / 1000.0) : h;
    for (double n = 1.0;; n += 1.0) {
      const double before = t0 + (n - 1.0) * scan, after = std::min(t0 + n * scan, t_limit);
      if (wins(after)) {
        const double t = bisect(before, after, wins);
        return {t, sign(applied_force(block, after, x))};
      }
      if (after >= t_limit) return {infinity, 0.0};
    }
  };
  const auto slip = [&block, h](double t0, BlockState start, double direction, double t_limit) -> SlipResult {
    auto nodes = std::make_shared<std::vector<Sample>>();
    nodes->push_back({t0, start.x, start.v});
    bool stopped = false;
    for (double n = 1.0; nodes->back().t < t_limit; n += 1.0) {
      const Sample node = nodes->back();
      const BlockState from{node.x, node.v};
      const double dt = std::min(t0 + n * h, t_limit) - node.t;
      BlockState next = rk4_step(block, direction, node.t, from, dt);
      if (direction * next.v <= 0.0) {
        // Re-integrate shorter sub-steps from the same node until the sign change is pinned down.
        const double tau = bisect(0.0, dt, [&](double sub) {
          return direction * rk4_step(block, direction, node.t, from, sub).v <= 0.0;
        });
        next = rk4_step(block, direction, node.t, from, tau);
        nodes->push_back({node.t + tau, next.x, next.v});
        stopped = true;
        break;
      }
      nodes->push_back({node.t + dt, next.x, next.v});
    }
    const Sample last = nodes->back();
    const OneDofBlock copy = block;
    const auto state = [nodes, copy, direction](double t) {
      const auto later = std::upper_bound(nodes->begin(), nodes->end(), t,
                                          [](double time, const Sample& s) { return time < s.t; });
      const Sample& node = *std::prev(later == nodes->begin() ? std::next(later) : later);
      return t == node.t ? BlockState{node.x, node.v}
                         : rk4_step(copy, direction, node.t, BlockState{node.x, node.v}, t - node.t);
    };
    return {{t0, last.t, slip_kind(direction), state}, {last.x, last.v}, stopped};
  };
  return drive(block, t_end, stick, slip);
}

std::vector<Sample> integrate_regularized(const OneDofBlock& block, double t_end, double h, double epsilon,
                                          Integrator integrator) {
  const char* where = "integrate_regularized";
  require_block(where, block);
  require_non_negative(where, "t_end", t_end);
  require_step(where, h, t_end);
  require_positive(where, "epsilon", epsilon);
  const auto acceleration = [&](double t, double x, double v) {
    return (applied_force(block, t, x) + regularized_friction(v, block.normal_force, epsilon, block.pair)) /
           block.mass;
  };
  // Steps counted up front so that rounding in t_end / h cannot add a sliver of a step.
  const auto steps = static_cast<std::size_t>(std::ceil(t_end / h - 1e-9));
  std::vector<Sample> samples;
  samples.reserve(steps + 1);
  samples.push_back({0.0, block.x0, block.v0});
  for (std::size_t i = 0; i < steps; ++i) {
    const auto [t, x, v] = samples.back();
    const double t_next = i + 1 == steps ? t_end : static_cast<double>(i + 1) * h;
    const double dt = t_next - t;
    switch (integrator) {
      case Integrator::explicit_euler:
        samples.push_back({t_next, x + dt * v, v + dt * acceleration(t, x, v)});
        break;
      case Integrator::semi_implicit_euler: {
        // The new velocity moves the position: the symplectic order that games use.
        const double v_next = v + dt * acceleration(t, x, v);
        samples.push_back({t_next, x + dt * v_next, v_next});
        break;
      }
      case Integrator::rk4: {
        const BlockState next = rk4_step(t, {x, v}, dt, acceleration);
        samples.push_back({t_next, next.x, next.v});
        break;
      }
    }
  }
  return samples;
}

}  // namespace frictionlab
