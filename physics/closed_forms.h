// Closed-form answers to the textbook friction problems, so every lesson can show theory
// beside simulation with the error between them. Doubles, SI units, angles in radians.
// Every function throws InvalidInput (naming the parameter and its allowed range) for a
// negative mass, a NaN, a negative coefficient and the like.
#pragma once

#include "physics/materials.h"

namespace frictionlab::theory {

// Steepest incline a block rests on: tan(angle) = mu_s, whatever its mass.
double sticking_angle(double mu_s);

// Acceleration down the slope of a block already sliding down it, g(sin θ − μk cos θ).
// Zero or negative means kinetic friction would stop it.
double incline_sliding_acceleration(double angle, double mu_k, double g);

// A block released from rest on an incline steeper than atan(mu_s), with kinetic friction
// mu_k and viscous drag c (c may be 0): speed and distance along the slope at time t >= 0.
// Where kinetic friction alone would hold it (tan θ <= mu_k) it never starts: both are 0.
double incline_speed(double angle, double mu_k, double c, double mass, double g, double t);
double incline_distance(double angle, double mu_k, double c, double mass, double g, double t);
// The same with quadratic drag b too (F = −b·v²): m v' = m·g(sin θ − μk cos θ) − c·v − b·v².
double incline_speed(double angle, double mu_k, double c, double b, double mass, double g, double t);
double incline_distance(double angle, double mu_k, double c, double b, double mass, double g, double t);
// The same slide as a world stepped every h s moves it: the drag applied exactly over each step
// before the step's other forces (as FrictionListener does, damped_velocity), then gravity
// and kinetic friction for the step, v ← damped(v) + a·h (a > 0: kinetic friction that would
// stop the block holds it from the start, and both are 0), and x ← x + h·v. Where m/c nears h
// or falls below it the two part: with c alone the stepped block creeps at a·h/(1 − e^(−c·h/m)),
// not a·m/c (c = 800 N·s/m on 1 kg at 240 Hz: 3.5 times faster). t is taken to the nearest
// whole step.
struct InclineSlide {
  double speed, distance;
};
InclineSlide incline_slide_stepped(double angle, double mu_k, double c, double b, double mass, double g, double t, double h);

// A uniform box of width d pushed horizontally at height h: pushed at or above d/(2 μs) it
// tips about its front edge before it slides, however hard the push.
double tip_height(double width, double mu_s);

struct PushOutcome {
  bool tips;     // true: tips before sliding; false: slides first
  double force;  // push (N) at which that happens: min(W·d/(2h), μs·W)
};
PushOutcome push_outcome(double weight, double width, double push_height, double mu_s);

// The spring lesson: a block of mass m on flat ground, pulled by a spring of stiffness k whose
// far end moves at pull_speed; at t = 0 the spring is at its rest length and the block at rest,
// no viscous drag. The motion settles at once into a periodic stick-slip cycle.
struct StickSlip {
  double breakaway_force;       // spring force when the block starts to slide, μs·m·g
  double restick_force;         // spring force when it stops, (2μk − μs)·m·g (negative: compressed)
  double stick_duration;        // s
  double slip_duration;         // s
  double period;                // stick + slip
  double first_breakaway_time;  // s after the pull starts
  double slip_distance;         // how far the block moves in one cycle, m
};
// Requires 0 <= mu_k <= mu_s (else no periodic stick-slip exists), k > 0, pull_speed > 0.
StickSlip spring_stick_slip(double mass, double k, double pull_speed, double mu_s, double mu_k, double g);

// A block launched at v0 on flat ground slowing under m v' = −μk m g − c v − b v², with any
// c >= 0 and b >= 0. v0 may have either sign; time and distance are magnitudes. Infinity where
// it never stops (no dry friction), or never stops within a finite distance.
struct SlideToRest {
  double time;
  double distance;
};
SlideToRest slide_to_rest(double v0, double mass, const FrictionPair& pair, double g);

// A round body (disk, ring, ball: any inertia about its centre) released on an incline.
// Positive is down the slope; friction_force is the magnitude of friction, acting up the slope.
struct DiskOnIncline {
  bool rolls;                   // rolls without slipping when tan θ <= max(μs, μk)·(1 + m R² / I)
  double acceleration;          // of the centre, m/s²
  double angular_acceleration;  // rad/s², in the rolling-down sense
  double friction_force;        // N
};
// With mu_k above mu_s it grips up to max(mu_s, mu_k)·N, as the simulation's contacts do (a
// contact pushed past mu_s·N but not mu_k·N is stopped slipping at once), and slips past that.
DiskOnIncline disk_on_incline(double angle, double mass, double radius, double inertia, double mu_s, double mu_k,
                              double g);

// A disk launched sliding at v0 with no spin on flat ground: kinetic friction slows the centre
// and spins the disk up until v = ω R, after which it rolls. v0 may have either sign; the
// results are magnitudes. With mu_k = 0 it never rolls (time and distance infinite).
struct RollStart {
  double time;
  double speed;
  double distance;
};
RollStart disk_starts_rolling(double v0, double mass, double radius, double inertia, double mu_k, double g);

// Two blocks stacked on the ground, a horizontal push on the bottom one (negative pushes the
// other way; accelerations then carry the same sign). Coulomb friction only: the answer is
// for the instant the push is applied to the blocks at rest, where c·v and b·v² are zero.
enum class StackRegime { at_rest, together, top_slips };
struct StackedBlocks {
  StackRegime regime;
  double top_acceleration;
  double bottom_acceleration;
  // Largest push for which the sliding pair moves as one, (μs_between + μk_ground)·(m1+m2)·g.
  // Together happens for μs_ground·(m1+m2)·g < |push| <= this; when this is below the
  // breakaway push the top block slips as soon as the bottom one moves.
  double max_push_together;
};
// Requires mu_k <= mu_s for both pairs: with mu_k above mu_s a surface pushed past mu_s·N would
// at once be held back harder, and which block then does what has no closed form here.
StackedBlocks stacked_blocks(double top_mass, double bottom_mass, const FrictionPair& between,
                             const FrictionPair& ground, double push, double g);

// Connected masses: a block of mass m_b on a level table, tied by a light rope over a light,
// frictionless pulley at the table's edge to a weight of mass m_h hanging beside it, both let go
// at rest. The rope makes them one body of mass m_b + m_h along the rope, driven by m_h·g and
// held back by the table's friction on the block alone, whose normal force is m_b·g. It stays
// put while m_h <= max(mu_s, mu_k)·m_b (at equality too: static friction can give exactly
// mu_s·m_b·g; with mu_k above mu_s a block pulled past mu_s·N would at once be held back by
// mu_k·N, so it cannot start before the pull beats both, the listener's rule). Otherwise both
// move with a = g·(m_h − mu_k·m_b)/(m_b + m_h), and the rope pulls with T = m_h·(g − a) on each.
struct ConnectedMasses {
  bool slides;
  double acceleration;  // m/s², of each along the rope; 0 while it stays put
  double tension;       // N, the rope's pull on each body
  double friction;      // N, magnitude of the table's friction on the block
  // The heaviest weight the block holds: max(mu_s, mu_k)·m_b.
  double heaviest_held;
};
ConnectedMasses connected_masses(double block_mass, double hanging_mass, double mu_s, double mu_k, double g);

// The friction-situations article's changing coefficient: a block of mass m at rest on level
// ground, pulled along it by a constant force from t = 0, on a surface that is dry before
// `from`, lubricated from `from` until `until`, and dry again after. In each stretch the
// coefficients are constant: a block at rest starts when the pull beats max(mu_s, mu_k)·m·g
// (the listener's rule) and then moves at a = (pull − mu_k·m·g)/m; a sliding block slowed by
// a < 0 stops where its speed reaches 0 and stays unless the pull beats max(mu_s, mu_k)·m·g.
// No drag (c and b are not used). The state at time t >= 0:
struct IntermittentSlide {
  bool sliding;
  double acceleration;  // m/s², at t (while sliding; 0 at rest)
  double speed;         // m/s
  double distance;      // m from where it stood
};
IntermittentSlide intermittent_slide(double mass, double pull, const FrictionPair& dry, const FrictionPair& lubricated,
                                     double from, double until, double t, double g);

// The friction-situations article's FAQ: friction in the direction of motion. A wheel of mass
// m, radius r and inertia I about its axle on level ground, turned forward by a torque from
// rest. Rolling without slipping, the ground's friction f pushes it forward and is all that
// speeds it up: m·a = f, I·α = torque − f·r, a = α·r, so a = torque·r/(I + m·r²) and
// f = m·a. That needs f <= max(mu_s, mu_k)·m·g, so it rolls up to the traction limit
// torque = max(mu_s, mu_k)·g·(I + m·r²)/r (mu_s·m·g·r for a wheel of no inertia, the article's
// simplest case). Above it the wheel spins: kinetic friction mu_k·m·g still pushes forward,
// a = mu_k·g, and the rest of the torque spins it up, α = (torque − mu_k·m·g·r)/I. Magnitudes,
// forward positive; torque >= 0.
struct DrivenWheel {
  bool rolls;
  double acceleration;          // m/s², of the axle
  double angular_acceleration;  // rad/s², in the rolling-forward sense
  double friction;              // N, forward
  double traction_limit;        // N·m
};
DrivenWheel driven_wheel(double mass, double radius, double inertia, double torque, double mu_s, double mu_k, double g);

// The tribology article's book pushed harder and harder (the force-sensor lab): a block of mass
// m at rest on flat ground, pushed along it by a force growing at `rate` from 0 at t = 0.
// Static friction answers the push until it reaches the breakaway push; then kinetic friction
// mu_k·m·g and the drag c·v + b·v² hold back a block that only speeds up, since the push keeps
// growing past them. The breakaway push is max(mu_s, mu_k)·m·g: with mu_k above mu_s a block
// pushed past mu_s·N would at once be pushed back by kinetic friction, so it cannot start
// before the push also beats mu_k·N (the same rule as the friction listener's).
// With b = 0 the slide is m·v' + c·v = rate·t − mu_k·m·g, solved in closed form. With b > 0 it
// is a Riccati equation with a ramp, which has no elementary solution: the same equation is
// then integrated with RK4 at 0.1 ms (at most 200 000 steps: a longer slide takes longer steps).
struct GrowingPush {
  double breakaway_push;    // N
  double breakaway_time;    // s after the push starts
  double push;              // N, rate·t
  double friction;          // N, magnitude at t: the push itself while stuck, then mu_k·m·g + c·v + b·v²
  double acceleration;      // m/s² at t
  double speed;             // m/s at t
  double distance;          // m at t, from where it stood
};
GrowingPush growing_push(double mass, double rate, const FrictionPair& pair, double g, double t);

// The tribology article's thrown box: a box of width w and height h thrown with its centre at
// centre_height, at speed vx (level), spinning at omega (counter-clockwise positive), tilted by
// angle, falls until its lowest corner comes within `clearance` of the floor (Box2D's bodies
// touch when their cores are two skins apart). Free flight: the centre falls as g·t²/2 and the
// box turns at omega. Found by stepping the lowest corner's height at 0.1 ms and bisecting the
// step where it passes the clearance. corner_x, corner_y: that corner from the centre, world axes.
struct BoxLanding {
  double time;
  double angle;  // rad, at landing
  double corner_x, corner_y;
  // Its bottom face is level to within 1 mm (thrown without spin, say): it lands on the face,
  // whose two ends share the impact, and no single corner takes it.
  bool flat;
};
BoxLanding box_landing(double width, double height, double centre_height, double angle, double omega, double g,
                       double clearance);

// A rigid body (mass, inertia about its centre) strikes a level floor at one point r from its
// centre (world axes), moving at (vx, vy) and spinning at omega, with restitution e. The impulse
// (J_t along x, J_n up) follows m·Δv = J, I·Δω = r × J. The point either grips (its sliding is
// stopped within the impact: needs |J_t| <= mu·J_n) or slides throughout (J_t = −mu·J_n·sign of
// its sliding), whichever is consistent; mu is the kinetic coefficient, since the point arrives
// sliding. Returns the motion just after.
struct CornerImpact {
  bool grips;
  double normal_impulse, tangent_impulse;  // N·s
  double vx, vy, omega;                    // just after
};
CornerImpact corner_impact(double mass, double inertia, double rx, double ry, double vx, double vy, double omega,
                           double mu, double restitution);

// The same impact as Box2D 2.4.1's velocity solver leaves it on a contact born in the step (no
// impulse carried over): friction, then the normal impulse, solved in turns `iterations` times,
// friction clamped at mu times the normal impulse found so far. A gripping corner whose friction
// waits on a normal impulse still growing is not settled after 8 turns (17.8 kg at 14.9 rad/s,
// mu 1.28: spin -0.19 rad/s after 8, -1.08 when settled); how far this is from corner_impact's
// answer is what the solver leaves undone.
CornerImpact solver_corner_impact(double mass, double inertia, double rx, double ry, double vx, double vy,
                                  double omega, double mu, double restitution, int iterations);

// A block launched up a slope of `angle` (0: flat ground) at v0 with kinetic friction mu_k:
// it slows at g·(sin θ + mu_k·cos θ) and stops after v0²/(2·g·(sin θ + mu_k·cos θ)); it then
// stays where it stopped if tan θ <= mu_s, and otherwise slides back down.
struct SlopeLaunch {
  double distance;  // m up the slope
  double time;      // s until it stops
  bool stays;
};
SlopeLaunch slope_launch(double v0, double angle, double mu_s, double mu_k, double g);

// The games' velocity hack of the tribology article: no friction at all, but each frame of
// length h the velocity is multiplied by `keep` (1 − f) after the frame has moved the body
// (which, on a slope, includes gravity's g·sin θ·h down the slope). Exact for that discrete
// process as the scene runs it: a frame of n sub-steps, each taking g·sin θ·h/n off the speed
// before it moves the body h/n, and the first frame starting from v0 + g·sin θ·h/(2n) (the
// scene's leapfrog start: the velocity half a sub-step before t = 0). On the flat it goes h·v0/(1 − keep) in all,
// linear in v0 where friction's distance grows as v0²; on any slope it never holds, but drifts
// down towards −keep·g·sin θ·h/(1 − keep).
struct VelocityHack {
  double distance_up;  // m, the farthest it gets along its launch (the whole slide on the flat)
  double drift_speed;  // m/s up the slope that it tends to: 0 on the flat, negative on a slope
};
VelocityHack velocity_hack(double v0, double keep, double h, double angle, double g, int substeps = 1);

}  // namespace frictionlab::theory
