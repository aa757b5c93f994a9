// Reduced one-degree-of-freedom models of the friction lessons: the same laws as the Box2D
// scene, with nothing else in the way, so the scene can be checked against an exact answer and
// the game-style integrators charted against it (speed against accuracy, and where they fail).
// Doubles, SI units. Bad parameters throw InvalidInput naming the parameter and its range.
#pragma once

#include <functional>
#include <vector>

#include "physics/materials.h"

namespace frictionlab {

// One degree of freedom: a block sliding along a line (flat ground, an incline, pulled by a spring).
struct OneDofBlock {
  double mass = 1, normal_force = 9.81;
  FrictionPair pair;
  double constant_force = 0;  // e.g. m g sinθ down the slope
  double spring_k = 0, anchor_start = 0, pull_speed = 0, rest_length = 0;  // spring force k·(anchor_start + pull_speed·t − x − rest_length)
  double x0 = 0, v0 = 0;
};

// Everything acting along the line but friction.
double applied_force(const OneDofBlock& block, double t, double x);

enum class EventKind {
  breakaway,  // starts to slide (from rest, or after touching v = 0 with the push still winning)
  stop,       // stops and sticks
  reversal,   // stops and at once slides back the other way
  end         // the end of the solve, t_end
};
struct Event {
  double t, x, v;
  EventKind kind;
};

// Stuck, or sliding towards −x (left) or +x (right), with the sign of kinetic friction fixed.
enum class PhaseKind { stick, slip_left, slip_right };

struct BlockState {
  double x = 0, v = 0;
};

// A stretch of motion between two events, with its own way of evaluating the state inside it.
struct Phase {
  double t_start = 0, t_end = 0;
  PhaseKind kind = PhaseKind::stick;
  std::function<BlockState(double t)> state;
};

class Trajectory {  // result of an event-driven solve; evaluate anywhere in [0, t_end]
 public:
  Trajectory(std::vector<Phase> phases, std::vector<Event> events);
  // Throw InvalidInput for t outside [0, t_end]. At an event the later phase answers.
  double position(double t) const;
  double velocity(double t) const;
  BlockState state(double t) const;
  const std::vector<Event>& events() const { return events_; }
  const std::vector<Phase>& phases() const { return phases_; }
  double t_end() const { return phases_.back().t_end; }

 private:
  std::vector<Phase> phases_;
  std::vector<Event> events_;
};

// At v = 0 the block sticks while |applied| <= μ_break·N, μ_break = max(μs, μk), and otherwise
// slides in the direction of the applied force. (With μk > μs a block pushed just past μs·N
// would be pushed back by kinetic friction: it cannot start until the push also beats μk·N.)
// Starting with v0 != 0 starts slipping in the direction of v0.

// Exact: phases (stick, slip left, slip right) joined at events; within each phase the ODE
// m x'' = applied − s μk N − c x' is solved in closed form (spring-mass-damper with ramp forcing:
// under-, critically, over-damped; k=0 cases); events located to ~1e-13 s by bracketing and
// bisection on the closed form. Requires b == 0 (else InvalidInput).
Trajectory solve_exact(const OneDofBlock& block, double t_end);

// Same phase logic, but each phase integrated numerically with classical RK4 at step h, events
// located by bisection of the RK4 step (sub-step re-integration) to 1e-13 s; allows b > 0.
// Independent of the closed forms: it only evaluates the ODE right-hand side.
Trajectory solve_event_rk4(const OneDofBlock& block, double t_end, double h);

// Fixed-step integrators with the regularized law (friction_laws.h, threshold epsilon): the
// "game-style" methods to chart against. An unstable choice of h shows as samples that grow or
// turn non-finite; they are returned as they are, since showing the failure is the point.
enum class Integrator { explicit_euler, semi_implicit_euler, rk4 };
struct Sample {
  double t, x, v;
};
// Samples at t = 0, h, 2h, ... and t_end (the last step is shortened to land on it).
std::vector<Sample> integrate_regularized(const OneDofBlock& block, double t_end, double h, double epsilon,
                                          Integrator integrator);

}  // namespace frictionlab
