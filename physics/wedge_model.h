// The friction-situations article's block on a swinging, accelerating wedge, as the article
// reduces it: one coordinate s along the surface (down the slope positive) in the wedge's frame,
// with the surface's angle θ(t) = θ0·sin(ω·t) and the frame's acceleration
// a(t) = a_x·cos(ω_a·t) (ω_a = 0: constant) entering only through
//   the driving force  F(t) = m·(g·sin θ + a·cos θ)   down the slope, and
//   the normal force   N(t) = m·(g·cos θ − a·sin θ)   pressing the block on the surface.
// The reduction leaves out the surface's own rotation (its centrifugal, angular-acceleration
// and Coriolis terms): what a Box2D block on a turning plank feels besides is exactly what it
// leaves out.
//
// Solved phase by phase (sticking, slipping one way, in flight) with the phases joined at
// located events: classical RK4 within a phase on a smooth right-hand side, each event found by
// bisecting the step to 1e-13 s, so the answer is as good as exact for the lessons (the tests
// hold it to an independent fine-step time stepping). Doubles, SI units, angles in radians.
#pragma once

#include <vector>

#include "physics/scenarios.h"

namespace frictionlab {

struct WedgeDrive {
  double mass = 1;       // kg
  double theta0 = 0;     // rad: the swing's amplitude
  double omega = 0;      // rad/s: how fast the surface swings
  double a_x = 0;        // m/s²: the wedge's horizontal acceleration (its amplitude when a_x_omega > 0)
  double a_x_omega = 0;  // rad/s: 0 for a constant acceleration
  double mu_s = 0, mu_k = 0;
  double g = standard_gravity;
  // With `rotation`, the terms the reduction leaves out are put back: in the frame turning with
  // the surface, the block's centre (centre_height above the surface line through the pivot,
  // starting `start` m up the slope from the pivot) feels the centrifugal θ'²·ρ, the Euler
  // −θ''×ρ and the Coriolis −2θ'×ρ' accelerations. This is what a rigid block on a turning
  // plank does, and what a Box2D body on a driven plank should follow.
  bool rotation = false;
  double centre_height = 0, start = 0;
  // m/s down the slope at t = 0, in the wedge's frame: 0 for the article's block at rest. A
  // stepped world's block starts off the model's by about a_x·h/2 (it moves with the plank's
  // first step), and a model started so tells what that start does later on.
  double start_speed = 0;

  double angle(double t) const;                     // θ(t), rad; the surface rises towards +x
  double angular_velocity(double t) const;          // θ'(t)
  double angular_acceleration(double t) const;      // θ''(t)
  double acceleration(double t) const;              // a(t), m/s², along +x
  double driving_force(double t) const;             // F(t), N, down the slope
  double normal_force(double t) const;              // N(t), N; negative: the wedge falls away faster than the block
  // The same from sin θ, cos θ and a(t) already worked out (the solver takes them once a time).
  double driving_force_at(double sin_theta, double cos_theta, double a) const;
  double normal_force_at(double sin_theta, double cos_theta, double a) const;
  // Where the wedge's pivot is and how fast it moves, starting at rest at x = 0.
  double wedge_position(double t) const;
  double wedge_velocity(double t) const;
};

// How friction acts in contact.
enum class WedgeLaw {
  coulomb,  // opposes the sliding velocity; static friction holds while |F| <= μs·N
  article,  // the article's equation as written: m·s'' = F − sgn(F)·μk·N, always sliding
};

enum class WedgeContact { stick, slip, flight };

struct WedgeState {
  double t = 0;
  double slide = 0, speed = 0;         // s (m, down the slope positive) and s'
  double height = 0, height_rate = 0;  // in flight: the distance above the surface and its rate
  WedgeContact contact = WedgeContact::stick;
  double normal = 0;    // N, the surface's push (0 in flight)
  double friction = 0;  // N along the slope, down positive: what the surface does along itself
  // The energy books since t = 0, in the wedge's frame: the work of gravity, of the frame's
  // pseudo-force −m·a, of friction, and the kinetic energy the landings took (and, with
  // rotation, the turning frame's work). Their sum is the change of kinetic energy
  // ½m(s'² + height_rate²).
  double work_gravity = 0, work_pseudo = 0, work_friction = 0, work_landings = 0;
  double work_rotation = 0;  // the centrifugal and Euler terms' work (rotation only; Coriolis does none)
};

enum class WedgeEventKind { breakaway, stop, reversal, lift_off, landing, sign_change };
// In words, as scripts read it: "breakaway", "stop", "reversal", "lift-off", "landing", "sign change".
const char* name_of(WedgeEventKind kind);
struct WedgeEvent {
  double t;
  WedgeEventKind kind;
  double slide, speed;
};

struct WedgeRun {
  double sample_step = 0;
  std::vector<WedgeState> samples;  // at t = k·sample_step, k = 0 .. t_end / sample_step
  std::vector<WedgeEvent> events;
  // The stretches in which the block slips along the surface, from a breakaway (or a landing
  // while sliding) to a stop or a lift-off; a reversal does not end one.
  std::vector<std::pair<double, double>> slip_windows;
};

// Throws InvalidInput for a bad parameter (negative mass, a coefficient outside [0, 10],
// non-finite values) or a sample step that would make more than 2e6 samples.
WedgeRun solve_wedge(const WedgeDrive& drive, WedgeLaw law, double t_end, double sample_step,
                     double max_step = 1e-3);

// The same equations stepped as a Box2D world and FrictionLab's listener step them, every
// `world_step`, following `run`'s stick and slip (so a breakaway comes where the model's does):
// the plank's velocity changes once a step, at its start, so the drive comes as a kick of
// a(t)·h there (none in the first step, where the plank moves at the block's own velocity);
// friction is decided once a step against the N the step starts with (its Coriolis part from
// the velocity the block brings in); a block that would turn round inside a step stops there,
// held if static friction can hold it, else sliding back for the rest of the step (the
// listener's restick correction); a breakaway step is held, and kinetic friction's due is paid
// at the next step's start: what was held past μ·N, and (μ − μk)·N for late + h/2, late from the
// margin's growth since the step before (physics/treatment_stick_slip.cpp's
// breakaway_correction); and the block moves through each step at the step's end velocity. The
// slide and speed at each of `run`'s samples, up to its first flight (the lists end there).
// Their gap off `run`'s exact ones is the stepping's own first-order error.
struct WedgeStepped {
  std::vector<double> slide, speed;
};
WedgeStepped step_as_the_world(const WedgeDrive& drive, const WedgeRun& run, double world_step);

// The kinetic energy of a state, J.
double kinetic_energy(const WedgeDrive& drive, const WedgeState& state);

}  // namespace frictionlab
