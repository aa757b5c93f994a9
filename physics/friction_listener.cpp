#include "physics/friction_listener.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace frictionlab {

void FrictionListener::set_threshold_speed(double epsilon) {
  if (!(epsilon > 0.0 && epsilon <= 100.0)) {
    throw InvalidInput("threshold speed epsilon = " + std::to_string(epsilon) +
                       " m/s is outside the allowed range (0, 100]");
  }
  threshold_speed_ = epsilon;
}

const ContactRecord* FrictionListener::find(const b2Body* a, const b2Body* b) const {
  // The body's own contact list: short, and in the world's order, so that of two contacts
  // between the same bodies the same one is found in every run.
  for (const b2ContactEdge* edge = a->GetContactList(); edge != nullptr; edge = edge->next) {
    if (edge->other != b || !edge->contact->IsTouching()) continue;
    if (const ContactRecord* found = record(edge->contact)) return found;
  }
  return nullptr;
}

FrictionTreatment FrictionListener::treatment_of(int material_a, int material_b) const {
  return rule_at(pairs_.pair_index(material_a, material_b)).treatment;
}

double FrictionListener::epsilon_of(int material_a, int material_b) const {
  return epsilon_at(pairs_.pair_index(material_a, material_b));
}

void FrictionListener::BeginContact(b2Contact* contact) {
  ContactRecord record;
  record.identity.contact = contact;
  record.identity.body_a = contact->GetFixtureA()->GetBody();
  record.identity.body_b = contact->GetFixtureB()->GetBody();
  record.identity.material_a = fixture_material(contact->GetFixtureA());
  record.identity.material_b = fixture_material(contact->GetFixtureB());
  record.identity.radius_a = contact->GetFixtureA()->GetShape()->m_radius;
  record.identity.radius_b = contact->GetFixtureB()->GetShape()->m_radius;
  if (!pairs_.has_pair(record.identity.material_a, record.identity.material_b)) {
    // Throwing here would unwind through Box2D and leave the world locked; the contact is
    // switched off instead and the scene reports the error once the step is over.
    record.identity.unpaired = true;
    if (error_.empty()) {
      auto name = [&](int id) { return id >= 0 && id < pairs_.material_count() ? pairs_.material(id).name : "(no material)"; };
      error_ = "no friction values for the pair " + name(record.identity.material_a) + "–" +
               name(record.identity.material_b) + " that just touched; give every fixture a material whose pairs are set";
    }
  } else {
    record.identity.pair_index = pairs_.pair_index(record.identity.material_a, record.identity.material_b);
  }
  if (ContactRecord* known = mutable_record(contact)) {
    record.listener.siblings = known->listener.siblings;  // counted when it began
    *known = record;
    return;
  }
  // A float holds every index exactly up to 2^24; a world of sixteen million contacts is far
  // beyond what a lesson steps.
  if (records_.size() >= (std::size_t{1} << 24)) {
    if (error_.empty()) error_ = "more than 16777216 contacts at once: the friction listener cannot track them";
    record.identity.unpaired = true;
  }
  records_.push_back(record);
  place(records_.back(), records_.size() - 1);
  // The groups are counted here and in EndContact, where touching begins and ends, so that a
  // step never has to search for them.
  ContactRecord& added = records_.back();
  visit_group(added, [&](const b2Contact* other, ContactRecord& member) {
    if (other != contact) {
      ++member.listener.siblings;
      ++added.listener.siblings;
    }
    return true;
  });
}

std::string FrictionListener::take_error() {
  std::string error = std::move(error_);
  error_.clear();
  return error;
}

void FrictionListener::EndContact(b2Contact* contact) {
  const ContactRecord* ended = record(contact);
  if (ended == nullptr) return;
  if (ended->listener.siblings > 0) {
    visit_group(*ended, [&](const b2Contact* other, ContactRecord& member) {
      if (other != contact) --member.listener.siblings;
      return true;
    });
  }
  const std::size_t index = index_of(contact);
  if (index + 1 != records_.size()) {
    records_[index] = records_.back();
    place(records_[index], index);
  }
  records_.pop_back();
}

