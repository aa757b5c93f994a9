// The contact listener that replaces Box2D's friction mixer with the pair table and gives
// static and kinetic friction their own coefficients.
#pragma once

#include <cmath>

#include <box2d/box2d.h>

#include <string>
#include <vector>

#include "physics/contact_mechanics.h"
#include "physics/friction_laws.h"
#include "physics/materials.h"
#include "physics/treatment.h"

namespace frictionlab {

// A fixture's material is stored in its user data as id + 1, so 0 means "none given".
inline int fixture_material(b2Fixture* fixture) {
  return static_cast<int>(fixture->GetUserData().pointer) - 1;
}

// Which contact a record is and between what: set when the contact begins, and the same for
// as long as it lasts.
struct ContactIdentity {
  b2Contact* contact = nullptr;
  b2Body* body_a = nullptr;
  b2Body* body_b = nullptr;
  int material_a = -1;
  int material_b = -1;
  float radius_a = 0.0f;           // the fixtures' shapes' skins (b2Shape::m_radius), m
  float radius_b = 0.0f;
  int pair_index = -1;             // the pair's place in the table (PairTable::pair_at)
  bool unpaired = false;           // its materials have no pair values: switched off, reported
};

// What the listener read of the contact around the last solve: where and how it touched when
// the solve began (PreSolve), and the forces and sliding the solver left (finish_step). This is
// what arrows, plots and the energy ledger show, the solver's numbers rather than the formula's.
struct SolverReadout {
  // Its pair has no dry friction (mu_s = mu_k = 0, a smooth wall; drag c or b may still act,
  // and it holds nothing either): nothing can hold it, so it neither sticks nor slips in the
  // lesson's sense; it only slides along or does not (see seen_slipping). Set from the pair
  // at every PreSolve, as the pair's sliders may change while it touches.
  bool frictionless = false;
  int point_count = 0;
  b2Vec2 point{0.0f, 0.0f};        // world, mean of the manifold points
  b2Vec2 normal{0.0f, 1.0f};       // world, from A to B
  // Per manifold point, at the start of the solve: the solver's lever arms and velocities.
  b2Vec2 world_points[b2_maxManifoldPoints];
  b2Vec2 start_velocity[b2_maxManifoldPoints];  // B's point velocity minus A's
  double normal_force = 0.0;       // N, on B
  double friction_force = 0.0;     // N, on B along the tangent (normal rotated -90°)
  double damping_force = 0.0;      // N, viscous + quadratic, on B along the tangent
  double sliding_velocity = 0.0;   // m/s, B relative to A along the tangent, end of step
  double point_normal_force[b2_maxManifoldPoints] = {0.0, 0.0};  // N, how the load is shared
  float step = 1.0f / 240.0f;      // s, the step the contact was last solved with
};

// What a drive did to the sliding between the step before and this one, read at each
// PreSolve. Only a driven (kinematic) body's velocity counts (is_driven).
struct DriveBetweenSteps {
  bool before_known = false;       // the contact was solved in the step before too
  // m/s, the driven bodies' share of the contact's relative velocity at the start of this step
  // and of the step before (B's point velocity less A's, counting only a driven body's): its
  // change along this step's tangent is what the drive alone did to the sliding between steps,
  // apart from corrections, drag and scripts that also change the bodies' velocities there.
  // Kept as vectors: on a turning plank the tangent turns by θ'·h between the steps, and the
  // plank's velocity read along the old tangent and then the new one changes by its velocity
  // across the surface times θ'·h, which B's own velocity changes by too, so that the sliding
  // does not (the contact keeps them together across the surface). Taken for the drive, it let
  // a block the exact model holds slide on from a stop (a plank swinging 33.7° at 5 rad/s and
  // carried at 16 m/s by then: the slide ended 0.020 m off, 0.018 allowed; 0.014 without it).
  b2Vec2 velocity{0.0f, 0.0f};
  b2Vec2 velocity_before{0.0f, 0.0f};
};

// A stuck contact whose friction went a hair past mu_s·N, within what the solver holds for a
// step (see treatment_stick_slip.cpp): how many steps in a row, the last step's friction above
// the limit (N), and the impulse held above the limit over them (N·s).
struct HoldBand {
  int steps = 0;
  double excess = 0.0;
  double impulse = 0.0;
};

// Whether the contact sticks or slips, and what the treatment carries from one step to the
// next to decide it again. A group of contacts between the same two bodies (a body on feet)
// sticks or slips as one, so every contact of the group holds the same copy of all of it
// (FrictionListener::share_group_state, join_group): whatever a treatment keeps of the group's
// state goes here, and a contact's own goes elsewhere.
struct FrictionState {
  ContactState state = ContactState::sticking;
  float slip_direction = 0.0f;     // sign of B's sliding velocity relative to A while slipping
  double held_demand = 0.0;        // N, what holding took in the last step it stayed within mu_s·N
  // N, mu_s·N in that step (negative: not known, as before any step). The breakaway is placed
  // where the demand's margin over the limit crossed zero, and a limit that falls as N does
  // moves that crossing as much as a demand that grows (see breakaway_correction).
  double held_limit = -1.0;
  // Steps held since then with the demand past mu_s·N while the solver held the friction within
  // it (it let the contact creep), and the band's steps before them: the crossing lies between
  // that step and the first of these, so the breakaway is placed from there
  // (breakaway_correction). -1 while held_demand is not from this stuck stretch (before any
  // step, and after a breakaway). crept_past: N, how far the last of them was past the limit;
  // each must pass it further to be counted (treatment_stick_slip.cpp, after_stuck_step).
  int crept_steps = -1;
  double crept_past = 0.0;
  HoldBand band;
};

// The correction a breakaway or re-stick owes the bodies, paid before the next step.
struct OwedCorrection {
  double impulse = 0.0;            // N·s along the tangent on B, owed since the last breakaway
  // s, how long the kinetic friction that impulse stands for has been acting: it was owed at
  // that rate, and a stuck neighbour must have carried its share as fast. 0 for a re-stick's
  // correction, which is a change of B's velocity rather than friction over a time.
  double span = 0.0;
};

// The listener's own notes on the contact, from one call to the next.
struct ListenerNotes {
  bool fresh = true;               // not yet seen by PreSolve: its first state comes from its speed
  bool solving = false;            // seen by PreSolve in this step, not yet by finish_step
  // How many other touching contacts join the same two bodies through the same pair of
  // materials (a body on feet has one contact a foot). Such a group sticks or slips as one:
  // under stick-slip its state is decided once a step for all of them (see settle).
  int siblings = 0;
  // N·s, the explicit dry impulse applied before this step (regularized), whose work is counted
  // once the step's velocity is known.
  double explicit_impulse = 0.0;
};

// One contact as the listener keeps it, in the parts that change at different moments: who
// touches (once), what the solve read (every step), what the drive did between steps, whether
// it sticks or slips (the treatment's, shared by a group), the correction it owes, and the
// listener's notes.
struct ContactRecord {
  ContactIdentity identity;
  SolverReadout solver;
  DriveBetweenSteps drive;
  FrictionState friction;
  OwedCorrection breakaway;
  ListenerNotes listener;

