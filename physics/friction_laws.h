// Friction laws as pure functions of the quantities a free-body diagram shows.
// Sign convention: positive along the chosen axis; the returned friction force acts on the
// body, so it opposes sliding (or the push that would cause it).
#pragma once

#include "physics/materials.h"

namespace frictionlab {

// -1, 0 or +1: the direction a friction force opposes.
template <typename Number>
constexpr Number sign(Number x) {
  return static_cast<Number>((x > Number(0)) - (x < Number(0)));
}

// Where a contact is on the engineering model's graph.
enum class ContactState { sticking, slipping };

struct FrictionOutcome {
  double force = 0.0;  // friction force on the body, N
  ContactState state = ContactState::sticking;
};

// The engineering model of the friction-models article, piecewise:
//   v = 0 and |F_a| <= mu_s·N : friction = -F_a (sticks)
//   v = 0 and |F_a| >  mu_s·N : friction = -mu_s·N·sign(F_a) (breaks away)
//   v != 0                    : friction = -mu_k·N·sign(v) - c·v - b·v²·sign(v)
// `applied` is the sum of every other force along the surface, `normal_force` >= 0.
// No run steps with it: the stick-slip treatment realises this law through the solver's
// impulses (treatment_stick_slip.cpp) and the exact reduced model through located events.
// It is the law a theory curve draws (friction against the applied force, its branches).
FrictionOutcome engineering_friction(double applied, double normal_force, double velocity, const FrictionPair& pair);

// The tribology article's regularized static friction: below the threshold speed epsilon the
// force grows linearly, -mu_s·N·v/epsilon; above it, kinetic -mu_k·N·sign(v). Viscous and
// quadratic terms are added on top in both regimes. epsilon must be > 0.
double regularized_friction(double velocity, double normal_force, double epsilon, const FrictionPair& pair);

// The velocity-dependent part alone, -c·v - b·v²·sign(v).
double damping_force(double velocity, const FrictionPair& pair);

// Velocity of a body of mass m moving at v after a step h under the damping terms alone:
// the exact solution of m·v' = -c·v - b·v·|v|. It never reverses the sign of v and never
// grows |v|, for any h, c, b >= 0 (an explicit step reverses v once h·c/m >= 2).
double damped_velocity(double velocity, double mass, double h, const FrictionPair& pair);

// Two rules of the stick-slip treatment (treatment_stick_slip.cpp, which says why) that a
// theory of the stepped world must follow too. A contact born sliding no faster than this
// (m/s) starts stuck, and a stuck contact is held in the solve at up to
// max(mu_s, mu_k)·(1 + stick_slip_hold_band) before the step's end judges it.
constexpr double stick_slip_birth_sliding_speed = 1e-3;
constexpr double stick_slip_hold_band = 2e-2;

}  // namespace frictionlab
