#include "physics/wedge_model.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "physics/validation.h"

namespace frictionlab {

double WedgeDrive::angle(double t) const { return theta0 * std::sin(omega * t); }
double WedgeDrive::angular_velocity(double t) const { return theta0 * omega * std::cos(omega * t); }
double WedgeDrive::angular_acceleration(double t) const { return -theta0 * omega * omega * std::sin(omega * t); }
double WedgeDrive::acceleration(double t) const { return a_x * std::cos(a_x_omega * t); }
// F and N from the surface's angle (its sine and cosine) and the wedge's acceleration a.
double WedgeDrive::driving_force_at(double sin_theta, double cos_theta, double a) const {
  return mass * (g * sin_theta + a * cos_theta);
}
double WedgeDrive::normal_force_at(double sin_theta, double cos_theta, double a) const {
  return mass * (g * cos_theta - a * sin_theta);
}
double WedgeDrive::driving_force(double t) const {
  const double theta = angle(t);
  return driving_force_at(std::sin(theta), std::cos(theta), acceleration(t));
}
double WedgeDrive::normal_force(double t) const {
  const double theta = angle(t);
  return normal_force_at(std::sin(theta), std::cos(theta), acceleration(t));
}
// From rest at x = 0: x'' = a_x·cos(ω_a·t) gives x' = a_x·sin(ω_a·t)/ω_a, x = a_x·(1 − cos(ω_a·t))/ω_a²,
// and ½·a_x·t² in the limit ω_a → 0. 1 − cos is written as 2·sin²(·/2) so small ω_a·t loses nothing.
double WedgeDrive::wedge_position(double t) const {
  if (a_x_omega == 0.0) return 0.5 * a_x * t * t;
  const double half = std::sin(0.5 * a_x_omega * t) / a_x_omega;
  return 2.0 * a_x * half * half;
}
double WedgeDrive::wedge_velocity(double t) const {
  if (a_x_omega == 0.0) return a_x * t;
  return a_x * std::sin(a_x_omega * t) / a_x_omega;
}

const char* name_of(WedgeEventKind kind) {
  switch (kind) {
    case WedgeEventKind::breakaway: return "breakaway";
    case WedgeEventKind::stop: return "stop";
    case WedgeEventKind::reversal: return "reversal";
    case WedgeEventKind::lift_off: return "lift-off";
    case WedgeEventKind::landing: return "landing";
    case WedgeEventKind::sign_change: return "sign change";
  }
  return "?";
}

double kinetic_energy(const WedgeDrive& drive, const WedgeState& state) {
  return 0.5 * drive.mass * (state.speed * state.speed + state.height_rate * state.height_rate);
}

namespace {

constexpr double event_tolerance = 1e-13;  // s: how closely events are located
constexpr std::size_t max_events = 1'000'000;
constexpr double max_samples = 2e6;

// What the solver integrates: the slide and its rate, the height above the surface and its
// rate (0 in contact), and the three works that accumulate continuously.
struct Vector {
  double s = 0, v = 0, d = 0, dd = 0, work_gravity = 0, work_pseudo = 0, work_friction = 0, work_rotation = 0;
};
Vector operator+(const Vector& a, const Vector& b) {
  return {a.s + b.s, a.v + b.v, a.d + b.d, a.dd + b.dd, a.work_gravity + b.work_gravity,
          a.work_pseudo + b.work_pseudo, a.work_friction + b.work_friction, a.work_rotation + b.work_rotation};
}
Vector operator*(double k, const Vector& a) {
  return {k * a.s, k * a.v, k * a.d, k * a.dd, k * a.work_gravity, k * a.work_pseudo, k * a.work_friction,
          k * a.work_rotation};
}

double sign_of(double x) { return x < 0.0 ? -1.0 : 1.0; }

// A phase: the contact, and in a slip the sign σ of the friction's opposition (friction is
// −σ·μk·N): the sliding direction for Coulomb's law, the driving force's for the article's.
struct Phase {
  WedgeContact contact = WedgeContact::stick;
  double sigma = 1.0;
};

class Solver {
 public:
  Solver(const WedgeDrive& drive, WedgeLaw law) : drive_(drive), law_(law) {}