  // Whether a student reads it as slipping (the probe `slipping`, the plots' shading): its
  // state; or, frictionless, whether the bodies slide along each other at all. The listener's
  // state says "slipping" for every frictionless contact, since nothing there can hold, and a
  // box standing still against a smooth wall was drawn and probed as slipping. "At all" is
  // faster than a floor that scales with the step squared: a push that grows from nothing acts
  // from the second step and leaves a body sliding at rate·h²/m after it, so that is the
  // smallest real sliding a step can show. The gentlest such push the lessons offer (push's
  // 0.2 N/s on 10 kg) gives 3.5e-7 m/s at 240 Hz and stacked_blocks' (0.5 N/s on 15 kg)
  // 5.8e-7; the floor, 1e-7 m/s at 240 Hz, is below both at every step, and above the solver's
  // leftovers for bodies at rest against a smooth wall (up to 1e-8 m/s at 240 Hz). The slip
  // then shows at the end of the first step anything pushes, as a slip with friction shows at
  // the end of the step it began in. (A box thrown into a smooth wall creeps on along the
  // floor at 8e-7 m/s, the solver pushing it into the wall: it slides, slowly, and reads so.)
  static constexpr double frictionless_sliding_speed_at_240_hz = 1e-7;  // m/s
  double frictionless_sliding_speed() const {
    const double steps_of_240_hz = 240.0 * solver.step;
    return frictionless_sliding_speed_at_240_hz * steps_of_240_hz * steps_of_240_hz;
  }
  bool seen_slipping() const {
    if (solver.frictionless) return std::abs(solver.sliding_velocity) > frictionless_sliding_speed();
    return friction.state == ContactState::slipping;
  }