void FrictionListener::PreSolve(b2Contact* contact, const b2Manifold*) {
  ContactRecord* found = mutable_record(contact);
  if (found == nullptr) return;
  ContactRecord& r = *found;
  if (r.identity.unpaired) {
    contact->SetEnabled(false);
    return;
  }
  const FrictionPair& pair = pairs_.pair_at(r.identity.pair_index);
  r.solver.frictionless = pair.mu_s == 0.0 && pair.mu_k == 0.0;
  // A contact born in this step missed apply_contact_forces: its drag starts now, before the
  // solve, so a block landing on a viscous film is not let off for a step.
  if (r.listener.fresh) apply_velocity_terms(contact, r);
  const TreatmentRule& rule = rule_at(r.identity.pair_index);
  // A foot that touches down while its body's other feet already touch joins their state.
  if (r.listener.fresh && r.listener.siblings > 0 && rule.judges_groups) join_group(contact, r);

  b2WorldManifold manifold;
  world_manifold(contact, r, &manifold);
  r.solver.point_count = contact->GetManifold()->pointCount;
  r.solver.normal = manifold.normal;
  const b2Vec2 t = ContactRecord::tangent_of(r.solver.normal);
  float sliding = 0.0f;
  r.solver.point.SetZero();
  for (int i = 0; i < r.solver.point_count; ++i) {
    r.solver.world_points[i] = manifold.points[i];
    r.solver.start_velocity[i] =
        point_velocity(r.identity.body_b, manifold.points[i]) - point_velocity(r.identity.body_a, manifold.points[i]);
    sliding += b2Dot(r.solver.start_velocity[i], t);
    r.solver.point += manifold.points[i];
  }
  if (r.solver.point_count > 0) {
    sliding /= static_cast<float>(r.solver.point_count);
    r.solver.point *= 1.0f / static_cast<float>(r.solver.point_count);
  }
  contact->SetFriction(rule.solver_coefficient(r, pair, sliding, epsilon_at(r.identity.pair_index)));
  r.drive.before_known = !r.listener.fresh;
  r.drive.velocity_before = r.drive.velocity;
  r.drive.velocity.SetZero();
  if (is_driven(r.identity.body_b)) r.drive.velocity += point_velocity(r.identity.body_b, r.solver.point);
  if (is_driven(r.identity.body_a)) r.drive.velocity -= point_velocity(r.identity.body_a, r.solver.point);
  r.listener.fresh = false;
  r.listener.solving = true;
}

void FrictionListener::world_manifold(const b2Contact* contact, const ContactRecord& r, b2WorldManifold* world) {
  // b2Contact::GetWorldManifold reaches the transforms and skins through the fixtures, their
  // bodies and shapes: four more objects a contact and step, cache misses all in a big pile.
  // The record keeps the bodies and skins, so a face's points are found here, with Box2D 2.4.1's
  // arithmetic in its order (each point midway between the two surfaces, the normal from A to
  // B), which gives the same floats. A circle's manifold is left to Box2D.
  const b2Manifold* m = contact->GetManifold();
  if (m->type == b2Manifold::e_circles || m->pointCount == 0) {
    contact->GetWorldManifold(world);
    return;
  }
  const bool face_a = m->type == b2Manifold::e_faceA;
  // The face's body, whose frame holds the normal and the plane, and the other, whose frame
  // holds the clipped points.
  const b2Transform& face = (face_a ? r.identity.body_a : r.identity.body_b)->GetTransform();
  const b2Transform& other = (face_a ? r.identity.body_b : r.identity.body_a)->GetTransform();
  const float face_radius = face_a ? r.identity.radius_a : r.identity.radius_b;
  const float other_radius = face_a ? r.identity.radius_b : r.identity.radius_a;
  const b2Vec2 normal = b2Mul(face.q, m->localNormal);
  const b2Vec2 plane = b2Mul(face, m->localPoint);
  for (int i = 0; i < m->pointCount; ++i) {
    const b2Vec2 clipped = b2Mul(other, m->points[i].localPoint);
    const b2Vec2 on_face = clipped + (face_radius - b2Dot(clipped - plane, normal)) * normal;
    const b2Vec2 on_other = clipped - other_radius * normal;
    world->points[i] = face_a ? 0.5f * (on_face + on_other) : 0.5f * (on_other + on_face);
  }
  world->normal = face_a ? normal : -normal;
}