  // The drive at one time, its sines and cosines taken once: a step of RK4 asks the rate four
  // times, and each rate asked the drive for them a dozen times over (two thirds of a wedge
  // check's time was sin and cos). WedgeDrive's own formulas, so the same numbers.
  struct DriveAt {
    double t = std::nan("");
    double sin_theta = 0, cos_theta = 0, acceleration = 0, rate = 0, spin_up = 0, driving_force = 0, normal_force = 0;
  };
  const DriveAt& at(double t) const {
    if (t == at_.t) return at_;
    const double swing = std::sin(drive_.omega * t);
    const double theta = drive_.theta0 * swing;
    at_.t = t;
    at_.sin_theta = std::sin(theta);
    at_.cos_theta = std::cos(theta);
    at_.acceleration = drive_.acceleration(t);
    at_.rate = drive_.rotation ? drive_.angular_velocity(t) : 0.0;
    at_.spin_up = -drive_.theta0 * drive_.omega * drive_.omega * swing;
    at_.driving_force = drive_.driving_force_at(at_.sin_theta, at_.cos_theta, at_.acceleration);
    at_.normal_force = drive_.normal_force_at(at_.sin_theta, at_.cos_theta, at_.acceleration);
    return at_;
  }

  // The turning frame's accelerations on the block's centre (0 without rotation): along the
  // slope (down positive) and away from the surface, split into the parts that do work
  // (centrifugal and Euler) and Coriolis, which does none.
  struct Turning {
    double along = 0, across = 0, coriolis_along = 0, coriolis_across = 0;
  };
  Turning turning(const DriveAt& drive, const Vector& y) const {
    if (!drive_.rotation) return {};
    const double rate = drive.rate, spin_up = drive.spin_up;
    const double rho = drive_.start - y.s;           // up the slope from the pivot
    const double z = drive_.centre_height + y.d;     // above the surface line
    // Up the slope: θ''·z + θ'²·ρ (+ 2θ'·z'); away from the surface: −θ''·ρ + θ'²·z (− 2θ'·ρ' = + 2θ'·s').
    return {-(spin_up * z + rate * rate * rho), -spin_up * rho + rate * rate * z, -2.0 * rate * y.dd, 2.0 * rate * y.v};
  }
  // What pushes the block down the slope and the surface's push, with the block in contact, and
  // the turning frame's part in them: worked out once for each rate or test. In WebAssembly
  // these small methods were not inlined, and each rate worked out the turning three times.
  struct Forces {
    DriveAt drive;
    Turning turn;
    double driving = 0, pressing = 0;
  };
  Forces forces(double t, const Vector& y) const {
    const DriveAt& drive = at(t);
    const Turning turn = turning(drive, y);
    return {drive, turn, drive.driving_force + drive_.mass * (turn.along + turn.coriolis_along),
            drive.normal_force - drive_.mass * (turn.across + turn.coriolis_across)};
  }
  double driving(double t, const Vector& y) const { return forces(t, y).driving; }
  double pressing(double t, const Vector& y) const { return forces(t, y).pressing; }

  double friction(const Phase& phase, const Forces& f) const {
    switch (phase.contact) {
      case WedgeContact::stick: return -f.driving;
      case WedgeContact::slip: return -phase.sigma * drive_.mu_k * f.pressing;
      case WedgeContact::flight: return 0.0;
    }
    return 0.0;
  }

  Vector rate(const Phase& phase, double t, const Vector& y) const {
    if (phase.contact == WedgeContact::stick) return {};
    const Forces f = forces(t, y);
    const double m = drive_.mass, a = f.drive.acceleration;
    const double sin_t = f.drive.sin_theta, cos_t = f.drive.cos_theta;
    const Turning& turn = f.turn;
    Vector r;
    r.s = y.v;
    r.work_gravity = m * drive_.g * sin_t * y.v;
    r.work_pseudo = m * a * cos_t * y.v;
    r.work_rotation = m * turn.along * y.v;
    if (phase.contact == WedgeContact::slip) {
      const double friction_force = friction(phase, f);
      r.v = (f.driving + friction_force) / m;
      r.work_friction = friction_force * y.v;
    } else {  // flight: the frame's effective gravity across the surface too
      r.v = f.driving / m;
      r.d = y.dd;
      r.dd = -f.drive.normal_force / m + turn.across + turn.coriolis_across;
      r.work_gravity -= m * drive_.g * cos_t * y.dd;
      r.work_pseudo += m * a * sin_t * y.dd;
      r.work_rotation += m * turn.across * y.dd;
    }
    return r;
  }