  // Box2D's friction direction for a contact normal: the normal turned by -90°.
  static b2Vec2 tangent_of(const b2Vec2& n) { return b2Cross(n, 1.0f); }
  b2Vec2 tangent() const { return tangent_of(solver.normal); }
  // The forces on `body`, which must be one of the two in contact (N, world axes).
  b2Vec2 friction_on(const b2Body* body) const {
    return side(body) * static_cast<float>(solver.friction_force) * tangent();
  }
  b2Vec2 normal_on(const b2Body* body) const {
    return side(body) * static_cast<float>(solver.normal_force) * solver.normal;
  }
  float side(const b2Body* body) const { return body == identity.body_b ? 1.0f : -1.0f; }
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

  // The run's treatment: what every pair without a treatment of its own follows. A pair that
  // names one (PairTable::set_treatment) keeps it whatever the run's is.
  void set_treatment(FrictionTreatment treatment) { run_rule_ = &rule_of(treatment); }
  FrictionTreatment treatment() const { return run_rule_->treatment; }
  // The run's speed epsilon of the threshold and regularized treatments, m/s, > 0; a pair with
  // its own epsilon uses that instead.
  void set_threshold_speed(double epsilon);
  double threshold_speed() const { return threshold_speed_; }
  // The treatment and epsilon a contact between these materials uses now.
  FrictionTreatment treatment_of(int material_a, int material_b) const;
  double epsilon_of(int material_a, int material_b) const;

  // Before each world step of length h: applies the viscous and quadratic terms (and, for the
  // regularized treatment, the dry force) as impulses at each contact, equal and opposite.
  void apply_contact_forces(b2World& world, float h);
  // Work done since the last call; the scene adds it to its ledger once per step.
  ContactWork take_work();
  // After a trial step whose outcome was undone: every contact decides its state afresh at
  // the next step, owes no breakaway impulse, and the trial's work is dropped.
  void forget_trial();

  // Every touching-or-not contact Box2D has begun and not ended, in no order that means
  // anything: iterate the world's contact list where order matters.
  const std::vector<ContactRecord>& contacts() const { return records_; }
  // The record of one of the world's contacts (null if the listener has none).
  const ContactRecord* record(const b2Contact* contact) const {
    const std::size_t index = index_of(contact);
    return index < records_.size() && records_[index].identity.contact == contact ? &records_[index] : nullptr;
  }
  // The scene put a body of this contact to rest (it sleeps, its velocity zero): Box2D solves a
  // sleeping contact no more, so finish_step() would leave its last sliding speed standing for
  // as long as it sleeps; resting, it slides no more.
  void came_to_rest(const b2Contact* contact) {
    if (ContactRecord* r = mutable_record(contact)) r->solver.sliding_velocity = 0.0;
  }
  // The first error met during the last step (empty if none), cleared by reading it.
  std::string take_error();
  // The record for the contact between two bodies, if they touch.
  const ContactRecord* find(const b2Body* a, const b2Body* b) const;

  void BeginContact(b2Contact* contact) override;
  void EndContact(b2Contact* contact) override;
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
  // After each world step: what the solver did at every contact it solved, read from the
  // contacts' manifolds, goes into their records (forces, sliding, work, the treatment's next
  // state). The scene calls it right after b2World::Step; until then the records hold the
  // previous step's figures.
  void finish_step();

