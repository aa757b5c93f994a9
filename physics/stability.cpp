#include "physics/stability.h"

#include <algorithm>
#include <cmath>

#include "physics/friction_laws.h"

namespace frictionlab {
namespace {

constexpr double launch_speed = 1.0;  // m/s

// The amplification of one step on v' = −λ·v, as a function of z = h·λ.
double amplification(Integrator integrator, double z) {
  switch (integrator) {
    case Integrator::explicit_euler:
    case Integrator::semi_implicit_euler: return 1.0 - z;
    case Integrator::rk4: return 1.0 - z + z * z / 2.0 - z * z * z / 6.0 + z * z * z * z / 24.0;
  }
  return 1.0;
}

double largest(const std::vector<double>& values, std::size_t from, std::size_t to) {
  double most = 0.0;
  for (std::size_t i = from; i < to; ++i) {
    if (!std::isfinite(values[i])) return INFINITY;
    most = std::max(most, std::abs(values[i]));
  }
  return most;
}

}  // namespace

std::string_view behaviour_name(Behaviour behaviour) {
  switch (behaviour) {
    case Behaviour::stable: return "stable";
    case Behaviour::chattering: return "chattering";
    case Behaviour::divergent: return "divergent";
  }
  return "?";
}

Behaviour classify_velocities(const std::vector<double>& velocities) {
  // Judged by the amplitude of the last eighth against the eighth before it: halving is stable
  // (even flipping sign, as a heavily damped explicit step does), holding is chatter, growing
  // past a hundred times where it started is divergence. The halving puts the measured
  // boundary just inside theory's: |1 − z|^50 = ½ is z = 1.986 for Euler, 0.993 of 2. (A
  // stricter rule mistakes RK4's uneven chatter for settling.)
  const std::size_t n = velocities.size();
  const std::size_t window = std::max<std::size_t>(10, n / 8);
  if (n < 2 * window) return Behaviour::stable;
  const double start = std::max(largest(velocities, 0, window), 1e-300);
  const double tail = largest(velocities, n - window, n);
  const double before = largest(velocities, n - 2 * window, n - window);
  if (!std::isfinite(tail) || tail > 100.0 * start) return Behaviour::divergent;
  if (tail <= 1e-12 * start || tail < 0.5 * before) return Behaviour::stable;
  return Behaviour::chattering;
}

Behaviour classify_regularized(const FrictionPair& pair, double gravity, double h, double epsilon,
                               Integrator integrator) {
  OneDofBlock block;
  block.mass = 1.0;
  block.normal_force = gravity;
  block.pair = pair;
  block.v0 = launch_speed;
  // Long enough to brake to the threshold, then twenty time constants of the linear part.
  const double braking = launch_speed / (std::max(pair.mu_k, 1e-3) * gravity);
  const double time_constant = epsilon / (pair.mu_s * gravity);
  const double linear_steps = std::max(400.0, 20.0 * time_constant / h);
  const double duration = h * (std::ceil(braking / h) + std::ceil(linear_steps));
  const std::vector<Sample> samples = integrate_regularized(block, duration, h, epsilon, integrator);
  // The last (shortened) step would judge a different h.
  std::vector<double> velocities;
  velocities.reserve(samples.size());
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) velocities.push_back(samples[i].v);
  // Only the part after braking says whether the method settles.
  const auto braked = static_cast<std::size_t>(std::ceil(braking / h));
  return classify_velocities(std::vector<double>(velocities.begin() + static_cast<std::ptrdiff_t>(std::min(braked, velocities.size())),
                                                 velocities.end()));
}

double theoretical_boundary(const FrictionPair& pair, double gravity, double epsilon, Integrator integrator) {
  // The largest z = h·λ with |amplification| <= 1, by bisection (z = 2 for Euler).
  double low = 0.5, high = 4.0;
  for (int i = 0; i < 200; ++i) {
    const double middle = 0.5 * (low + high);
    (std::abs(amplification(integrator, middle)) <= 1.0 ? low : high) = middle;
  }
  return low * epsilon / (pair.mu_s * gravity);
}

double measured_boundary(const FrictionPair& pair, double gravity, double epsilon, Integrator integrator) {
  const double guess = theoretical_boundary(pair, gravity, epsilon, integrator);
  double low = 0.25 * guess, high = 4.0 * guess;
  while (high / low > 1.0 + 1e-4) {
    const double middle = std::sqrt(low * high);
    (classify_regularized(pair, gravity, middle, epsilon, integrator) == Behaviour::stable ? low : high) = middle;
  }
  return std::sqrt(low * high);
}

std::vector<double> logarithmic_range(double low, double high, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) {
    values.push_back(low * std::pow(high / low, count == 1 ? 0.0 : static_cast<double>(i) / (count - 1)));
  }
  return values;
}

std::vector<StabilityCell> stability_map(const FrictionPair& pair, double gravity, Integrator integrator,
                                         const std::vector<double>& steps, const std::vector<double>& epsilons) {
  std::vector<StabilityCell> cells;
  for (const double epsilon : epsilons) {
    for (const double h : steps) {
      cells.push_back({integrator, h, epsilon, classify_regularized(pair, gravity, h, epsilon, integrator)});
    }
  }
  return cells;
}

double theoretical_creep_speed(const FrictionPair& pair, double angle, double epsilon) {
  return epsilon * std::tan(angle) / pair.mu_s;
}

double creep_speed(const FrictionPair& pair, double gravity, double angle, double epsilon, double h,
                   Integrator integrator) {
  OneDofBlock block;
  block.mass = 1.0;
  block.normal_force = gravity * std::cos(angle);
  block.constant_force = gravity * std::sin(angle);
  block.pair = pair;
  // Thirty time constants of the linear part: the creep is reached to e^-30.
  const double time_constant = epsilon / (pair.mu_s * block.normal_force);
  const double duration = h * std::ceil(30.0 * time_constant / h + 100.0);
  return integrate_regularized(block, duration, h, epsilon, integrator).back().v;
}

std::vector<double> viscous_explicit(double ratio, int steps) {
  std::vector<double> velocities{1.0};
  for (int i = 0; i < steps; ++i) velocities.push_back(velocities.back() * (1.0 - ratio));
  return velocities;
}

std::vector<double> viscous_exact(double ratio, int steps) {
  // Mass 1 and h 1: then c is the ratio h·c/m itself.
  FrictionPair viscous;
  viscous.c = ratio;
  std::vector<double> velocities{1.0};
  for (int i = 0; i < steps; ++i) velocities.push_back(damped_velocity(velocities.back(), 1.0, 1.0, viscous));
  return velocities;
}

}  // namespace frictionlab