  Vector rk4(const Phase& phase, double t, const Vector& y, double h) const {
    const Vector k1 = rate(phase, t, y);
    const Vector k2 = rate(phase, t + 0.5 * h, y + (0.5 * h) * k1);
    const Vector k3 = rate(phase, t + 0.5 * h, y + (0.5 * h) * k2);
    const Vector k4 = rate(phase, t + h, y + h * k3);
    return y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }

  double breakaway_limit(double pressing_force) const { return std::max(drive_.mu_s, drive_.mu_k) * pressing_force; }

  // Whether the phase has ended by (t, y).
  bool ended(const Phase& phase, double t, const Vector& y) const {
    switch (phase.contact) {
      case WedgeContact::stick: {
        const Forces f = forces(t, y);
        return f.pressing < 0.0 || std::abs(f.driving) > breakaway_limit(f.pressing);
      }
      case WedgeContact::slip: {
        const Forces f = forces(t, y);
        if (f.pressing < 0.0) return true;
        if (law_ == WedgeLaw::coulomb) return phase.sigma * y.v <= 0.0;
        // The article's friction, −sgn(F)·μk·N, is none while F = 0 (σ = 0): that phase ends
        // when F takes a sign, the others when F changes it.
        return phase.sigma == 0.0 ? f.driving != 0.0 : phase.sigma * f.driving < 0.0;
      }
      case WedgeContact::flight: return y.d < 0.0;
    }
    return false;
  }

  // The phase a block in contact at t enters, touching with slide rate v (v = 0: at rest on it).
  Phase contact_phase(double t, const Vector& y) const {
    const Forces f = forces(t, y);
    const double force = f.driving;
    if (law_ == WedgeLaw::article) {
      // At F = 0 exactly, the sign F takes next; none if it stays 0 (a still, level surface).
      if (force != 0.0) return {WedgeContact::slip, sign_of(force)};
      const double next = driving(t + 1e-9, y);
      return {WedgeContact::slip, next == 0.0 ? 0.0 : sign_of(next)};
    }
    if (y.v != 0.0) return {WedgeContact::slip, sign_of(y.v)};
    if (std::abs(force) <= breakaway_limit(f.pressing)) return {WedgeContact::stick, 1.0};
    return {WedgeContact::slip, sign_of(force)};
  }

  WedgeState state_of(const Phase& phase, double t, const Vector& y, double work_landings) const {
    WedgeState state;
    state.t = t;
    state.slide = y.s, state.speed = y.v, state.height = y.d, state.height_rate = y.dd;
    state.contact = phase.contact;
    const Forces f = forces(t, y);
    state.normal = phase.contact == WedgeContact::flight ? 0.0 : f.pressing;
    state.friction = friction(phase, f);
    state.work_gravity = y.work_gravity, state.work_pseudo = y.work_pseudo, state.work_friction = y.work_friction;
    state.work_rotation = y.work_rotation;
    state.work_landings = work_landings;
    return state;
  }

