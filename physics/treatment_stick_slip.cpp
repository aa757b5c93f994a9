// stick-slip: each contact is stuck or slipping. Stuck, the solver may use up to mu_s·N; a
// contact starts slipping when the solved tangential impulse reaches that limit, and slips
// with mu_k·N until its sliding stops or reverses. Several contacts between the same two
// bodies (a body on feet) are one group with one state, judged from their totals. This is what makes the spring lesson
// converge to the exact Coulomb answer as the step shrinks (it realises the engineering
// model's piecewise law through the solver's impulses).
#include <algorithm>
#include <cmath>

#include "physics/contact_mechanics.h"
#include "physics/friction_listener.h"
#include "physics/treatment.h"

namespace frictionlab {
namespace {

// A contact born sliding faster than this starts out slipping; slower, it starts stuck and
// the solver decides at the first step. Only a contact's birth uses a speed: afterwards the
// state follows from the impulses, which is what lets the error vanish as the step shrinks.
constexpr float birth_sliding_speed = 1e-3f;

// The solver clamps each point's friction impulse against the normal impulse of its own
// iteration, and the final normal impulse differs from it by round-off and by the last
// iteration's change (about 1e-4 of it on a sliding block). Breaking away must not wait for
// more than float noise, or the breakaway comes a step late at high rates; stopping must not
// be declared on noise, or a sliding block would stick for a step in mid-slide.
constexpr double breakaway_tolerance = 1e-5;

// What a stuck group's contacts give the solver. Box2D clamps every manifold point's friction
// at the coefficient times that point's own normal impulse, a cone per point; a rigid body on
// feet has one cone for all of them, mu_s times the total load. With mu_s per point the solver
// cannot always find the split that holds the body (its eight iterations move friction from a
// saturated point to the others too slowly, and the loads of feet in a row are its own choice),
// so the body crept while it should hold and then broke away early: a block on six feet at
// mu_s = 1 at 7.2 N instead of 9.8 N. So the stuck group's points get a coefficient no load
// share reaches; the solver then holds the body wherever a rigid hold needs no more than that,
// and the group's cone is applied after the solve, from the totals (after_solve).
constexpr float group_hold_coefficient = 1e4f;

float solver_coefficient(ContactRecord& r, const FrictionPair& pair, float sliding, double) {
  if (r.fresh && std::abs(sliding) > birth_sliding_speed) {
    r.state = ContactState::slipping;
    r.slip_direction = sign(sliding);
  }
  if (r.state == ContactState::slipping) return static_cast<float>(pair.mu_k);
  return r.siblings > 0 ? group_hold_coefficient : static_cast<float>(breakaway_coefficient(pair));
}

// The step in which a contact breaks free was solved with mu_s throughout, although the
// static limit was passed somewhere inside it; from then on friction is only mu_k. Box2D's
// velocities are those of the middle of a step (x_{n+1} = x_n + h·v_{n+1/2}), so the
// kinetic friction has been acting for s = late + h/2 when the step ends, where `late` is how
// long before the step's sample time the demanded friction crossed mu_s·N. That crossing is
// found by linear interpolation between the friction that held in the previous step and the
// friction this step demanded (the limit plus the excess that set the contact sliding). The
// impulse owed is (mu_s - mu_k)·N·s. Without it the breakaway is a step late on average and
// the error is first order; with it the spring lesson converges at second order.
double breakaway_correction(const ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  const double h = solved.step;
  const double mass = contact_mass(r.body_a, r.body_b, r.point_count == 2, r.point, r.tangent());
  const double normal_force = solved.normal_impulse / h;
  const double excess = mass * std::abs(solved.sliding_end) / h;
  const double growth = (breakaway_coefficient(pair) * normal_force + excess - r.held_force) / h;
  const double late = growth > 0.0 ? std::clamp(excess / growth, 0.0, h) : 0.5 * h;
  return (breakaway_coefficient(pair) - pair.mu_k) * normal_force * (late + 0.5 * h);
}

// The same for a stuck group, whose points the solver held with group_hold_coefficient: it kept
// the body still with friction |T| that may pass the group's limit mu_s·N. A lone contact's
// solve would have stopped at the limit and left the rest as velocity; that rest, |T| - mu_s·N·h,
// is handed back, and then the kinetic friction owed since the crossing, as above, with the
// demanded friction the hold plus whatever velocity the solve left. The body's translational
// mass applies: the feet keep it level, as a face does.
double group_breakaway_correction(const ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  const double h = solved.step;
  const double mass = translational_mass(r.body_a, r.body_b);
  const double normal_force = solved.group_normal_impulse / h;
  const double limit = breakaway_coefficient(pair) * normal_force;
  const double held = std::abs(solved.group_tangent_impulse) / h;
  const double demanded = held + mass * std::abs(solved.group_sliding_end) / h;
  const double excess = std::max(demanded - limit, 0.0);
  const double growth = (demanded - r.held_force) / h;
  const double late = growth > 0.0 ? std::clamp(excess / growth, 0.0, h) : 0.5 * h;
  const double handed_back = std::max(held - limit, 0.0) * h;
  return handed_back + (breakaway_coefficient(pair) - pair.mu_k) * normal_force * (late + 0.5 * h);
}

// A slipping contact whose sliding reversed inside the step stopped somewhere in it, and from
// there on Coulomb's law says: static friction holds it if the other forces along the surface
// are within mu_s·N, or it slides back with kinetic friction the other way. The solver kept
// kinetic friction against the old direction to the step's end instead, and left the body
// moving back too fast. Left as it was, the next step's stuck solve had to undo that motion
// too: up to (mu_s + mu_k)·N more of friction than holding needs, whatever the step, so a block
// with mu_k a tenth of mu_s, stopped by a spring pushing back, broke away backwards at once.
// The other forces come from the step's own velocities: B's sliding at the start (PreSolve,
// before the forces acted) and at the end, less the friction impulse. The impulse that makes
// the step end as Coulomb's law would is owed to the body now, and the state follows the law.
void restick_correction(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  const double h = solved.step;
  const b2Vec2 t = r.tangent();
  if (r.point_count == 0 || h <= 0.0) return;
  double start = 0.0;
  for (int i = 0; i < r.point_count; ++i) start += b2Dot(r.start_velocity[i], t);
  start /= r.point_count;
  const double end = solved.sliding_end;
  const double mass = contact_mass(r.body_a, r.body_b, r.point_count == 2, r.point, t);
  const double normal_force = solved.normal_impulse / h;
  const double other = (mass * (end - start) - solved.tangent_impulse) / h;  // N on B along t, but friction
  const double moving = start - end;
  const double stopped = moving != 0.0 ? std::clamp(start / moving, 0.0, 1.0) : 0.0;  // share of the step
  double wanted = 0.0;  // B's sliding at the step's end by Coulomb's law: held
  // Read from float velocities, `other` is good to a few parts in a million; at the limit
  // itself (a spring stopping a block with mu_k = 0 pushes back with exactly mu_s·N) it holds,
  // and were it a hair above, the next step's stuck solve would find that out.
  if (std::abs(other) > breakaway_coefficient(pair) * normal_force * (1.0 + stop_tolerance)) {
    const double way = other > 0.0 ? 1.0 : -1.0;
    wanted = way * std::max(std::abs(other) - pair.mu_k * normal_force, 0.0) * (1.0 - stopped) * h / mass;
    r.state = ContactState::slipping;
    r.slip_direction = static_cast<float>(way);
  }
  r.breakaway_impulse = mass * (wanted - end);
}

void after_solve(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  // A rigid body sticks or slips as a whole on all its contacts with the other body, so what
  // they reached together decides, once for the group (see FrictionListener::settle). For a
  // contact alone the group's figures are its own.
  const double reached = std::abs(solved.group_tangent_impulse) / solved.group_normal_impulse;
  if (r.state == ContactState::sticking) {
    if (reached >= breakaway_coefficient(pair) * (1.0 - breakaway_tolerance)) {
      r.state = ContactState::slipping;
      if (r.siblings == 0) {
        // B goes the way it would have gone without the friction: m·v - T (friction on B
        // opposes B's sliding). The sliding velocity alone will not do: the limit is declared
        // within breakaway_tolerance, so at fine steps the contact often breaks away in a step
        // whose friction still held, with round-off of either sign for a velocity; slipping
        // the wrong way, the next step saw a reversal and stuck again at once.
        const double mass = contact_mass(r.body_a, r.body_b, r.point_count == 2, r.point, r.tangent());
        r.slip_direction = sign(static_cast<float>(mass * solved.sliding_end - solved.tangent_impulse));
        r.breakaway_impulse = r.slip_direction * breakaway_correction(r, pair, solved);
      } else {
        // A held group ends the step with round-off for a velocity, of either sign. B goes the
        // way it would have gone without the friction: m·v - T.
        const double mass = translational_mass(r.body_a, r.body_b);
        r.slip_direction = sign(static_cast<float>(mass * solved.group_sliding_end - solved.group_tangent_impulse));
        r.breakaway_impulse = r.slip_direction * group_breakaway_correction(r, pair, solved);
      }
    } else {
      r.held_force = std::abs(solved.group_tangent_impulse) / solved.step;
    }
  } else {
    const bool held = reached < pair.mu_k * (1.0 - stop_tolerance);
    const bool reversed = sign(solved.group_sliding_end) == -r.slip_direction;
    if (held || reversed) r.state = ContactState::sticking;
    if (reversed && r.siblings == 0) restick_correction(r, pair, solved);
  }
}

}  // namespace

const TreatmentRule& stick_slip_rule() {
  static const TreatmentRule rule{FrictionTreatment::stick_slip, solver_coefficient, after_solve, nullptr, true};
  return rule;
}

}  // namespace frictionlab
