// The contact listener that replaces Box2D's friction mixer with the pair table and gives
// static and kinetic friction their own coefficients.
#pragma once

#include <box2d/box2d.h>

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "physics/friction_laws.h"
#include "physics/materials.h"

namespace frictionlab {

// How the dry (Coulomb) part of friction is treated; selectable per run so they can be compared.
enum class FrictionTreatment {
  stick_slip,   // each contact sticks (mu_s) or slips (mu_k), switched by what the solver did
  threshold,    // mu_s below a sliding speed epsilon, mu_k above: the usual game approach
  regularized,  // the tribology article's F = mu_s·N·v/epsilon below epsilon, an explicit force
  box2d,        // Box2D's single coefficient (mu_k of the pair) for sticking and sliding alike
};
std::string_view treatment_name(FrictionTreatment treatment);
// Throws InvalidInput listing the allowed names.
FrictionTreatment parse_treatment(std::string_view name);

// A fixture's material is stored in its user data as id + 1, so 0 means "none given".
inline int fixture_material(b2Fixture* fixture) {
  return static_cast<int>(fixture->GetUserData().pointer) - 1;
}

// Box2D reports inertia about the body origin; dynamics needs it about the centre of mass.
inline float central_inertia(const b2Body* body) {
  const b2Vec2 c = body->GetLocalCenter();
  return body->GetInertia() - body->GetMass() * b2Dot(c, c);
}

// What the solver did at one contact in the last step, so arrows, plots and the energy ledger
// show the solver's numbers rather than the formula's.
struct ContactRecord {
  b2Body* body_a = nullptr;
  b2Body* body_b = nullptr;
  int material_a = -1;
  int material_b = -1;
  ContactState state = ContactState::sticking;
  float slip_direction = 0.0f;     // sign of B's sliding velocity relative to A while slipping
  int point_count = 0;
  b2Vec2 point{0.0f, 0.0f};        // world, mean of the manifold points
  b2Vec2 normal{0.0f, 1.0f};       // world, from A to B
  double normal_force = 0.0;       // N, on B
  double friction_force = 0.0;     // N, on B along the tangent (normal rotated -90°)
  double damping_force = 0.0;      // N, viscous + quadratic, on B along the tangent
  double sliding_velocity = 0.0;   // m/s, B relative to A along the tangent, end of step
  double point_normal_force[b2_maxManifoldPoints] = {0.0, 0.0};  // N, how the load is shared
  // Per manifold point, at the start of the solve: the solver's lever arms and velocities.
  b2Vec2 world_points[b2_maxManifoldPoints];
  b2Vec2 start_velocity[b2_maxManifoldPoints];  // B's point velocity minus A's
  bool fresh = true;               // not yet seen by PreSolve: its first state comes from its speed
  bool unpaired = false;           // its materials have no pair values: switched off, reported
  double held_force = 0.0;         // N, friction while stuck in the previous step
  double breakaway_impulse = 0.0;  // N·s along the tangent on B, owed since the last breakaway

  // Box2D's friction direction for a contact normal: the normal turned by -90°.
  static b2Vec2 tangent_of(const b2Vec2& n) { return b2Cross(n, 1.0f); }
  b2Vec2 tangent() const { return tangent_of(normal); }
  // The forces on `body`, which must be one of the two in contact (N, world axes).
  b2Vec2 friction_on(const b2Body* body) const { return side(body) * static_cast<float>(friction_force) * tangent(); }
  b2Vec2 normal_on(const b2Body* body) const { return side(body) * static_cast<float>(normal_force) * normal; }
  float side(const b2Body* body) const { return body == body_b ? 1.0f : -1.0f; }
};

// Work done in one step, split the way the energy ledger reports it (joules).
struct ContactWork {
  double friction = 0.0;  // dry friction on the sliding velocity: never positive
  double damping = 0.0;   // viscous and quadratic terms: never positive
  double impacts = 0.0;   // normal impulses: non-positive, nonzero only when bodies collide
  double drivers = 0.0;   // contact impulses on dynamic bodies through kinematic bodies' motion
};

class FrictionListener : public b2ContactListener {
 public:
  explicit FrictionListener(const PairTable& pairs) : pairs_(pairs) { records_.reserve(256); }

  void set_treatment(FrictionTreatment treatment) { treatment_ = treatment; }
  FrictionTreatment treatment() const { return treatment_; }
  // The speed epsilon of the threshold and regularized treatments, m/s, > 0.
  void set_threshold_speed(double epsilon);
  double threshold_speed() const { return threshold_speed_; }

  // Before each world step of length h: applies the viscous and quadratic terms (and, for the
  // regularized treatment, the dry force) as impulses at each contact, equal and opposite.
  void apply_contact_forces(b2World& world, float h);
  // Work done since the last call; the scene adds it to its ledger once per step.
  ContactWork take_work();
  // After a trial step whose outcome was undone: every contact decides its state afresh at
  // the next step, owes no breakaway impulse, and the trial's work is dropped.
  void forget_trial();

  // Unordered: iterate the world's contact list where order matters.
  const std::unordered_map<b2Contact*, ContactRecord>& contacts() const { return records_; }
  // The first error met during the last step (empty if none), cleared by reading it.
  std::string take_error();
  // The record for the contact between two bodies, if they touch.
  const ContactRecord* find(const b2Body* a, const b2Body* b) const;

  void BeginContact(b2Contact* contact) override;
  void EndContact(b2Contact* contact) override;
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

 private:
  // The breakaway impulse owed, the viscous and quadratic drag and the regularized dry force,
  // as impulses at the contact for the coming step.
  void apply_velocity_terms(b2Contact* contact, ContactRecord& r);
  // Adds the impulses of every other touching contact between the same two bodies (a body on
  // feet), along this contact's tangent `t`, to the totals.
  void sum_sibling_impulses(const b2Contact* contact, const b2Vec2& t, double* normal, double* tangent) const;
  double breakaway_correction(const ContactRecord& r, const FrictionPair& pair, double normal_impulse,
                              float sliding_end) const;

  const PairTable& pairs_;
  FrictionTreatment treatment_ = FrictionTreatment::stick_slip;
  double threshold_speed_ = 0.01;
  float step_ = 1.0f / 240.0f;
  std::unordered_map<b2Contact*, ContactRecord> records_;
  ContactWork work_;
  std::string error_;
};

}  // namespace frictionlab