void FrictionListener::finish_step() {
  // Box2D would report each contact to PostSolve in the solver's order, and finding the record
  // from there costs two dependent cache misses (the contact, then the record); the records are
  // read here in their own order instead, the contact's impulses from its manifold, where the
  // solver stored them. The physics is the same; only the ledger's sums are added up in
  // another order.
  for (ContactRecord& r : records_) {
    if (!r.listener.solving) continue;
    r.listener.solving = false;
    settle(r);
  }
  // After the loop: every contact's record has read its own impulses as the solver left them.
  for (const b2Contact* contact : held_groups_) {
    if (const ContactRecord* r = record(contact)) share_held_friction_by_load(*r);
  }
  held_groups_.clear();
}

SolvedContact FrictionListener::read_solve(ContactRecord& r, const TreatmentRule& rule) {
  const b2Manifold* solved_manifold = r.identity.contact->GetManifold();
  const b2Vec2 n = r.solver.normal;
  const b2Vec2 t = ContactRecord::tangent_of(n);
  const bool a_driven = is_driven(r.identity.body_a);
  const bool b_driven = is_driven(r.identity.body_b);

  double normal_impulse = 0.0;
  double tangent_impulse = 0.0;
  float sliding_end = 0.0f;
  const int count = std::min(r.solver.point_count, solved_manifold->pointCount);
  for (int i = 0; i < count; ++i) {
    const b2Vec2 p = r.solver.world_points[i];
    const b2Vec2 end_velocity =
        solved_point_velocity(r.identity.body_b, p, step_) - solved_point_velocity(r.identity.body_a, p, step_);
    const b2Vec2 mean_velocity = 0.5f * (r.solver.start_velocity[i] + end_velocity);
    const float jn = solved_manifold->points[i].normalImpulse;
    const float jt = solved_manifold->points[i].tangentImpulse;
    // An impulse changes kinetic energy by itself times the mean of the velocities before
    // and after it: exact for the solver's sequence of impulses, so the ledger closes.
    work_.friction += jt * b2Dot(mean_velocity, t);
    work_.impacts += jn * b2Dot(mean_velocity, n);
    const b2Vec2 on_b = jn * n + jt * t;
    if (a_driven) work_.drivers += b2Dot(on_b, solved_point_velocity(r.identity.body_a, p, step_));
    if (b_driven) work_.drivers -= b2Dot(on_b, solved_point_velocity(r.identity.body_b, p, step_));
    r.solver.point_normal_force[i] = jn / step_;
    normal_impulse += jn;
    tangent_impulse += jt;
    sliding_end += b2Dot(end_velocity, t);
  }
  if (count > 0) sliding_end /= static_cast<float>(count);
  r.solver.normal_force = normal_impulse / step_;
  if (rule.explicit_dry_force == nullptr) r.solver.friction_force = tangent_impulse / step_;
  r.solver.sliding_velocity = sliding_end;
  r.solver.step = step_;
  work_.friction += r.listener.explicit_impulse * sliding_end;
  r.listener.explicit_impulse = 0.0;
  return SolvedContact{normal_impulse, tangent_impulse, sliding_end, step_, normal_impulse, tangent_impulse, sliding_end};
}

void FrictionListener::settle(ContactRecord& r) {
  b2Contact* contact = r.identity.contact;
  const TreatmentRule& rule = rule_at(r.identity.pair_index);
  SolvedContact solved = read_solve(r, rule);
  const FrictionPair& pair = pairs_.pair_at(r.identity.pair_index);
  if (r.listener.siblings > 0 && rule.judges_groups) {
    // A body standing on several feet touches the floor through several contacts. Being rigid,
    // it sticks or slides as a whole: its feet share one static limit, mu_s times their total
    // load, however the load happens to be split between them (which statics cannot decide for
    // three feet in a row, and the solver decides its own way). So the group is judged once,
    // from its totals, and all its contacts take the verdict, a foot without load included.
    if (!sum_group(contact, r, &solved)) return;  // the group's first contact decides
    if (solved.group_normal_impulse <= 0.0) return;  // no load, no evidence either way
    rule.after_solve(r, pair, solved);
    share_group_state(contact, r);
    if (r.friction.state == ContactState::sticking) held_groups_.push_back(contact);
  } else {
    if (solved.normal_impulse <= 0.0) return;  // no load, no evidence either way: keep the state
    rule.after_solve(r, pair, solved);
  }
  if (r.breakaway.impulse != 0.0) owing_.push_back(contact);
}