  WedgeRun run(double t_end, double sample_step, double max_step) {
    WedgeRun result;
    result.sample_step = sample_step;
    const auto sample_count = static_cast<std::size_t>(std::floor(t_end / sample_step + 1e-9)) + 1;
    result.samples.reserve(sample_count);
    double t = 0.0, work_landings = 0.0;
    Vector y;
    y.v = drive_.start_speed;
    Phase phase = contact_phase(0.0, y);
    double window_start = phase.contact == WedgeContact::slip ? 0.0 : -1.0;
    result.samples.push_back(state_of(phase, 0.0, y, 0.0));
    std::size_t next = 1;
    auto event = [&](WedgeEventKind kind) {
      if (result.events.size() >= max_events) {
        throw InvalidInput("the wedge: more than a million events before t = " + std::to_string(t) +
                           " s (the block chatters between phases); shorten the run");
      }
      result.events.push_back({t, kind, y.s, y.v});
    };
    auto enter = [&](Phase entered) {
      const bool was_slipping = phase.contact == WedgeContact::slip;
      const bool slips = entered.contact == WedgeContact::slip;
      if (slips && !was_slipping) window_start = t;
      if (was_slipping && !slips) {
        result.slip_windows.emplace_back(window_start, t);
        window_start = -1.0;
      }
      phase = entered;
    };
    while (next < sample_count) {
      const double sample_t = static_cast<double>(next) * sample_step;
      if (t == sample_t) {  // an event found on a sample's instant: record it before stepping on
        result.samples.push_back(state_of(phase, t, y, work_landings)), ++next;
        continue;
      }
      const double h = std::min(max_step, sample_t - t);
      Vector after = rk4(phase, t, y, h);
      if (!ended(phase, t + h, after)) {
        y = after;
        t = h == sample_t - t ? sample_t : t + h;
        if (t == sample_t) result.samples.push_back(state_of(phase, t, y, work_landings)), ++next;
        continue;
      }
      // The phase ends inside this step: the first instant it has, to event_tolerance.
      double lo = 0.0, hi = h;
      while (hi - lo > event_tolerance) {
        const double mid = 0.5 * (lo + hi);
        if (ended(phase, t + mid, rk4(phase, t, y, mid))) hi = mid;
        else lo = mid;
      }
      y = rk4(phase, t, y, hi);
      t += hi;
      transition(phase, t, y, work_landings, event, enter);
    }
    if (phase.contact == WedgeContact::slip) result.slip_windows.emplace_back(window_start, t);
    return result;
  }

 private:
  template <class Event, class Enter>
  void transition(const Phase& phase, double t, Vector& y, double& work_landings, Event event, Enter enter) {
    const double m = drive_.mass;
    if (phase.contact != WedgeContact::flight && pressing(t, y) < 0.0) {
      y.d = 0.0, y.dd = 0.0;
      event(WedgeEventKind::lift_off);
      enter({WedgeContact::flight, 1.0});
      return;
    }
    switch (phase.contact) {
      case WedgeContact::stick: {
        event(WedgeEventKind::breakaway);
        enter({WedgeContact::slip, sign_of(driving(t, y))});
        return;
      }
      case WedgeContact::slip: {
        if (law_ == WedgeLaw::article) {
          event(WedgeEventKind::sign_change);
          enter({WedgeContact::slip, sign_of(driving(t, y))});  // F has just taken this sign
          return;
        }
        y.v = 0.0;
        const Phase next = contact_phase(t, y);
        event(next.contact == WedgeContact::stick ? WedgeEventKind::stop : WedgeEventKind::reversal);
        enter(next);
        return;
      }
      case WedgeContact::flight: {
        // A plastic landing: the surface stops the fall (normal impulse m·|dd|), and friction's
        // impulse, at most μ times that, acts along the surface (Coulomb's law for impacts).
        const double fall = -y.dd, before = 0.5 * m * (y.v * y.v + y.dd * y.dd);
        if (law_ == WedgeLaw::coulomb) {
          // Sliding through the impact, only kinetic friction acts: it stops the block if its
          // impulse, μk times the landing's, is enough.
          if (std::abs(y.v) <= drive_.mu_k * fall) y.v = 0.0;
          else y.v -= sign_of(y.v) * drive_.mu_k * fall;
        } else {
          y.v -= sign_of(driving(t, y)) * drive_.mu_k * fall;
        }
        y.d = 0.0, y.dd = 0.0;
        work_landings += 0.5 * m * y.v * y.v - before;
        event(WedgeEventKind::landing);
        if (pressing(t, y) <= 0.0) {
          enter({WedgeContact::flight, 1.0});  // lands as the wedge falls away again: flies on
        } else {
          enter(contact_phase(t, y));
        }
        return;
      }
    }
  }

