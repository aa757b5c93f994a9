#include "physics/friction_laws.h"

#include <cmath>

namespace frictionlab {

double damping_force(double velocity, const FrictionPair& pair) {
  return -pair.c * velocity - pair.b * velocity * std::abs(velocity);
}

FrictionOutcome engineering_friction(double applied, double normal_force, double velocity, const FrictionPair& pair) {
  if (velocity != 0.0) {
    return {-pair.mu_k * normal_force * sign(velocity) + damping_force(velocity, pair), ContactState::slipping};
  }
  const double limit = pair.mu_s * normal_force;
  if (std::abs(applied) <= limit) return {-applied, ContactState::sticking};
  return {-limit * sign(applied), ContactState::slipping};
}

double regularized_friction(double velocity, double normal_force, double epsilon, const FrictionPair& pair) {
  const double dry = std::abs(velocity) < epsilon ? -pair.mu_s * normal_force * velocity / epsilon
                                                  : -pair.mu_k * normal_force * sign(velocity);
  return dry + damping_force(velocity, pair);
}

double damped_velocity(double velocity, double mass, double h, const FrictionPair& pair) {
  // The exact solution of m·v' = -c·v - b·v·|v| over h (a Bernoulli equation): it only shrinks
  // |v| and never changes its sign, whatever h, c and b are.
  const double speed = std::abs(velocity);
  const double gamma = pair.c / mass;
  const double beta = pair.b / mass;
  if (gamma == 0.0) return velocity / (1.0 + h * beta * speed);
  const double decay = std::exp(-gamma * h);
  return velocity * decay / (1.0 + beta * speed * -std::expm1(-gamma * h) / gamma);
}

}  // namespace frictionlab
