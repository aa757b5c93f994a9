// Where the game-style methods fail. The tribology article's regularized friction (a steep
// line through v = 0 instead of Coulomb's jump) makes friction a stiff damper below the
// threshold speed epsilon, with rate mu_s·g/epsilon: a fixed-step integrator is stable there
// only for h below a bound that shrinks with epsilon. Above it the block never settles: its
// velocity flips sign every step (chatter). A large epsilon instead lets a block creep down a
// slope it should stick to. The viscous term has the same trap for h·c/m >= 2 when applied
// explicitly; the project applies it exactly (damped_velocity) and has none.
#pragma once

#include <string_view>
#include <vector>

#include "physics/reduced_model.h"

namespace frictionlab {

enum class Behaviour {
  stable,      // settles: the velocity dies away
  chattering,  // never settles: the velocity keeps flipping sign, bounded by the kinetic law
  divergent    // grows without bound, or stops being a number
};
std::string_view behaviour_name(Behaviour behaviour);

// A block launched at 1 m/s on flat ground, integrated with the regularized law at step h and
// threshold epsilon until well after it should have stopped, then judged by its last steps.
Behaviour classify_regularized(const FrictionPair& pair, double gravity, double h, double epsilon,
                               Integrator integrator);

// The largest step at which the method is stable below the threshold, from linear stability:
// h = z·epsilon/(mu_s·g) with z = 2 for both Euler methods (friction depends on v alone, so
// the semi-implicit one updates v exactly as the explicit one does) and z = 2.785... for RK4,
// the real root of |1 − z + z²/2 − z³/6 + z⁴/24| = 1.
double theoretical_boundary(const FrictionPair& pair, double gravity, double epsilon, Integrator integrator);

// The same boundary found by bisection on classify_regularized between h_low (stable) and
// h_high (not), to a relative 1e-4.
double measured_boundary(const FrictionPair& pair, double gravity, double epsilon, Integrator integrator);

struct StabilityCell {
  Integrator integrator;
  double h, epsilon;
  Behaviour behaviour;
};
// Every (h, epsilon) of two logarithmic grids, for one integrator.
std::vector<StabilityCell> stability_map(const FrictionPair& pair, double gravity, Integrator integrator,
                                         const std::vector<double>& steps, const std::vector<double>& epsilons);
std::vector<double> logarithmic_range(double low, double high, int count);

// The speed a block settles to on a slope of `angle` (radians, tan(angle) < mu_s, where
// Coulomb's block sticks) under the regularized law: epsilon·tan(angle)/mu_s in theory.
double creep_speed(const FrictionPair& pair, double gravity, double angle, double epsilon, double h,
                   Integrator integrator);
double theoretical_creep_speed(const FrictionPair& pair, double angle, double epsilon);

// The viscous term alone over n steps at h·c/m = `ratio`, from v = 1: applied as an explicit
// force (v ← v·(1 − h·c/m)) or as the project applies it (damped_velocity, exact). Returns the
// velocity after each step.
std::vector<double> viscous_explicit(double ratio, int steps);
std::vector<double> viscous_exact(double ratio, int steps);
Behaviour classify_velocities(const std::vector<double>& velocities);

}  // namespace frictionlab
