// box2d: Box2D's own single coefficient (the pair's mu_k) for sticking and sliding alike; the
// state is only reported (slipping once the impulse reaches the limit), never acted on.
#include <cmath>

#include "physics/friction_listener.h"
#include "physics/treatment.h"

namespace frictionlab {
namespace {

float solver_coefficient(ContactRecord&, const FrictionPair& pair, float, double) {
  return static_cast<float>(pair.mu_k);
}

void after_solve(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  const double reached = std::abs(solved.tangent_impulse) / solved.normal_impulse;
  r.friction.state = reached >= pair.mu_k * (1.0 - stop_tolerance) ? ContactState::slipping : ContactState::sticking;
}

}  // namespace

const TreatmentRule& box2d_rule() {
  static const TreatmentRule rule{FrictionTreatment::box2d, solver_coefficient, after_solve, nullptr, false};
  return rule;
}

}  // namespace frictionlab