bool FrictionListener::sum_group(const b2Contact* contact, const ContactRecord& r, SolvedContact* solved) {
  const b2Vec2 t = r.tangent();
  bool first = true;
  double normal = 0.0, tangent = 0.0, weighted_sliding = 0.0;
  float sliding = 0.0f;
  int points = 0;
  visit_group(r, [&](const b2Contact* other, const ContactRecord& member) {
    if (first && other != contact) return false;
    first = false;
    // Box2D keeps each point's accumulated impulses in the manifold for warm starting, where
    // the solver left them at the end of the step. Along this contact's tangent, and with
    // the same sign convention (on the body that is this contact's B). The member's points and
    // normal are those its PreSolve saw in this step, as the solver did.
    const b2Manifold* manifold = other->GetManifold();
    const float side = member.identity.body_b == r.identity.body_b ? 1.0f : -1.0f;
    const float along = side * b2Dot(member.tangent(), t);
    const int count = std::min(member.solver.point_count, manifold->pointCount);
    for (int i = 0; i < count; ++i) {
      const double jn = manifold->points[i].normalImpulse;
      const b2Vec2 p = member.solver.world_points[i];
      const float v =
          b2Dot(solved_point_velocity(r.identity.body_b, p, step_) - solved_point_velocity(r.identity.body_a, p, step_), t);
      normal += jn;
      tangent += along * manifold->points[i].tangentImpulse;
      weighted_sliding += jn * v;
      sliding += v;
      ++points;
    }
    return true;
  });
  if (first) return false;
  solved->group_normal_impulse = normal;
  solved->group_tangent_impulse = tangent;
  if (normal > 0.0) {
    solved->group_sliding_end = static_cast<float>(weighted_sliding / normal);
  } else if (points > 0) {
    solved->group_sliding_end = sliding / static_cast<float>(points);
  }
  return true;
}

void FrictionListener::share_group_state(const b2Contact* contact, const ContactRecord& r) {
  visit_group(r, [&](const b2Contact* other, ContactRecord& member) {
    // The sign of B's sliding relative to A along the tangent is the same seen from either body
    // (both flip), so the state is copied as it is.
    if (other != contact) member.friction = r.friction;
    return true;
  });
}

// A stuck group's points are given a coefficient no load share reaches (stick-slip's
// group_hold_coefficient), so the solver holds the body wherever a rigid hold needs it. The
// feet of a body in a row have the same tangential row in the solver (same direction, same
// height below the centre), so how the friction is split between them changes nothing the body
// does, and statics cannot decide it: the solver keeps whatever split its warm start gives,
// step after step. Left so, friction piled up on a foot whose load had all but gone (17 N on a
// foot carrying 0.002 N of a 9 kg block on six feet), and in the step its load reached 0 the
// solver's clamp dropped it, faster than its passes could move it to the other feet: the body
// was left sliding 6 mm/s, and taking that back the next step read as a breakaway at 166.8 N
// where mu·N is 178.8 N. The next step starts from the split Coulomb's law gives a rigid body
// on equal feet, each point's friction in proportion to its load: the same total impulse at
// the same height (the same warm start for the body), and a foot that loses its load has
// carried only its share of the friction. Where every point's tangent is the group's, the same
// way: feet on one flat surface, or on two steps at two heights. On steps the split moves the
// friction's moment, and that is what Coulomb's law asks: a point whose load goes carries no
// friction. Left to the solver, friction stayed on a high step whose load was going (it may
// hold 10^4 times the load there), and its moment held up a body the closed form tips: a body
// on steps 0.5 m apart, pulled at 0.6 m, stood unturned at 1.5 times the pull that tips it
// (BodyOnTwoSteps). A body between a floor and a ceiling (tangents opposite) keeps the
// solver's split: no scene has shown what the share does there.
void FrictionListener::share_held_friction_by_load(const ContactRecord& r) {
  const b2Vec2 t = r.tangent();
  double normal = 0.0, tangent = 0.0;
  bool parallel = true;
  visit_group(r, [&](const b2Contact* other, const ContactRecord& member) {
    const float side = member.identity.body_b == r.identity.body_b ? 1.0f : -1.0f;
    const float along = side * b2Dot(member.tangent(), t);
    // Float tangents of parallel surfaces agree to round-off.
    if (std::abs(along - 1.0f) > 1e-5f) parallel = false;
    const b2Manifold* manifold = other->GetManifold();
    for (int i = 0; i < manifold->pointCount; ++i) {
      normal += manifold->points[i].normalImpulse;
      tangent += along * manifold->points[i].tangentImpulse;
    }
    return parallel;
  });
  if (!parallel || !(normal > 0.0)) return;
  visit_group(r, [&](const b2Contact* other, const ContactRecord& member) {
    const float side = member.identity.body_b == r.identity.body_b ? 1.0f : -1.0f;
    const float along = side * b2Dot(member.tangent(), t) > 0.0f ? 1.0f : -1.0f;
    b2Manifold* manifold = const_cast<b2Contact*>(other)->GetManifold();
    for (int i = 0; i < manifold->pointCount; ++i) {
      manifold->points[i].tangentImpulse = static_cast<float>(along * tangent * manifold->points[i].normalImpulse / normal);
    }
    return true;
  });
}

