// stick-slip: each contact is stuck or slipping. Stuck, the solver may use up to mu_s·N; a
// contact starts slipping when the solved tangential impulse reaches that limit, and slips
// with mu_k·N until its sliding stops or reverses. Several contacts between the same two
// bodies (a body on feet) are one group with one state, judged from their totals. This is what makes the spring lesson
// converge to the exact Coulomb answer as the step shrinks (it realises the engineering
// model's piecewise law through the solver's impulses).
#include <algorithm>
#include <cmath>

#include "physics/contact_mechanics.h"
#include "physics/friction_laws.h"
#include "physics/friction_listener.h"
#include "physics/treatment.h"

namespace frictionlab {
namespace {

// A contact born sliding faster than this starts out slipping; slower, it starts stuck and
// the solver decides at the first step. Only a contact's birth uses a speed: afterwards the
// state follows from the impulses, which is what lets the error vanish as the step shrinks.
constexpr float birth_sliding_speed = static_cast<float>(stick_slip_birth_sliding_speed);

// The solver clamps each point's friction impulse against the normal impulse of its own
// iteration, and the final normal impulse differs from it by round-off and by the last
// iteration's change (about 1e-4 of it on a sliding block). Friction within this share of
// mu_s·N is friction at the limit, which static friction still gives.
constexpr double breakaway_tolerance = 1e-5;

// A stuck contact at exactly mu_s·N must stay stuck, and Box2D's eight iterations make that
// hard to see. After a disturbance (the first step of a block held on a table by a weight on a
// rope, the weight's pull exactly mu_s·N) they leave the bodies a little of the velocity they
// should not have (the block ends its first step moving at 3e-6 m/s, the weight faster: the
// rope is not met either), and the next step's friction must undo that as well as hold: up
// to 0.7 % past the limit across the pulley's sliders, less in each later step. Judged by that
// one step, a contact at the limit broke away. So the solver may hold a stuck contact up to
// this much past the limit, and a step that went past it, within this band, is judged as
// follows (for a contact alone; a group keeps the rule below). If the step began with the contact sliding the way the excess pushes (the solver's
// leftover from the step before), and the step took most of that sliding away, the excess may
// be the solver catching up: the contact stays stuck and is watched. It stays stuck while
// what it went past the limit by dies away from step to step, and breaks away as soon as that
// stops (a real excess, or one still growing), with the impulse it held past the limit handed
// back and kinetic friction owed from the instant the limit was crossed, however many steps
// back. Every other excess breaks away at once, as before: a load that grows steadily (the
// spring lesson) leaves a stuck contact creeping at a steady speed, not one dying away, and
// is not held for a step it should have slipped in, which would cost position the
// velocity-only correction cannot give back.
constexpr double hold_band = stick_slip_hold_band;
// The share of its sliding a step must take away, and the share of the excess that sliding's
// momentum (the contact's own mass times it) must reach, for the excess to count as the
// solver's leftover. Measured: after the pulley's first step the block's own momentum is 6 to
// 16 % of the excess (the rest rides on the weight) and a step takes 80 to 97 % of its
// sliding away; a steadily pulled block creeps with under 0.2 % of the excess, as fast at the
// end of a step as at its start.
constexpr double leftover_taken = 0.5;
constexpr double leftover_share = 0.02;
// An excess that shrinks to less than this share of the last step's is the solver's leftover
// dying away; the pulley's shrinks to a quarter or less a step.
constexpr double dying_away = 0.5;

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
  if (r.listener.fresh && std::abs(sliding) > birth_sliding_speed) {
    r.friction.state = ContactState::slipping;
    r.friction.slip_direction = sign(sliding);
  }
  if (r.friction.state == ContactState::slipping) return static_cast<float>(pair.mu_k);
  return r.listener.siblings > 0 ? group_hold_coefficient
                                 : static_cast<float>(breakaway_coefficient(pair) * (1.0 + hold_band));
}

// B's sliding along the tangent when the step began (PreSolve's velocities, before the forces
// acted), the mean over the contact's points; 0 with none.
double sliding_at_start(const ContactRecord& r) {
  double start = 0.0;
  for (int i = 0; i < r.solver.point_count; ++i) start += b2Dot(r.solver.start_velocity[i], r.tangent());
  if (r.solver.point_count > 0) start /= r.solver.point_count;
  return start;
}

// The mass the contact's tangential motion feels: a group's feet keep the body level, as a face
// does; a lone contact's own mass applies.
double tangential_mass(const ContactRecord& r) {
  return r.listener.siblings > 0
             ? translational_mass(r.identity.body_a, r.identity.body_b)
             : contact_mass(r.identity.body_a, r.identity.body_b, r.solver.point_count == 2, r.solver.point, r.tangent());
}

// What a stuck contact (or group) did in a step, along its tangent: the friction it held and
// the friction holding it would have taken, which is more when the solver let it move.
struct StuckStep {
  double h;              // s
  double normal_force;   // N
  double limit;          // N, mu_s·N
  double held;           // N
  double demanded;       // N
  double mass;           // kg, what the contact's tangential motion feels
  float way;             // the way B goes without friction: m·v - T (friction on B opposes it)
};

StuckStep stuck_step(const ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  StuckStep step{};
  step.h = solved.step;
  step.normal_force = solved.group_normal_impulse / step.h;
  step.limit = breakaway_coefficient(pair) * step.normal_force;
  step.held = std::abs(solved.group_tangent_impulse) / step.h;
  step.mass = tangential_mass(r);
  step.demanded = step.held + step.mass * std::abs(solved.group_sliding_end) / step.h;
  step.way = sign(static_cast<float>(step.mass * solved.group_sliding_end - solved.group_tangent_impulse));
  return step;
}

// Whether a stuck step that went past the limit by `past` (N) may be the solver undoing what it
// left the step before (see hold_band).
bool looks_like_leftover(const ContactRecord& r, const StuckStep& step, double past, const SolvedContact& solved) {
  // A group's sliding at the start is known only at each foot, where the body's turning adds
  // round-off as large as such a leftover (5e-8 m/s on a block on three feet at 1000 Hz, a
  // twentieth of the excess): groups break away past the tolerance, as they did.
  if (r.listener.siblings > 0 || r.solver.point_count == 0) return false;
  const double start = sliding_at_start(r);
  const double along = step.way * start;
  return along > 0.0 && std::abs(solved.group_sliding_end) <= leftover_taken * along &&
         step.mass * along >= leftover_share * past * step.h;
}

// The impulse owed to a contact that breaks away, on B in the way it slips. The steps since it
// was last within mu_s·N were solved stuck, although the static limit was passed somewhere in
// the first of them; from then on friction is only mu_k. Box2D's velocities are those of the
// middle of a step (x_{n+1} = x_n + h·v_{n+1/2}), so the kinetic friction has been acting for
// s = late + h/2 when the step ends, where `late` is how long before the step's sample time
// the demanded friction crossed mu_s·N. That crossing is found by linear interpolation of the
// margin, demand less limit, between the step last held within the limit and this one: the
// limit moves with N, and where N falls under a steady demand it is the limit that closes the
// gap. (Interpolating the demand alone against this step's limit put such a crossing at the
// half step whatever it was: a block on a swinging, shaken plank with mu_k = 0 at mu_s 1.507,
// its demand flat and N falling 0.6 % a step, broke away 1.5 steps late and slid 0.08 m/s
// short of the exact slide, 0.22 m off at the end.) The impulse
// owed is what the solver held past the limit (in this step and any it held within the band)
// and (mu_s - mu_k)·N·s. Without it the breakaway is a step late on average and the error is
// first order; with it the spring lesson converges at second order. s goes into the record
// (breakaway.span): the listener shares the impulse with bodies stuck to B or A at that rate.
double breakaway_correction(ContactRecord& r, const FrictionPair& pair, const StuckStep& step) {
  const double span = (r.friction.band.steps + std::max(r.friction.crept_steps, 0) + 1) * step.h;  // since the friction was last within the limit
  const double excess = std::max(step.demanded - step.limit, 0.0);
  // The limit then: this step's if none is known (the same limit for both ends), and for a group.
  // A group's total normal impulse carries the solver's split between its feet, which moves
  // from step to step (3.7e-5 of N on a block on three feet, mu_s 2, 120 Hz: the limit moved by
  // 4 % of a step's growth of the pull, the crossing by a tenth of a step, and the block slid
  // 0.15 % faster than on its face). A lone contact's N is the solver's one answer.
  const double limit_then =
      r.friction.held_limit >= 0.0 && r.listener.siblings == 0 ? r.friction.held_limit : step.limit;
  const double growth = ((step.demanded - step.limit) - (r.friction.held_demand - limit_then)) / span;
  const double late = growth > 0.0 ? std::clamp(excess / growth, 0.0, span) : 0.5 * step.h;
  const double held_past = r.friction.band.impulse + std::max(step.held - step.limit, 0.0) * step.h;
  r.breakaway.span = late + 0.5 * step.h;
  return held_past + (breakaway_coefficient(pair) - pair.mu_k) * step.normal_force * r.breakaway.span;
}

void leave_band(ContactRecord& r) {
  r.friction.band.steps = 0;
  r.friction.band.excess = 0.0;
  r.friction.band.impulse = 0.0;
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
//
// Box2D's velocities are those of the middle of a step (x_{n+1} = x_n + h·v_{n+1/2}, as in
// breakaway_correction): a step's change of velocity is what the forces do from the middle of
// the step before to the middle of this one, a span h long. The solver spreads the step's own
// forces (gravity, springs, the push of the surface) over that span. A driven (kinematic)
// body's change of velocity between the steps is the drive's over the same span, but the
// sliding takes it all at once, before the solve, so the solver finds the stop as if the drive
// had acted first. So Coulomb's law is followed here with the drive spread over the span like
// the other forces: from B's sliding before the drive changed, slowed by kinetic friction and
// by the forces and the drive together until it stops, then held if static friction can hold
// it against them, or carried the other way by them against kinetic friction for the rest of
// the span. Placing the stop inside the span leaves an error of order the step squared at each
// one, as the breakaway's placing does. Taken all at once at the start, the drive stopped the
// sliding too early, and after it the block was left with the step's kinetic friction and
// none of the drive that carries it on (made up only by the next step's drive, whose own
// kinetic friction then stopped it again): each reversal left the block's sliding off by up
// to mu_k·g·h, which nothing took back while it slid, a first-order error (a level plank shaken
// at 14.62 m/s², 10 rad/s, mu_s 0.9692, mu_k 0.7089: 0.35·mu_k·g·h a reversal on average,
// the slide 0.026 m off the exact one after 5 s at 240 Hz, 0.005 at 960). Only the driven
// body's own change counts as the drive: a breakaway correction, drag or a script's velocity
// applied between the steps is B's sliding at the span's start, no force the contact must hold
// against. (Taken for a stop held whatever the drive, B was dragged to A's new speed at every
// reversal: by a·h = 0.125 m/s on a plank shaken at 30 m/s², 40 times what mu_s·N gives in a
// step at mu_s 0.066; ΔK off by 2.4 J in 5 s.)
void restick_correction(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  const double h = solved.step;
  const b2Vec2 t = r.tangent();
  if (r.solver.point_count == 0 || h <= 0.0) return;
  const double start = sliding_at_start(r);
  const double end = solved.sliding_end;
  const double mass = tangential_mass(r);
  if (!(mass > 0.0)) return;
  const double normal_force = solved.normal_impulse / h;
  const double other = (mass * (end - start) - solved.tangent_impulse) / h;  // N on B along t, but friction
  // 0 unless a body is driven: the listener counts only a driven body's velocity in them.
  const double drive = r.drive.before_known ? mass * b2Dot(r.drive.velocity - r.drive.velocity_before, t) / h : 0.0;
  const double pushing = other + drive;            // N on B along t over the span, but friction
  const double before = start - drive * h / mass;  // B's sliding at the span's start
  // Read from float velocities, `other` is good to a few parts in a million; at the limit
  // itself (a spring stopping a block with mu_k = 0 pushes back with exactly mu_s·N) it holds,
  // and were it a hair above, the next step's stuck solve would find that out.
  const double limit = breakaway_coefficient(pair) * normal_force * (1.0 + stop_tolerance);
  // The way it slid before the step: the state's, unless it was already sliding the other way
  // when the span began: a contact with no load keeps its state unsolved (FrictionListener), so a block that
  // leaves the surface inside the contact's skin and turns round in the air comes back with the
  // way it had before it left. Taken for a stop at the span's start, its sliding was set to
  // what one span's pushing gives from rest: a block on a shaken plank, back from a 0.5 mm hop
  // at 0.64 m/s, was left sliding at 0.11 m/s (wedge, a_x -27.59 at 10 rad/s, mu_k 0.045: the
  // slide 0.38 m off the exact one at the end, at 240 and 480 Hz alike).
  const double way = r.friction.slip_direction * before < 0.0 ? sign(before) : r.friction.slip_direction;
  // m/s that kinetic friction and the pushing take from the sliding over the span while it
  // slides on the old way.
  const double slowing = (pair.mu_k * normal_force - way * pushing) * h / mass;
  double wanted = 0.0;  // B's sliding at the step's end by Coulomb's law
  if (way * before > 0.0 && (!(slowing > 0.0) || way * before >= slowing)) {
    // No stop in the span by Coulomb's law, whatever the solver ended with (round-off at a stop
    // at the span's very end, or a normal impulse that changed after friction was clamped
    // against it): it slides on the old way.
    wanted = before + (pushing - way * pair.mu_k * normal_force) * h / mass;
    r.friction.state = ContactState::slipping;
    r.friction.slip_direction = static_cast<float>(way);
  } else {
    // The share of the span it slid on before it stopped (none, if it was at rest at the span's
    // start).
    const double stopped = slowing > 0.0 ? std::clamp(way * before / slowing, 0.0, 1.0) : 0.0;
    if (std::abs(pushing) > limit) {
      const double back = sign(pushing);
      wanted = (pushing - back * pair.mu_k * normal_force) * (1.0 - stopped) * h / mass;
      r.friction.state = ContactState::slipping;
      r.friction.slip_direction = static_cast<float>(back);
    } else {
      // Held: the friction holding it is the pushing, from which a later breakaway's crossing
      // of the limit is placed (breakaway_correction).
      r.friction.state = ContactState::sticking;
      r.friction.held_demand = std::abs(pushing);
      r.friction.held_limit = breakaway_coefficient(pair) * normal_force;
      r.friction.crept_steps = 0;
      r.friction.crept_past = 0.0;
    }
  }
  r.breakaway.impulse = mass * (wanted - end);
  r.breakaway.span = 0.0;
}

// A stuck contact (or group) after the solve: held within mu_s·N, watched within the band, or
// broken away with the impulse it is owed.
void after_stuck_step(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  const StuckStep step = stuck_step(r, pair, solved);
  // Without friction to hold it (mu_s = mu_k = 0) a contact slips, as it always did. Within
  // mu_s·N it stays stuck if the solver held it: if what holding takes, with what the contact
  // still slides at the step's end, is within the band the solver may hold. Friction short of
  // mu_s·N on a contact that slides on is the solver's clamp, not a hold: a top block on a
  // light bottom one that breaks away from the floor, tilting it, was clamped 1.5 % short of
  // it and slid back at up to 0.09 m/s while read as stuck, never seen to slip.
  if (step.limit > 0.0 && step.held <= step.limit * (1.0 + breakaway_tolerance) &&
      step.demanded <= step.limit * (1.0 + hold_band)) {
    // The crossing is placed on the demand (breakaway_correction), so the demand is what is
    // kept: where the solver let the contact creep, what it held falls short of it. Kept as the
    // held friction, the margin then read up to a step's growth low, and the breakaway was
    // placed late: on a level plank shaken at 17.8 m/s² (mu_s 1.76, mu_k 0.29), 4 ms late at
    // each reversal's brief stop, each leaving the block 0.055 m/s slow, the slide 0.076 m off
    // the exact one after 5 s at 240 Hz (0.028 m kept so).
    // A step whose demand went past the limit while the solver held the friction within it
    // (letting the contact creep) leaves the crossing where it was, between the last step within
    // the limit and this one; kept as the new start, it put the crossing past this step and the
    // breakaway a step late: a block on a shaken plank stopped for 0.9 ms (mu_s 1.787,
    // mu_k 0.16), demand 1 N past mu_s·N at the next step and held, broke away the step after
    // with its crossing placed 1 ms late and slid on 0.024 m/s slow, the slide 0.096 m off the
    // exact one at 5 s at 240 Hz (0.041 m kept so). Kept only while that start was within the
    // limit and the demand goes on past it further each step, as a growing load's does, and past
    // round-off (breakaway_tolerance): a contact held at mu_s·N, its demand a hair over from one
    // step to the next, would else carry its start on for as long as it held and be paid
    // (mu_s - mu_k)·N for all that time at the breakaway. (What a band step before it held past
    // the limit is dropped here, as it was.)
    const double past_limit = step.demanded - step.limit;
    const bool crossing_kept = r.friction.crept_steps >= 0 && r.friction.held_demand <= r.friction.held_limit &&
                               past_limit > breakaway_tolerance * step.limit && past_limit > r.friction.crept_past;
    if (crossing_kept) {
      r.friction.crept_steps += r.friction.band.steps + 1;
      r.friction.crept_past = past_limit;
    } else {
      r.friction.held_demand = step.demanded;
      r.friction.held_limit = step.limit;
      r.friction.crept_steps = 0;
      r.friction.crept_past = 0.0;
    }
    leave_band(r);
    return;
  }
  const double past = step.held - step.limit;
  const bool within_band = step.demanded <= step.limit * (1.0 + hold_band);
  const bool watched = r.friction.band.steps > 0 ? past < dying_away * r.friction.band.excess
                                                 : looks_like_leftover(r, step, past, solved);
  if (within_band && watched) {
    ++r.friction.band.steps;
    r.friction.band.excess = past;
    r.friction.band.impulse += past * step.h;
    return;
  }
  // B goes the way it would have gone without the friction. Its sliding velocity alone will
  // not do: a contact that held at the limit ends its step with round-off of either sign for
  // a velocity, and slipping the wrong way, the next step saw a reversal and stuck again.
  r.friction.state = ContactState::slipping;
  r.friction.slip_direction = step.way;
  r.breakaway.impulse = r.friction.slip_direction * breakaway_correction(r, pair, step);
  leave_band(r);
  r.friction.crept_steps = -1;
  // What the step held past the limit is handed back with the correction: the step's
  // friction, as the arrows and plots show it, is the limit.
  if (r.listener.siblings == 0 && step.held > step.limit) r.solver.friction_force *= step.limit / step.held;
}

// Whether the solver held a slipping contact (or group) in this step, friction having reached
// `reached` times N.
// Friction short of mu_k·N is the solver's evidence that it held the contact, which then
// ends the step (all but) at rest. Still sliding faster than a step of kinetic friction
// could stop it, mu_k·N·h/m, it was not held: its friction fell short because the normal
// impulse grew after friction had been clamped against it (a rocking block, 4 solver
// passes: 0.4 % short on a pair sliding at 2.3 m/s, taken for held, stuck, broken away the
// next step with a correction for the time it "held", and so every other step: 4 m/s² more
// than its forces give).
bool held_by_the_solver(const ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved, double reached) {
  const double mass = tangential_mass(r);
  const bool at_rest = mass > 0.0 && std::abs(solved.group_sliding_end) <= pair.mu_k * solved.group_normal_impulse / mass;
  // Friction falls short of mu_k·N while a contact slides too: the normal impulses move after
  // friction was clamped against them, most in the first step after a breakaway, warm-started
  // from the stuck step's. With mu_k above mu_s the body breaks away at mu_k·N and, just past
  // it, slides off from rest slowly enough to look held: six feet, 1.71 kg, mu_s 0, mu_k 1.84,
  // c 778 N·s/m, b 606 N·s²/m², 50 N/s, 480 Hz: friction short of it, the block speeding up
  // from rest to 9.5 mm/s in the step, taken for held, broken away again the next step, and
  // so for 8 steps, its breakaway read at 2 sub-steps of 240 Hz (the held steps' ends) 1.9 N
  // late; a box, mu_s 0.67, mu_k 1.57, c 449, b 567, 200 N/s: 8 % short, 2.1 N late. A held
  // body does not speed up: one that ends its step sliding faster its way than it began, by
  // more than the speed below which a contact counts as not sliding
  // (stick_slip_birth_sliding_speed), was not held.
  const double start = sliding_at_start(r);
  const bool sped_up = r.friction.slip_direction * (solved.group_sliding_end - start) > birth_sliding_speed;
  return reached < pair.mu_k * (1.0 - stop_tolerance) && at_rest && !sped_up;
}

// A slipping contact (or group) after the solve: it slides on, or it stopped (held by the
// solver, or its sliding reversed) and sticks, with Coulomb's law deciding a lone contact's stop.
void after_slipping_step(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved, double reached) {
  // With no friction at all nothing stops the sliding, so a reversal is the other body's doing
  // (a driven plank's velocity changes between steps) and the contact slides on, the new way.
  // Taken for a stop, its correction set the sliding to zero: a frictionless block on a shaken
  // plank was dragged along at the plank's speed at every reversal.
  if (breakaway_coefficient(pair) == 0.0) {
    if (solved.group_sliding_end != 0.0) {
      r.friction.slip_direction = static_cast<float>(sign(solved.group_sliding_end));
    }
    return;
  }
  const bool held = held_by_the_solver(r, pair, solved, reached);
  const bool reversed = sign(solved.group_sliding_end) == -r.friction.slip_direction;
  if (held || reversed) r.friction.state = ContactState::sticking;
  // Stopped by the solver on a driven body, the drive may carry it on the other way at once,
  // which the drive's change of velocity at the next step's start shows the stuck solve only
  // then: held for that step at mu_s·N, it broke away with a correction for a span read from
  // the last hold, however long ago (0.02 m/s off at such stops on the shaken plank). Coulomb's
  // law decides it here, as at a reversal. Only where mu_s > mu_k: the stale span costs the
  // correction's (mu_s - mu_k)·N·span, nothing where mu_k >= mu_s (the held step's limit is
  // then mu_k·N already), and decided here those settings ended up to 0.038 m further off the
  // exact slide than held for the step (wedge, mu_k 1.6 against mu_s 0.34 and 1.33).
  const bool driven = is_driven(r.identity.body_a) || is_driven(r.identity.body_b);
  const bool stop_on_drive = held && driven && r.drive.before_known && pair.mu_k < pair.mu_s;
  if ((reversed || stop_on_drive) && r.listener.siblings == 0) restick_correction(r, pair, solved);
}

void after_solve(ContactRecord& r, const FrictionPair& pair, const SolvedContact& solved) {
  // A rigid body sticks or slips as a whole on all its contacts with the other body, so what
  // they reached together decides, once for the group (see FrictionListener::settle). For a
  // contact alone the group's figures are its own.
  const double reached = std::abs(solved.group_tangent_impulse) / solved.group_normal_impulse;
  if (r.friction.state == ContactState::sticking) {
    after_stuck_step(r, pair, solved);
  } else {
    after_slipping_step(r, pair, solved, reached);
  }
}

}  // namespace

const TreatmentRule& stick_slip_rule() {
  static const TreatmentRule rule{FrictionTreatment::stick_slip, solver_coefficient, after_solve, nullptr, true};
  return rule;
}

}  // namespace frictionlab
