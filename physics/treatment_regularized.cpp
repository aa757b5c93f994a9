// regularized: the tribology article's approximation, F = -mu_s·N·v/epsilon below epsilon and
// -mu_k·N·sign(v) above, applied as an explicit force before the step (as a game applies it).
// The solver gets no friction at all; on a slope the contact creeps at epsilon·tanθ/mu_s, and
// past h > 2·epsilon/(mu_s·g·cosθ) the steep line overshoots and jitters.
#include <cmath>

#include "physics/friction_listener.h"
#include "physics/treatment.h"

namespace frictionlab {
namespace {

float solver_coefficient(ContactRecord& r, const FrictionPair&, float sliding, double epsilon) {
  r.friction.state = std::abs(sliding) < epsilon ? ContactState::sticking : ContactState::slipping;
  return 0.0f;
}

void after_solve(ContactRecord&, const FrictionPair&, const SolvedContact&) {}

double dry_force(double sliding, double normal_force, const FrictionPair& pair, double epsilon) {
  const FrictionPair dry{pair.mu_s, pair.mu_k, 0.0, 0.0};  // c and b are applied implicitly apart
  return regularized_friction(sliding, normal_force, epsilon, dry);
}

}  // namespace

const TreatmentRule& regularized_rule() {
  static const TreatmentRule rule{FrictionTreatment::regularized, solver_coefficient, after_solve, dry_force, false};
  return rule;
}

}  // namespace frictionlab
