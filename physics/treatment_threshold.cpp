// threshold: the velocity-threshold switch games use. mu_s while the contact slides slower
// than epsilon, mu_k faster; the state is read from the speed alone, never from the impulses.
#include <cmath>

#include "physics/friction_listener.h"
#include "physics/treatment.h"

namespace frictionlab {
namespace {

float solver_coefficient(ContactRecord& r, const FrictionPair& pair, float sliding, double epsilon) {
  const bool slow = std::abs(sliding) < epsilon;
  r.friction.state = slow ? ContactState::sticking : ContactState::slipping;
  return static_cast<float>(slow ? pair.mu_s : pair.mu_k);
}

void after_solve(ContactRecord&, const FrictionPair&, const SolvedContact&) {}

}  // namespace

const TreatmentRule& threshold_rule() {
  static const TreatmentRule rule{FrictionTreatment::threshold, solver_coefficient, after_solve, nullptr, false};
  return rule;
}

}  // namespace frictionlab