void FrictionListener::join_group(const b2Contact* contact, ContactRecord& r) {
  visit_group(r, [&](const b2Contact* other, const ContactRecord& member) {
    if (other == contact || member.listener.fresh) return true;
    r.friction = member.friction;
    r.listener.fresh = false;  // its state is the group's, not one judged from its own speed
    return false;
  });
}

void FrictionListener::apply_contact_forces(b2World& world, float h) {
  step_ = h;
  if (!drag_due()) {
    // Most worlds (a pile of boxes, every stick-slip lesson without c or b) owe nothing before
    // a step but the breakaway corrections of the few contacts that broke away in the last
    // one: those alone are visited, in the order the last step found them.
    for (b2Contact* contact : owing_) {
      if (ContactRecord* found = mutable_record(contact)) apply_velocity_terms(contact, *found);
    }
    owing_.clear();
    return;
  }
  // The world's contact list, not the hash map, sets the order: impulses summed in a fixed
  // order keep runs bit-for-bit repeatable.
  owing_.clear();
  drag_pending_ = false;
  for (b2Contact* contact = world.GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    if (!contact->IsTouching()) continue;
    ContactRecord* found = mutable_record(contact);
    if (found != nullptr && !found->listener.fresh) apply_velocity_terms(contact, *found);
  }
}

bool FrictionListener::drag_due() const {
  if (drag_pending_ || run_rule_->explicit_dry_force != nullptr) return true;
  // The table is read through only when it has changed since the last look.
  if (pairs_.revision() != drag_read_at_) {
    pairs_have_drag_ = false;
    const int n = pairs_.material_count();
    for (int index = 0; index < n * n && !pairs_have_drag_; ++index) {
      const FrictionPair& pair = pairs_.pair_at(index);
      const PairTreatment& own = pairs_.treatment_at(index);
      pairs_have_drag_ = pair.c != 0.0 || pair.b != 0.0 || (own.own && rule_of(own.treatment).explicit_dry_force != nullptr);
    }
    drag_read_at_ = pairs_.revision();
  }
  return pairs_have_drag_;
}

namespace {

// A body touching the other through several contacts (a block on feet, one contact a foot)
// slides as one body, as it sticks as one (settle): the pair's drag, c·v + b·v·|v|, is the
// body's, shared between its contacts, not each contact's whole. Each foot taking the whole
// had a block on three feet dragged by 3·c (c 5 N·s/m, 1 kg, 2 N/s: sliding at a third of
// the face's speed, 0.34 m/s against 0.94 after 4 s, and on six feet a sixth). Each
// contact's share is exact for c (the shares' decays multiply to the whole's) and
// first-order for b.
FrictionPair drag_share(const FrictionPair& pair, int siblings) {
  FrictionPair drag = pair;
  if (siblings > 0) {
    drag.c /= siblings + 1;
    drag.b /= siblings + 1;
  }
  return drag;
}

}  // namespace