 private:
  // The breakaway impulse owed, the viscous and quadratic drag and the regularized dry force,
  // as impulses at the contact for the coming step.
  void apply_velocity_terms(b2Contact* contact, ContactRecord& r);
  // The breakaway impulse r owes, on its two bodies, each side shared with the bodies stuck to
  // it (friction_listener_breakaway.cpp).
  void apply_breakaway(b2Contact* contact, ContactRecord& r);
  // The bodies stuck to `body` through stuck contacts other than `broken` that can carry their
  // share of `push` (N·s on body, world axes) over `span` seconds, and the share each takes.
  struct Share {
    b2Body* body;
    b2Vec2 push;
  };
  void share_with_stuck(const b2Contact* broken, b2Body* body, const b2Vec2& push, double span, std::vector<Share>* shares);
  // Calls visit(contact, record) for every contact of r's group, r's own included, in the
  // moving body's contact list order, until visit returns false. A ground's list holds every
  // contact on it (quadratic in a pile's base), so the moving body's is walked.
  template <class Visit>
  void visit_group(const ContactRecord& r, Visit visit) {
    if (r.identity.unpaired) return;
    b2Body* walked = r.identity.body_b->GetType() == b2_staticBody ? r.identity.body_a : r.identity.body_b;
    const b2Body* partner = walked == r.identity.body_b ? r.identity.body_a : r.identity.body_b;
    for (b2ContactEdge* edge = walked->GetContactList(); edge != nullptr; edge = edge->next) {
      if (edge->other != partner) continue;
      ContactRecord* member = mutable_record(edge->contact);
      if (member == nullptr || member->identity.unpaired) continue;
      if (member->identity.pair_index != r.identity.pair_index) continue;
      if (!visit(static_cast<const b2Contact*>(edge->contact), *member)) return;
    }
  }
  // In the settling of a contact with siblings: false unless it is its group's first contact;
  // if it is, the group's totals and sliding go into `solved`.
  bool sum_group(const b2Contact* contact, const ContactRecord& r, SolvedContact* solved);
  // The state the group's first contact was left in, given to the rest of the group.
  void share_group_state(const b2Contact* contact, const ContactRecord& r);
  // A stuck group's friction impulse, left in its manifolds for the next step's warm start,
  // shared between its points in proportion to their loads (see finish_step).
  void share_held_friction_by_load(const ContactRecord& r);
  // A new contact takes its group's state from a sibling that has one already.
  void join_group(const b2Contact* contact, ContactRecord& r);
  ContactRecord* mutable_record(const b2Contact* contact) {
    return const_cast<ContactRecord*>(static_cast<const FrictionListener*>(this)->record(contact));
  }
  // Where a contact's record is. Box2D 2.4.1's b2Contact has no user data, and hashing the
  // contact three times a step cost a 4000-box pile a fifth of its step in cache misses. The
  // index is kept in the contact's restitution threshold instead: Box2D reads that only to
  // decide whether a contact bounces, and FrictionLab's fixtures have no restitution, so the
  // threshold changes nothing. A contact that never began (its threshold is Box2D's 1 m/s)
  // fails the check in record(), whose records_[index].identity.contact must be the contact itself.
  static std::size_t index_of(const b2Contact* contact) {
    return static_cast<std::size_t>(contact->GetRestitutionThreshold());
  }
  void place(ContactRecord& record, std::size_t index) {
    record.identity.contact->SetRestitutionThreshold(static_cast<float>(index));
  }
  // The figures of one contact the solver solved in the last step (see finish_step).
  void settle(ContactRecord& r);
  // What the solver did at r's points in the last step: its forces and sliding into the record,
  // the work into the ledger, and the totals the treatment judges the contact by.
  SolvedContact read_solve(ContactRecord& r, const TreatmentRule& rule);
  // The contact's world manifold now, as b2Contact::GetWorldManifold gives it.
  static void world_manifold(const b2Contact* contact, const ContactRecord& r, b2WorldManifold* world);
  // Whether some contact may owe a drag or regularized force before the coming step, so that
  // every contact must be visited (breakaway corrections alone are listed in owing_).
  bool drag_due() const;
  const TreatmentRule& rule_at(int pair_index) const {
    const PairTreatment& own = pairs_.treatment_at(pair_index);
    return own.own ? rule_of(own.treatment) : *run_rule_;
  }
  double epsilon_at(int pair_index) const {
    const PairTreatment& own = pairs_.treatment_at(pair_index);
    return own.own && own.epsilon > 0.0 ? own.epsilon : threshold_speed_;
  }

  const PairTable& pairs_;
  const TreatmentRule* run_rule_ = &stick_slip_rule();
  double threshold_speed_ = 0.01;
  float step_ = 1.0f / 240.0f;
  // Records live in one dense array (an ended contact's slot is filled by the last record).
  std::vector<ContactRecord> records_;
  // Some record was left a drag force to apply or clear.
  bool drag_pending_ = false;
  // Whether some pair of the table has drag or a dry force of its own, as of its revision
  // drag_read_at_ (see drag_due).
  mutable bool pairs_have_drag_ = false;
  mutable unsigned long drag_read_at_ = 0;
  // The contacts left a breakaway correction by the last step, in the order it found them.
  std::vector<b2Contact*> owing_;
  // The first contacts of the groups the last step left stuck, whose friction is shared by load
  // once every contact of the step is settled.
  std::vector<b2Contact*> held_groups_;
  ContactWork work_;
  std::string error_;
};

}  // namespace frictionlab