  WedgeDrive drive_;
  WedgeLaw law_;
  mutable DriveAt at_;  // the drive at the last time asked
};

}  // namespace

WedgeRun solve_wedge(const WedgeDrive& drive, WedgeLaw law, double t_end, double sample_step, double max_step) {
  using namespace validation;
  const char* where = "the wedge";
  require_positive(where, "mass", drive.mass);
  require_finite(where, "theta0", drive.theta0);
  if (std::abs(drive.theta0) >= 1.5) reject(where, "theta0", "strictly between -1.5 and 1.5 rad", drive.theta0);
  require_non_negative(where, "omega", drive.omega);
  require_finite(where, "a_x", drive.a_x);
  require_non_negative(where, "a_x_omega", drive.a_x_omega);
  for (const auto& [coefficient, mu] : {std::pair{&static_coefficient, drive.mu_s}, std::pair{&kinetic_coefficient, drive.mu_k}}) {
    // The physics' own limit, as check_pair holds every pair to.
    if (!in_range(mu, 0.0, coefficient->largest, false)) {
      std::ostringstream range;
      range << "0 to " << coefficient->largest;
      reject(where, coefficient->name, range.str(), mu);
    }
  }
  require_positive(where, "g", drive.g);
  require_non_negative(where, "centre_height", drive.centre_height);
  require_finite(where, "start", drive.start);
  require_finite(where, "start_speed", drive.start_speed);
  require_non_negative(where, "t_end", t_end);
  require_positive(where, "sample_step", sample_step);
  require_positive(where, "max_step", max_step);
  if (t_end / sample_step > max_samples) {
    std::ostringstream range;
    range << ">= t_end / 2e6 = " << t_end / max_samples << " s (at most 2e6 samples)";
    reject(where, "sample_step", range.str(), sample_step);
  }
  return Solver(drive, law).run(t_end, sample_step, max_step);
}

WedgeStepped step_as_the_world(const WedgeDrive& drive, const WedgeRun& run, double world_step) {
  validation::require_positive("the wedge stepped as the world", "world_step", world_step);
  const Solver solver(drive, WedgeLaw::coulomb);
  const double h = world_step, m = drive.mass, mu_k = drive.mu_k;
  const double limit = std::max(drive.mu_s, drive.mu_k);
  const long steps_a_sample = std::max(1L, std::lround(run.sample_step / h));
  WedgeStepped stepped;
  if (run.samples.empty()) return stepped;
  stepped.slide.push_back(0.0);
  stepped.speed.push_back(0.0);
  Vector y;  // the slide and its speed; in contact, so no height
  long n = 0;
  std::optional<double> held_margin;  // the demand past the limit in the step last held (N), if it was
  for (std::size_t j = 1; j < run.samples.size(); ++j) {
    if (run.samples[j].contact == WedgeContact::flight || run.samples[j - 1].contact == WedgeContact::flight) break;
    for (long i = 0; i < steps_a_sample; ++i, ++n) {
      const double t = static_cast<double>(n) * h;
      const Solver::Forces f = solver.forces(t, y);
      // No kick of the plank's in the first step: it moves at the block's own velocity.
      const double drive_along = n == 0 ? f.driving - m * f.drive.acceleration * f.drive.cos_theta : f.driving;
      const double normal = std::max(0.0, f.pressing);
      const double margin = std::abs(drive_along) - limit * normal;
      if (run.samples[j].contact == WedgeContact::stick) {
        y.v = 0.0;
        held_margin = margin;
      } else if (y.v == 0.0) {
        if (margin <= 0.0) {
          held_margin = margin;  // held at the start of a slip, as the world's block may be
        } else {
          // The breakaway step is held; the listener pays what it held past the limit, and
          // (μ − μk)·N for late + h/2, late from the margin's growth since the step before (its
          // guess of half a step where it knows none).
          double late = 0.5 * h;
          if (held_margin && margin > *held_margin) late = std::min(h, h * margin / (margin - *held_margin));
          y.v = sign_of(drive_along) * (margin * h + (limit - mu_k) * normal * (late + 0.5 * h)) / m;
          held_margin.reset();
        }
      } else {
        const double way = sign_of(y.v);
        double after = y.v + h * (drive_along - way * mu_k * normal) / m;
        if (after * way < 0.0) {
          if (margin <= 0.0) {
            after = 0.0;
            held_margin = margin;
          } else {
            // Stopped inside the step and sliding back for the share of it left.
            const double left = 1.0 - std::abs(y.v) / std::abs(y.v - after);
            after = h * (drive_along - sign_of(drive_along) * mu_k * normal) / m * left;
          }
        }
        y.v = after;
        y.s += h * y.v;
      }
    }
    stepped.slide.push_back(y.s);
    stepped.speed.push_back(y.v);
  }
  return stepped;
}

}  // namespace frictionlab