void FrictionListener::apply_velocity_terms(b2Contact* contact, ContactRecord& r) {
  if (r.identity.unpaired) return;
  const float h = step_;
  const FrictionPair& pair = pairs_.pair_at(r.identity.pair_index);
  const TreatmentRule& rule = rule_at(r.identity.pair_index);
  r.solver.damping_force = 0.0;
  if (r.breakaway.impulse != 0.0) apply_breakaway(contact, r);
  const bool explicit_dry = rule.explicit_dry_force != nullptr;
  if (!explicit_dry && pair.c == 0.0 && pair.b == 0.0) return;

  const int count = contact->GetManifold()->pointCount;
  if (count == 0) return;
  b2WorldManifold manifold;
  contact->GetWorldManifold(&manifold);
  b2Vec2 p{0.0f, 0.0f};
  for (int i = 0; i < count; ++i) p += manifold.points[i];
  p *= 1.0f / static_cast<float>(count);
  const b2Vec2 t = ContactRecord::tangent_of(manifold.normal);
  const bool face = count == 2;
  const float mass = contact_mass(r.identity.body_a, r.identity.body_b, face, p, t);
  if (mass <= 0.0f) return;
  // A contact stick-slip holds stuck does not slide: what its points still move along it is the
  // solver's leftover (a box under a steadily growing push creeps at a steady 2e-4 m/s while
  // held), and drag on that leftover is no part of c·v + b·v·|v|. Taken through the centre of a
  // tall box it held the box back from tipping: with c 979.8 on a 1 kg box, 1.185 m by 2 m,
  // pushed at 1.212 m, 0.044 N at its centre kept 0.011 N of 9.8 N on its back edge in the
  // step past the exact tipping push, and the box tipped a step late.
  if (rule.treatment == FrictionTreatment::stick_slip && !r.listener.fresh && r.friction.state == ContactState::sticking &&
      !explicit_dry) {
    return;
  }
  const double v = sliding_speed(r.identity.body_a, r.identity.body_b, face, p, t);
  const FrictionPair drag = drag_share(pair, r.listener.siblings);
  // Implicit in the velocity: stable and sign-preserving at any h·c/m.
  const double damping_impulse = mass * (damped_velocity(v, mass, h, drag) - v);
  double dry_impulse = 0.0;
  if (explicit_dry) {
    dry_impulse = h * rule.explicit_dry_force(v, r.solver.normal_force, pair, epsilon_at(r.identity.pair_index));
  }
  const double total = damping_impulse + dry_impulse;
  if (total == 0.0) return;
  apply_tangential_impulse(r.identity.body_a, r.identity.body_b, p, t, static_cast<float>(total), face);
  const double mean_velocity = v + 0.5 * total / mass;
  work_.damping += damping_impulse * mean_velocity;
  // The dry force acts like gravity does in Box2D's semi-implicit step (v' = v + h·F/m, then
  // x' = x + h·v'), so its work is counted as gravity's is, on the step's new velocity v':
  // counted on the impulse's own mean velocity it would leave m·(h·F/m)²/2 a step unexplained
  // in the ledger, a third of a creeping block's budget.
  r.listener.explicit_impulse = dry_impulse;
  r.solver.damping_force = damping_impulse / h;
  // Cleared at the next step even if the drag has been switched off by then.
  drag_pending_ = drag_pending_ || r.solver.damping_force != 0.0;
  if (explicit_dry) r.solver.friction_force = dry_impulse / h;
}

void FrictionListener::forget_trial() {
  for (ContactRecord& r : records_) {
    // All as before its first step, but the way it last slipped, which a trial has never
    // reset (only a slip reads it), and the count of its siblings, which still touch.
    const float way = r.friction.slip_direction;
    const int siblings = r.listener.siblings;
    r.friction = FrictionState{};
    r.friction.slip_direction = way;
    r.breakaway = OwedCorrection{};
    r.listener = ListenerNotes{};
    r.listener.siblings = siblings;
  }
  owing_.clear();
  work_ = ContactWork{};
}

ContactWork FrictionListener::take_work() {
  ContactWork done = work_;
  work_ = ContactWork{};
  return done;
}

}  // namespace frictionlab
