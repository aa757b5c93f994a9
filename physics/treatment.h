// The friction treatments: how the dry (Coulomb) part of friction is realised at a contact.
// Each lives in its own file (treatment_stick_slip.cpp, treatment_threshold.cpp,
// treatment_regularized.cpp, treatment_box2d.cpp); the listener looks one up once per contact
// and step and calls it, so nothing else switches on the treatment.
#pragma once

#include <string_view>

#include "physics/friction_laws.h"
#include "physics/materials.h"

namespace frictionlab {

struct ContactRecord;

// A slipping contact is declared stopped when the solved friction falls this far below
// mu_k·N: the final normal impulse differs from the one each iteration clamped against by
// about 1e-4 of it, and a stop declared on that noise would stick a block for a step mid-slide.
constexpr double stop_tolerance = 1e-3;

// What the solver did at one contact, summed over its manifold points.
struct SolvedContact {
  double normal_impulse = 0.0;   // N·s on B
  double tangent_impulse = 0.0;  // N·s on B along the tangent
  float sliding_end = 0.0f;      // m/s, B relative to A along the tangent, after the solve
  float step = 0.0f;             // s
  // The same over the contact's group, every touching contact between the two bodies through
  // the same pair (a body on feet has one a foot), when the rule judges groups; the contact's
  // own otherwise and when it is the only one. The group's sliding is the mean over its points
  // weighted by their normal impulses, along this contact's tangent.
  double group_normal_impulse = 0.0;
  double group_tangent_impulse = 0.0;
  float group_sliding_end = 0.0f;
};

// One treatment's three moments in a step. Plain functions, no state of their own: the state
// a treatment keeps between steps lives in the contact's record.
struct TreatmentRule {
  FrictionTreatment treatment;
  // Before the solve: the coefficient Box2D's solver clamps the tangential impulse with, given
  // the mean sliding speed at the start of the step; may set the record's state. record.listener.fresh is
  // true at the contact's first solve. epsilon is the threshold speed, m/s.
  float (*solver_coefficient)(ContactRecord& record, const FrictionPair& pair, float sliding, double epsilon);
  // After the solve: the contact's state for the next step, from the impulses it took.
  void (*after_solve)(ContactRecord& record, const FrictionPair& pair, const SolvedContact& solved);
  // The dry friction this treatment applies itself, as an explicit force before the step
  // (N, on B along the tangent), or null when the solver's impulse is the dry friction.
  double (*explicit_dry_force)(double sliding, double normal_force, const FrictionPair& pair, double epsilon);
  // Whether a group of contacts between the same two bodies keeps one state. If so, the listener
  // calls after_solve once a step per group, on its first contact in the moving body's contact
  // list, with the group's totals, and gives the state it leaves to every contact of the group;
  // a contact joining a group takes the group's state instead of judging its own birth. If not,
  // every contact is judged alone.
  bool judges_groups = false;
};

const TreatmentRule& stick_slip_rule();
const TreatmentRule& threshold_rule();
const TreatmentRule& regularized_rule();
const TreatmentRule& box2d_rule();
inline const TreatmentRule& rule_of(FrictionTreatment treatment) {
  switch (treatment) {
    case FrictionTreatment::stick_slip: return stick_slip_rule();
    case FrictionTreatment::threshold: return threshold_rule();
    case FrictionTreatment::regularized: return regularized_rule();
    case FrictionTreatment::box2d: return box2d_rule();
  }
  return stick_slip_rule();
}

}  // namespace frictionlab
