#include "physics/closed_forms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "physics/friction_laws.h"
#include "physics/validation.h"

namespace frictionlab::theory {
namespace {

using validation::reject;
using validation::require_finite;
using validation::require_non_negative;
using validation::require_positive;

constexpr double infinity = std::numeric_limits<double>::infinity();

// Inclines run from flat to vertical; beyond that "down the slope" changes meaning.
void require_slope_angle(const char* where, double angle) {
  if (!(angle >= 0.0 && angle <= std::numbers::pi / 2)) reject(where, "angle", "in [0, pi/2] rad", angle);
}

void require_pair(const char* where, const FrictionPair& pair) {
  for (const PairCoefficient& coefficient : pair_coefficients) require_non_negative(where, coefficient.name, pair.*coefficient.value);
}

// Stick and slip only make sense together when sliding is no harder than starting to slide.
void require_kinetic_not_above_static(const char* where, double mu_s, double mu_k) {
  if (mu_k > mu_s) {
    std::ostringstream message;
    message << where << ": mu_k must be in [0, mu_s] = [0, " << mu_s << "], got " << mu_k;
    throw InvalidInput(message.str());
  }
}

// e^(−u) − 1 + u without the cancellation that loses every digit when u is small.
double exp_minus_one_plus(double u) {
  if (std::abs(u) > 0.1) return std::expm1(-u) + u;
  double term = u * u / 2.0, sum = 0.0;
  for (int n = 3; n < 20 && term != 0.0; ++n) {
    sum += term;
    term *= -u / n;
  }
  return sum;
}

// e^(−u) less the first n terms of its series, Σ_{k>=n} (−u)^k/k!: summed as a series for
// small u, where subtracting the terms from e^(−u) would cancel every digit.
double exp_series_tail(double u, int n) {
  double term = 1.0;  // (−u)^k / k!
  if (std::abs(u) > 1.0) {
    double tail = std::exp(-u);
    for (int k = 0; k < n; ++k, term *= -u / k) tail -= term;
    return tail;
  }
  for (int k = 1; k <= n; ++k) term *= -u / k;
  double tail = 0.0;
  for (int k = n; k < n + 30 && term != 0.0; ++k) {
    tail += term;
    term *= -u / (k + 1);
  }
  return tail;
}

}  // namespace

double sticking_angle(double mu_s) {
  require_non_negative("sticking_angle", "mu_s", mu_s);
  return std::atan(mu_s);
}

double incline_sliding_acceleration(double angle, double mu_k, double g) {
  require_slope_angle("incline_sliding_acceleration", angle);
  require_non_negative("incline_sliding_acceleration", "mu_k", mu_k);
  require_positive("incline_sliding_acceleration", "g", g);
  return g * (std::sin(angle) - mu_k * std::cos(angle));
}

namespace {
struct InclineMotion {
  double speed, distance;
};

InclineMotion incline_motion(const char* where, double angle, double mu_k, double c, double b, double mass, double g,
                             double t) {
  require_slope_angle(where, angle);
  require_non_negative(where, "mu_k", mu_k);
  require_non_negative(where, "c", c);
  require_non_negative(where, "b", b);
  require_positive(where, "mass", mass);
  require_positive(where, "g", g);
  require_non_negative(where, "t", t);
  const double a = incline_sliding_acceleration(angle, mu_k, g);
  if (a <= 0.0) return {0.0, 0.0};  // broke free, but kinetic friction holds it at once
  const double beta = b / mass;
  // Quadratic drag too (v' = a − γv − βv², a Riccati equation): v rises to the positive root
  // v1 of the right side; with v2 the negative root, D = β(v1 − v2) and E = exp(−D·t),
  //   v = v1(1 − E)/(1 − rE), r = v1/v2,   x = v1·t + ln((1 − rE)/(1 − r))/β.
  // Where βv²·t is below 1e-12 of the speed (a b far too small to matter) the formulas cancel
  // badly, and the drag-free ones below are exact to that.
  if (beta > 0.0 && beta * a * t * t > 1e-12) {
    const double gamma = c / mass;
    const double root = std::sqrt(gamma * gamma + 4.0 * beta * a);
    // Both roots written without subtracting nearly equal numbers.
    const double v1 = 2.0 * a / (gamma + root), v2 = -(gamma + root) / (2.0 * beta);
    const double r = v1 / v2, E = std::exp(-root * t);
    return {v1 * (-std::expm1(-root * t)) / (1.0 - r * E), v1 * t + std::log1p(r * -std::expm1(-root * t) / (1.0 - r)) / beta};
  }
  if (c == 0.0) return {a * t, a * t * t / 2.0};
  // Viscous drag gives a terminal speed a/γ, approached exponentially.
  const double gamma = c / mass;
  return {-(a / gamma) * std::expm1(-gamma * t), (a / (gamma * gamma)) * exp_minus_one_plus(gamma * t)};
}
}  // namespace

double incline_speed(double angle, double mu_k, double c, double mass, double g, double t) {
  return incline_motion("incline_speed", angle, mu_k, c, 0.0, mass, g, t).speed;
}

double incline_distance(double angle, double mu_k, double c, double mass, double g, double t) {
  return incline_motion("incline_distance", angle, mu_k, c, 0.0, mass, g, t).distance;
}

double incline_speed(double angle, double mu_k, double c, double b, double mass, double g, double t) {
  return incline_motion("incline_speed", angle, mu_k, c, b, mass, g, t).speed;
}

double incline_distance(double angle, double mu_k, double c, double b, double mass, double g, double t) {
  return incline_motion("incline_distance", angle, mu_k, c, b, mass, g, t).distance;
}

InclineSlide incline_slide_stepped(double angle, double mu_k, double c, double b, double mass, double g, double t,
                                   double h) {
  constexpr const char* where = "incline_slide_stepped";
  incline_motion(where, angle, mu_k, c, b, mass, g, t);  // the same checks
  require_positive(where, "h", h);
  const double a = incline_sliding_acceleration(angle, mu_k, g);
  if (a <= 0.0) return {0.0, 0.0};
  const FrictionPair drag{mu_k, mu_k, c, b};
  const double steps = std::round(t / h);
  double v = 0.0, x = 0.0;
  for (double n = 0.0; n < steps; n += 1.0) {
    const double next = damped_velocity(v, mass, h, drag) + a * h;
    // Once the speed no longer changes, the rest of the way is at that speed.
    if (next == v) return {v, x + (steps - n) * h * v};
    v = next;
    x += h * v;
  }
  return {v, x};
}

double tip_height(double width, double mu_s) {
  require_positive("tip_height", "width", width);
  require_non_negative("tip_height", "mu_s", mu_s);
  if (mu_s == 0.0) return infinity;  // frictionless: it always slides first
  return width / (2.0 * mu_s);
}

PushOutcome push_outcome(double weight, double width, double push_height, double mu_s) {
  require_positive("push_outcome", "weight", weight);
  require_positive("push_outcome", "width", width);
  require_non_negative("push_outcome", "push_height", push_height);
  require_non_negative("push_outcome", "mu_s", mu_s);
  // Moments about the front bottom edge: push·h against weight·d/2. Friction acts through that
  // edge, so it has no moment there; tipping needs no friction beyond what holds the base.
  const double tip_force = push_height > 0.0 ? weight * width / (2.0 * push_height) : infinity;
  const double slide_force = mu_s * weight;
  // Decided on the heights, not the forces, so that h == tip_height tips exactly as promised.
  const bool tips = 2.0 * mu_s * push_height >= width;
  return {tips, tips ? tip_force : slide_force};
}

StickSlip spring_stick_slip(double mass, double k, double pull_speed, double mu_s, double mu_k, double g) {
  const char* where = "spring_stick_slip";
  require_positive(where, "mass", mass);
  require_positive(where, "k", k);
  require_positive(where, "pull_speed", pull_speed);
  require_non_negative(where, "mu_s", mu_s);
  require_non_negative(where, "mu_k", mu_k);
  require_kinetic_not_above_static(where, mu_s, mu_k);
  require_positive(where, "g", g);
  const double weight = mass * g;
  const double omega = std::sqrt(k / mass);
  // While slipping, the stretch oscillates about its kinetic balance μk·m·g/k, starting Δ above
  // it and moving at pull_speed; the block stops half a swing later, Δ below it.
  const double delta = (mu_s - mu_k) * weight / k;
  StickSlip result{};
  result.breakaway_force = mu_s * weight;
  result.restick_force = (2.0 * mu_k - mu_s) * weight;
  result.stick_duration = 2.0 * delta / pull_speed;
  result.slip_duration = (std::numbers::pi + 2.0 * std::atan2(pull_speed, omega * delta)) / omega;
  result.period = result.stick_duration + result.slip_duration;
  result.first_breakaway_time = mu_s * weight / (k * pull_speed);
  // Each cycle ends as it began, so the block keeps pace with the far end of the spring.
  result.slip_distance = pull_speed * result.period;
  return result;
}

SlideToRest slide_to_rest(double v0, double mass, const FrictionPair& pair, double g) {
  const char* where = "slide_to_rest";
  require_finite(where, "v0", v0);
  require_positive(where, "mass", mass);
  require_pair(where, pair);
  require_positive(where, "g", g);
  const double speed = std::abs(v0);
  if (speed == 0.0) return {0.0, 0.0};
  // Deceleration a + γv + βv²: time is ∫dv/Q, distance ∫v dv/Q over [0, v0].
  const double a = pair.mu_k * g, gamma = pair.c / mass, beta = pair.b / mass;
  if (a == 0.0) {
    // Drag alone never quite stops it; linear drag still stops it within a finite distance.
    if (gamma == 0.0) return {infinity, infinity};
    if (beta == 0.0) return {infinity, speed / gamma};
    return {infinity, std::log1p(beta * speed / gamma) / beta};
  }
  const double discriminant = gamma * gamma - 4.0 * a * beta;
  const double q = std::sqrt(std::abs(discriminant));
  // Distance from 0 to the nearest root of Q, the radius of convergence of 1/Q's power series.
  double nearest_root = infinity;
  if (beta == 0.0 && gamma > 0.0) nearest_root = a / gamma;
  if (beta > 0.0) nearest_root = discriminant < 0.0 ? std::sqrt(a / beta) : 2.0 * a / (gamma + q);

  if (speed <= 0.25 * nearest_root) {
    // Slow launches (and pure Coulomb): the closed forms below subtract nearly equal logarithms,
    // so sum the power series of 1/Q instead. term_n = coef_n·v0^n with
    // coef_n = −(γ coef_{n−1} + β coef_{n−2})/a; scaling by v0^n keeps every term finite.
    double older = 0.0, term = 1.0 / a, time = 0.0, distance = 0.0;
    for (int n = 0; n < 100; ++n) {
      time += term * speed / (n + 1);
      distance += term * speed * speed / (n + 2);
      const double next = -(gamma * speed * term + beta * speed * speed * older) / a;
      older = term;
      term = next;
      if (std::abs(term) + std::abs(older) < 1e-20 / a) break;
    }
    return {time, distance};
  }
  if (beta == 0.0) {
    const double growth = std::log1p(gamma * speed / a);
    return {growth / gamma, speed / gamma - a / (gamma * gamma) * growth};
  }
  double time = 0.0;
  if (discriminant < 0.0) {
    // The arctangent difference folded into one arctangent, which stays accurate as q → 0.
    time = (2.0 / q) * std::atan(speed * q / (2.0 * a + gamma * speed));
  } else if (discriminant == 0.0) {
    time = 2.0 * speed / (gamma * speed + 2.0 * a);
  } else {
    const double top = 2.0 * beta * speed + gamma;
    time = std::log1p(q * speed * (gamma + q) / (a * (top + q))) / q;
  }
  if (discriminant > 0.0 && q >= gamma / 2.0) {
    // Well-separated real roots −p and −r: partial fractions, each term of modest size.
    const double p = 2.0 * a / (gamma + q), r = (gamma + q) / (2.0 * beta);
    return {time, (r * std::log1p(speed / r) - p * std::log1p(speed / p)) / q};
  }
  return {time, (std::log1p((gamma * speed + beta * speed * speed) / a) - gamma * time) / (2.0 * beta)};
}

DiskOnIncline disk_on_incline(double angle, double mass, double radius, double inertia, double mu_s, double mu_k,
                              double g) {
  const char* where = "disk_on_incline";
  require_slope_angle(where, angle);
  require_positive(where, "mass", mass);
  require_positive(where, "radius", radius);
  require_positive(where, "inertia", inertia);
  require_non_negative(where, "mu_s", mu_s);
  require_non_negative(where, "mu_k", mu_k);
  require_positive(where, "g", g);
  // κ = I/(mR²): how much of the weight's pull goes into spinning the body up when it rolls.
  const double kappa = inertia / (mass * radius * radius);
  const double normal_force = mass * g * std::cos(angle);
  const double rolling_acceleration = g * std::sin(angle) / (1.0 + kappa);
  const double rolling_friction = kappa * mass * rolling_acceleration;
  // The grip holds up to max(μs, μk)·N, the rule the simulation's contacts follow: with μk above
  // μs a contact pushed past μs·N but not μk·N would be stopped slipping at once by the larger
  // kinetic friction, so it holds. Past that it slips, against μk·N.
  if (rolling_friction <= std::max(mu_s, mu_k) * normal_force) {
    return {true, rolling_acceleration, rolling_acceleration / radius, rolling_friction};
  }
  const double friction = mu_k * normal_force;
  return {false, g * std::sin(angle) - friction / mass, friction * radius / inertia, friction};
}

RollStart disk_starts_rolling(double v0, double mass, double radius, double inertia, double mu_k, double g) {
  const char* where = "disk_starts_rolling";
  require_finite(where, "v0", v0);
  require_positive(where, "mass", mass);
  require_positive(where, "radius", radius);
  require_positive(where, "inertia", inertia);
  require_non_negative(where, "mu_k", mu_k);
  require_positive(where, "g", g);
  const double speed0 = std::abs(v0);
  const double kappa = inertia / (mass * radius * radius);
  // The contact point's slip speed v − ωR falls at μk g (1 + 1/κ); the same friction removes
  // the fraction κ/(1+κ) of the launch speed by the time it reaches zero.
  const double final_speed = speed0 / (1.0 + kappa);
  if (speed0 == 0.0) return {0.0, 0.0, 0.0};
  if (mu_k == 0.0) return {infinity, speed0, infinity};
  const double deceleration = mu_k * g;
  const double time = speed0 / (deceleration * (1.0 + 1.0 / kappa));
  return {time, final_speed, speed0 * time - deceleration * time * time / 2.0};
}

StackedBlocks stacked_blocks(double top_mass, double bottom_mass, const FrictionPair& between,
                             const FrictionPair& ground, double push, double g) {
  const char* where = "stacked_blocks";
  require_positive(where, "top_mass", top_mass);
  require_positive(where, "bottom_mass", bottom_mass);
  require_pair(where, between);
  require_pair(where, ground);
  require_kinetic_not_above_static("stacked_blocks (between)", between.mu_s, between.mu_k);
  require_kinetic_not_above_static("stacked_blocks (ground)", ground.mu_s, ground.mu_k);
  require_finite(where, "push", push);
  require_positive(where, "g", g);
  const double total_mass = top_mass + bottom_mass;
  const double force = std::abs(push), direction = push < 0.0 ? -1.0 : 1.0;
  // Together, the top block needs friction m_top·a from the bottom one; it can have μs_between·m_top·g.
  const double max_push_together = (between.mu_s + ground.mu_k) * total_mass * g;
  if (force <= ground.mu_s * total_mass * g) return {StackRegime::at_rest, 0.0, 0.0, max_push_together};
  if (force <= max_push_together) {
    const double a = force / total_mass - ground.mu_k * g;
    return {StackRegime::together, direction * a, direction * a, max_push_together};
  }
  const double top_a = between.mu_k * g;
  const double bottom_a = (force - between.mu_k * top_mass * g - ground.mu_k * total_mass * g) / bottom_mass;
  return {StackRegime::top_slips, direction * top_a, direction * bottom_a, max_push_together};
}

ConnectedMasses connected_masses(double block_mass, double hanging_mass, double mu_s, double mu_k, double g) {
  const char* where = "connected_masses";
  require_positive(where, "block_mass", block_mass);
  require_positive(where, "hanging_mass", hanging_mass);
  require_non_negative(where, "mu_s", mu_s);
  require_non_negative(where, "mu_k", mu_k);
  require_positive(where, "g", g);
  ConnectedMasses result{};
  result.heaviest_held = std::max(mu_s, mu_k) * block_mass;
  if (hanging_mass <= result.heaviest_held) {
    // Held: friction answers the rope, which holds the weight up.
    result.tension = hanging_mass * g;
    result.friction = result.tension;
    return result;
  }
  result.slides = true;
  result.acceleration = g * (hanging_mass - mu_k * block_mass) / (block_mass + hanging_mass);
  result.tension = hanging_mass * (g - result.acceleration);
  result.friction = mu_k * block_mass * g;
  return result;
}

IntermittentSlide intermittent_slide(double mass, double pull, const FrictionPair& dry, const FrictionPair& lubricated,
                                     double from, double until, double t, double g) {
  const char* where = "intermittent_slide";
  require_positive(where, "mass", mass);
  require_non_negative(where, "pull", pull);
  require_pair(where, dry);
  require_pair(where, lubricated);
  require_non_negative(where, "from", from);
  if (!(until >= from)) reject(where, "until", "at or after from", until);
  require_non_negative(where, "t", t);
  require_positive(where, "g", g);
  const double weight = mass * g;
  // The three stretches, each [start, end) with its coefficients.
  const struct {
    double start, end;
    const FrictionPair* pair;
  } stretches[] = {{0.0, from, &dry}, {from, until, &lubricated}, {until, infinity, &dry}};
  IntermittentSlide state{false, 0.0, 0.0, 0.0};
  for (const auto& stretch : stretches) {
    if (stretch.end <= stretch.start || t < stretch.start) continue;
    const double stop_at = std::min(t, stretch.end);
    const double starts_past = std::max(stretch.pair->mu_s, stretch.pair->mu_k) * weight;
    const double a = (pull - stretch.pair->mu_k * weight) / mass;
    if (state.speed == 0.0 && pull <= starts_past) {
      state = {false, 0.0, 0.0, state.distance};
      continue;  // held all through this stretch
    }
    // Sliding (or starting): at a, until the speed reaches 0 if a < 0.
    const double run = stop_at - stretch.start;
    if (a < 0.0 && state.speed + a * run <= 0.0) {
      const double to_stop = -state.speed / a;
      state.distance += state.speed * to_stop + 0.5 * a * to_stop * to_stop;
      state.speed = 0.0;
      // At rest again: the pull cannot beat max(mu_s, mu_k)·N here, since it lost to mu_k·N.
      state.sliding = false;
      state.acceleration = 0.0;
      continue;
    }
    state.distance += state.speed * run + 0.5 * a * run * run;
    state.speed += a * run;
    state.sliding = true;
    state.acceleration = a;
  }
  return state;
}

DrivenWheel driven_wheel(double mass, double radius, double inertia, double torque, double mu_s, double mu_k, double g) {
  const char* where = "driven_wheel";
  require_positive(where, "mass", mass);
  require_positive(where, "radius", radius);
  require_non_negative(where, "inertia", inertia);
  require_non_negative(where, "torque", torque);
  require_non_negative(where, "mu_s", mu_s);
  require_non_negative(where, "mu_k", mu_k);
  require_positive(where, "g", g);
  DrivenWheel wheel{};
  const double rolling_inertia = inertia + mass * radius * radius;  // about the contact point
  wheel.traction_limit = std::max(mu_s, mu_k) * g * rolling_inertia / radius;
  if (torque <= wheel.traction_limit) {
    wheel.rolls = true;
    wheel.acceleration = torque * radius / rolling_inertia;
    wheel.angular_acceleration = wheel.acceleration / radius;
    wheel.friction = mass * wheel.acceleration;
    return wheel;
  }
  if (inertia == 0.0) reject(where, "inertia", "more than 0 when the torque passes the traction limit", inertia);
  wheel.friction = mu_k * mass * g;
  wheel.acceleration = mu_k * g;
  wheel.angular_acceleration = (torque - wheel.friction * radius) / inertia;
  return wheel;
}

GrowingPush growing_push(double mass, double rate, const FrictionPair& pair, double g, double t) {
  const char* where = "growing_push";
  require_positive(where, "mass", mass);
  require_positive(where, "rate", rate);
  require_pair(where, pair);
  require_positive(where, "g", g);
  require_non_negative(where, "t", t);
  GrowingPush push{};
  push.breakaway_push = std::max(pair.mu_s, pair.mu_k) * mass * g;
  push.breakaway_time = push.breakaway_push / rate;
  push.push = rate * t;
  if (t <= push.breakaway_time) {
    push.friction = push.push;
    return push;
  }
  // Sliding from v = 0 at t_b: m·v' = R·τ + D − c·v − b·v², with τ = t − t_b and D the push's
  // excess over kinetic friction at breakaway, (max(mu_s, mu_k) − mu_k)·m·g >= 0.
  const double tau = t - push.breakaway_time, kinetic = pair.mu_k * mass * g;
  const double excess = push.breakaway_push - kinetic;
  const double ramp = rate / mass, offset = excess / mass, gamma = pair.c / mass, beta = pair.b / mass;
  if (beta == 0.0 && gamma == 0.0) {
    push.speed = ramp * tau * tau / 2.0 + offset * tau;
    push.distance = ramp * tau * tau * tau / 6.0 + offset * tau * tau / 2.0;
  } else if (beta == 0.0) {
    // v = (D/c)·(1 − e^(−u)) + (R/c²)·(e^(−u) − 1 + u) with u = γτ, and its integral; the tails
    // of e^(−u)'s series keep every digit when c is small.
    const double u = gamma * tau;
    push.speed = -offset * exp_series_tail(u, 1) / gamma + ramp * exp_series_tail(u, 2) / (gamma * gamma);
    push.distance = offset * exp_series_tail(u, 2) / (gamma * gamma) - ramp * exp_series_tail(u, 3) / (gamma * gamma * gamma);
  } else {
    // 0.1 ms, or more for a very long slide, so that no call takes more than 200 000 steps: a
    // script cannot stop C++ code, so it must not be able to ask for a run without end.
    const double step = std::max(1e-4, tau / 200000.0);
    const auto acceleration = [&](double s, double v) { return ramp * s + offset - gamma * v - beta * v * std::abs(v); };
    double s = 0.0, x = 0.0, v = 0.0;
    while (s < tau) {
      const double h = std::min(step, tau - s);
      const double k1v = acceleration(s, v), k1x = v;
      const double k2v = acceleration(s + h / 2, v + h / 2 * k1v), k2x = v + h / 2 * k1v;
      const double k3v = acceleration(s + h / 2, v + h / 2 * k2v), k3x = v + h / 2 * k2v;
      const double k4v = acceleration(s + h, v + h * k3v), k4x = v + h * k3v;
      x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      s += h;
    }
    push.speed = v;
    push.distance = x;
  }
  push.friction = kinetic + pair.c * push.speed + pair.b * push.speed * push.speed;
  push.acceleration = (push.push - push.friction) / mass;
  return push;
}

BoxLanding box_landing(double width, double height, double centre_height, double angle, double omega, double g,
                       double clearance) {
  const char* where = "box_landing";
  require_positive(where, "width", width);
  require_positive(where, "height", height);
  require_finite(where, "angle", angle);
  require_finite(where, "omega", omega);
  require_positive(where, "g", g);
  require_non_negative(where, "clearance", clearance);
  // The lowest corner's height above the floor at t, and which corner it is.
  const auto lowest = [&](double t, double* cx, double* cy) {
    const double turned = angle + omega * t, c = std::cos(turned), s = std::sin(turned);
    double low = std::numeric_limits<double>::infinity();
    for (const double sx : {-0.5, 0.5}) {
      for (const double sy : {-0.5, 0.5}) {
        const double x = sx * width * c - sy * height * s, y = sx * width * s + sy * height * c;
        if (y < low) {
          low = y;
          if (cx != nullptr) *cx = x, *cy = y;
        }
      }
    }
    return centre_height - 0.5 * g * t * t + low - clearance;
  };
  if (lowest(0.0, nullptr, nullptr) <= 0.0) reject(where, "centre_height", "high enough that no corner starts touching", centre_height);
  constexpr double step = 1e-4;
  double before = 0.0;
  while (lowest(before + step, nullptr, nullptr) > 0.0) before += step;
  double after = before + step;
  for (int i = 0; i < 60; ++i) {
    const double middle = 0.5 * (before + after);
    (lowest(middle, nullptr, nullptr) > 0.0 ? before : after) = middle;
  }
  BoxLanding landing{after, angle + omega * after, 0.0, 0.0, false};
  lowest(after, &landing.corner_x, &landing.corner_y);
  // The next corner along the bottom: the one at the other end of the face that is lowest.
  const double c = std::cos(landing.angle), s = std::sin(landing.angle);
  const double rise = std::min(std::abs(width * s), std::abs(height * c));
  landing.flat = rise < 1e-3;
  return landing;
}

CornerImpact corner_impact(double mass, double inertia, double rx, double ry, double vx, double vy, double omega,
                           double mu, double restitution) {
  const char* where = "corner_impact";
  require_positive(where, "mass", mass);
  require_positive(where, "inertia", inertia);
  require_non_negative(where, "mu", mu);
  if (!(restitution >= 0.0 && restitution <= 1.0)) reject(where, "restitution", "in [0, 1]", restitution);
  // The point's velocity, and how an impulse (J_t, J_n) at it changes that velocity: Δu = K·J.
  const double ux = vx - omega * ry, uy = vy + omega * rx;
  if (!(uy < 0.0)) reject(where, "the point's vertical speed", "< 0 (moving into the floor)", uy);
  const double k_tt = 1.0 / mass + ry * ry / inertia, k_nn = 1.0 / mass + rx * rx / inertia, k_tn = -rx * ry / inertia;
  CornerImpact impact{};
  // Grips: after the impact the point does not slide, and bounces back at −e·uy.
  const double want_t = -ux, want_n = -(1.0 + restitution) * uy;
  const double determinant = k_tt * k_nn - k_tn * k_tn;
  double jt = (want_t * k_nn - k_tn * want_n) / determinant, jn = (k_tt * want_n - k_tn * want_t) / determinant;
  impact.grips = jn >= 0.0 && std::abs(jt) <= mu * jn;
  if (!impact.grips) {
    // Slides: kinetic friction against the point's sliding just after the impact (what a solver
    // that clamps friction at mu·J_n settles on), the normal impulse what stops the fall. Of the
    // two directions, the one whose sliding after the impact agrees with it.
    for (const double direction : {ux > 0.0 ? 1.0 : -1.0, ux > 0.0 ? -1.0 : 1.0}) {
      jn = want_n / (k_nn - direction * mu * k_tn);
      jt = -direction * mu * jn;
      if (jn >= 0.0 && direction * (ux + k_tt * jt + k_tn * jn) >= 0.0) break;
    }
  }
  impact.normal_impulse = jn;
  impact.tangent_impulse = jt;
  impact.vx = vx + jt / mass;
  impact.vy = vy + jn / mass;
  impact.omega = omega + (rx * jn - ry * jt) / inertia;
  return impact;
}

CornerImpact solver_corner_impact(double mass, double inertia, double rx, double ry, double vx, double vy,
                                  double omega, double mu, double restitution, int iterations) {
  const char* where = "solver_corner_impact";
  require_positive(where, "mass", mass);
  require_positive(where, "inertia", inertia);
  require_non_negative(where, "mu", mu);
  if (!(restitution >= 0.0 && restitution <= 1.0)) reject(where, "restitution", "in [0, 1]", restitution);
  if (iterations < 1) reject(where, "iterations", "at least 1", iterations);
  const double k_tt = 1.0 / mass + ry * ry / inertia, k_nn = 1.0 / mass + rx * rx / inertia;
  // The normal's target: bounce back at e times the speed it comes in with, as corner_impact has it.
  const double bounce = restitution * std::min(vy + omega * rx, 0.0);
  double jt = 0.0, jn = 0.0;
  const auto apply = [&](double dt, double dn) {
    vx += dt / mass;
    vy += dn / mass;
    omega += (rx * dn - ry * dt) / inertia;
  };
  for (int turn = 0; turn < iterations; ++turn) {
    // Non-penetration matters more than friction, so Box2D solves friction first, within the
    // normal impulse of the turn before.
    const double limit = mu * jn;
    const double wanted_t = std::clamp(jt - (vx - omega * ry) / k_tt, -limit, limit);
    apply(wanted_t - jt, 0.0);
    jt = wanted_t;
    const double wanted_n = std::max(jn - (vy + omega * rx + bounce) / k_nn, 0.0);
    apply(0.0, wanted_n - jn);
    jn = wanted_n;
  }
  return {std::abs(jt) < mu * jn, jn, jt, vx, vy, omega};
}

SlopeLaunch slope_launch(double v0, double angle, double mu_s, double mu_k, double g) {
  const char* where = "slope_launch";
  require_non_negative(where, "v0", v0);
  require_slope_angle(where, angle);
  require_non_negative(where, "mu_s", mu_s);
  require_non_negative(where, "mu_k", mu_k);
  require_positive(where, "g", g);
  const double deceleration = g * (std::sin(angle) + mu_k * std::cos(angle));
  if (deceleration <= 0.0) return {infinity, infinity, true};  // flat and frictionless: it never stops
  // It stays while static friction can hold it: up to max(mu_s, mu_k)·N, as the listener holds
  // (with mu_k above mu_s, a block just pushed past mu_s·N would at once be held back by mu_k·N).
  return {v0 * v0 / (2.0 * deceleration), v0 / deceleration, std::tan(angle) <= std::max(mu_s, mu_k)};
}

VelocityHack velocity_hack(double v0, double keep, double h, double angle, double g, int substeps) {
  const char* where = "velocity_hack";
  require_non_negative(where, "v0", v0);
  if (!(keep >= 0.0 && keep < 1.0)) reject(where, "keep", "in [0, 1)", keep);
  require_positive(where, "h", h);
  require_slope_angle(where, angle);
  require_positive(where, "g", g);
  if (!(substeps >= 1 && substeps <= 1000)) reject(where, "substeps", "in [1, 1000]", substeps);
  const double n = substeps;
  const double pull = g * std::sin(angle) * h;  // speed gravity takes away in a frame
  // Frame k starts at u_k. Its n sub-steps each take pull/n off the speed and then move the
  // body by h/n times the new speed: h·(u_k − lag·pull) in all, lag = (n + 1)/(2n). Then the
  // cut: u_(k+1) = keep·(u_k − pull), which tends to u* = −keep·pull/(1 − keep), as
  // u* + (u_0 − u*)·keep^k. The first frame starts from the velocity half a sub-step back (the
  // scene's leapfrog start, v(−h/2) = v0 − (h/2)·a with a = −g·sin θ): u_0 = v0 + pull/(2n).
  const double lag = (n + 1.0) / (2.0 * n), drift = -keep * pull / (1.0 - keep);
  const double start = v0 + pull / (2.0 * n);
  if (pull == 0.0) return {h * v0 / (1.0 - keep), 0.0};
  // Frames move it up while u_k > lag·pull; sum those moves in closed form (a geometric series).
  const double excess = start - drift, threshold = lag * pull - drift;  // u_k − u* = excess·keep^k
  if (excess <= threshold) return {0.0, drift};
  if (keep == 0.0) return {h * (start - lag * pull), drift};  // one frame up, then only down
  const double frames = std::floor(std::log(threshold / excess) / std::log(keep)) + 1.0;  // k with u_k > lag·pull
  const double geometric = (1.0 - std::pow(keep, frames)) / (1.0 - keep);
  return {h * (excess * geometric + frames * (drift - lag * pull)), drift};
}

}  // namespace frictionlab::theory
