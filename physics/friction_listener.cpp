#include "physics/friction_listener.h"

#include <algorithm>
#include <cmath>
#include <string>

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
constexpr double stop_tolerance = 1e-3;

b2Vec2 point_velocity(const b2Body* body, const b2Vec2& world_point) {
  return body->GetLinearVelocityFromWorldPoint(world_point);
}

// The mass the contact's tangential motion feels: what an impulse P along t at p needs to
// change the relative sliding speed by P / m.
float tangential_mass(const b2Body* a, const b2Body* b, const b2Vec2& p, const b2Vec2& t) {
  float inverse = 0.0f;
  for (const b2Body* body : {a, b}) {
    if (body->GetType() != b2_dynamicBody) continue;
    inverse += 1.0f / body->GetMass();
    // A fixed-rotation body (inertia 0) cannot turn, so the lever arm adds nothing.
    const float inertia = central_inertia(body);
    const float arm = b2Cross(p - body->GetWorldCenter(), t);
    if (inertia > 0.0f) inverse += arm * arm / inertia;
  }
  return inverse > 0.0f ? 1.0f / inverse : 0.0f;
}

// The mass a push through both centres of mass feels, rotation aside.
float translational_mass(const b2Body* a, const b2Body* b) {
  float inverse = 0.0f;
  for (const b2Body* body : {a, b}) {
    if (body->GetType() == b2_dynamicBody) inverse += 1.0f / body->GetMass();
  }
  return inverse > 0.0f ? 1.0f / inverse : 0.0f;
}

// On a face (two manifold points) the normal forces redistribute to keep a body from pitching,
// so tangential impulses there move the translational mass and go through the centres of
// mass. Applied at the face instead, their torque would set the body pitching for a step until
// the normal impulses stopped it, and the velocity they leave can even reverse. At a single
// point (a corner, a wheel) rotation is free and the point's own effective mass applies.
float contact_mass(const b2Body* a, const b2Body* b, bool face, const b2Vec2& p, const b2Vec2& t) {
  return face ? translational_mass(a, b) : tangential_mass(a, b, p, t);
}

// The sliding speed the contact's own impulses act on: of the centres of mass on a face (where
// those impulses go through the centres), of the contact point elsewhere.
double sliding_speed(const b2Body* a, const b2Body* b, bool face, const b2Vec2& p, const b2Vec2& t) {
  const b2Vec2 relative = face ? b->GetLinearVelocity() - a->GetLinearVelocity() : point_velocity(b, p) - point_velocity(a, p);
  return b2Dot(relative, t);
}

// The static limit: with mu_k > mu_s a contact pushed past mu_s·N but not mu_k·N would be
// pushed back by kinetic friction the moment it moved, so it cannot start until mu_k·N.
double breakaway_coefficient(const FrictionPair& pair) { return std::max(pair.mu_s, pair.mu_k); }

void apply_tangential_impulse(b2Body* a, b2Body* b, const b2Vec2& p, const b2Vec2& t, float impulse,
                              bool through_centres = false) {
  for (b2Body* body : {b, a}) {
    if (body->GetType() != b2_dynamicBody) continue;
    const b2Vec2 push = (body == b ? impulse : -impulse) * t;
    if (through_centres) {
      body->ApplyLinearImpulseToCenter(push, true);
    } else {
      body->ApplyLinearImpulse(push, p, true);
    }
  }
}

}  // namespace

std::string_view treatment_name(FrictionTreatment treatment) {
  switch (treatment) {
    case FrictionTreatment::stick_slip: return "stick-slip";
    case FrictionTreatment::threshold: return "threshold";
    case FrictionTreatment::regularized: return "regularized";
    case FrictionTreatment::box2d: return "box2d";
  }
  return "?";
}

FrictionTreatment parse_treatment(std::string_view name) {
  for (FrictionTreatment t : {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                              FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    if (name == treatment_name(t)) return t;
  }
  throw InvalidInput("unknown friction treatment '" + std::string(name) +
                     "'; allowed: stick-slip, threshold, regularized, box2d");
}

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
    auto found = records_.find(edge->contact);
    if (found != records_.end()) return &found->second;
  }
  return nullptr;
}

void FrictionListener::BeginContact(b2Contact* contact) {
  ContactRecord record;
  record.body_a = contact->GetFixtureA()->GetBody();
  record.body_b = contact->GetFixtureB()->GetBody();
  record.material_a = fixture_material(contact->GetFixtureA());
  record.material_b = fixture_material(contact->GetFixtureB());
  if (!pairs_.has_pair(record.material_a, record.material_b)) {
    // Throwing here would unwind through Box2D and leave the world locked; the contact is
    // switched off instead and the scene reports the error once the step is over.
    record.unpaired = true;
    if (error_.empty()) {
      auto name = [&](int id) { return id >= 0 && id < pairs_.material_count() ? pairs_.material(id).name : "(no material)"; };
      error_ = "no friction values for the pair " + name(record.material_a) + "–" + name(record.material_b) +
               " that just touched; give every fixture a material whose pairs are set";
    }
  }
  records_[contact] = record;
}

std::string FrictionListener::take_error() {
  std::string error = std::move(error_);
  error_.clear();
  return error;
}

void FrictionListener::EndContact(b2Contact* contact) { records_.erase(contact); }

void FrictionListener::PreSolve(b2Contact* contact, const b2Manifold*) {
  auto found = records_.find(contact);
  if (found == records_.end()) return;
  ContactRecord& r = found->second;
  if (r.unpaired) {
    contact->SetEnabled(false);
    return;
  }
  const FrictionPair& pair = pairs_.pair(r.material_a, r.material_b);
  // A contact born in this step missed apply_contact_forces: its drag starts now, before the
  // solve, so a block landing on a viscous film is not let off for a step.
  if (r.fresh) apply_velocity_terms(contact, r);

  b2WorldManifold manifold;
  contact->GetWorldManifold(&manifold);
  r.point_count = contact->GetManifold()->pointCount;
  r.normal = manifold.normal;
  const b2Vec2 t = ContactRecord::tangent_of(r.normal);
  float sliding = 0.0f;
  r.point.SetZero();
  for (int i = 0; i < r.point_count; ++i) {
    r.world_points[i] = manifold.points[i];
    r.start_velocity[i] = point_velocity(r.body_b, manifold.points[i]) - point_velocity(r.body_a, manifold.points[i]);
    sliding += b2Dot(r.start_velocity[i], t);
    r.point += manifold.points[i];
  }
  if (r.point_count > 0) {
    sliding /= static_cast<float>(r.point_count);
    r.point *= 1.0f / static_cast<float>(r.point_count);
  }
  const bool slow = std::abs(sliding) < threshold_speed_;
  switch (treatment_) {
    case FrictionTreatment::stick_slip:
      if (r.fresh && std::abs(sliding) > birth_sliding_speed) {
        r.state = ContactState::slipping;
        r.slip_direction = sign(sliding);
      }
      contact->SetFriction(static_cast<float>(r.state == ContactState::sticking ? breakaway_coefficient(pair) : pair.mu_k));
      break;
    case FrictionTreatment::threshold:
      r.state = slow ? ContactState::sticking : ContactState::slipping;
      contact->SetFriction(static_cast<float>(slow ? pair.mu_s : pair.mu_k));
      break;
    case FrictionTreatment::regularized:
      r.state = slow ? ContactState::sticking : ContactState::slipping;
      contact->SetFriction(0.0f);  // the dry force is applied explicitly in apply_contact_forces
      break;
    case FrictionTreatment::box2d:
      contact->SetFriction(static_cast<float>(pair.mu_k));
      break;
  }
  r.fresh = false;
}

void FrictionListener::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) {
  auto found = records_.find(contact);
  if (found == records_.end() || found->second.unpaired) return;
  ContactRecord& r = found->second;
  const FrictionPair& pair = pairs_.pair(r.material_a, r.material_b);
  const b2Vec2 n = r.normal;
  const b2Vec2 t = ContactRecord::tangent_of(n);
  const bool a_driven = r.body_a->GetType() == b2_kinematicBody;
  const bool b_driven = r.body_b->GetType() == b2_kinematicBody;

  double normal_impulse = 0.0;
  double tangent_impulse = 0.0;
  float sliding_end = 0.0f;
  const int count = std::min(r.point_count, impulse->count);
  for (int i = 0; i < count; ++i) {
    const b2Vec2 p = r.world_points[i];
    const b2Vec2 end_velocity = point_velocity(r.body_b, p) - point_velocity(r.body_a, p);
    const b2Vec2 mean_velocity = 0.5f * (r.start_velocity[i] + end_velocity);
    const float jn = impulse->normalImpulses[i];
    const float jt = impulse->tangentImpulses[i];
    // An impulse changes kinetic energy by itself times the mean of the velocities before
    // and after it: exact for the solver's sequence of impulses, so the ledger closes.
    work_.friction += jt * b2Dot(mean_velocity, t);
    work_.impacts += jn * b2Dot(mean_velocity, n);
    const b2Vec2 on_b = jn * n + jt * t;
    if (a_driven) work_.drivers += b2Dot(on_b, point_velocity(r.body_a, p));
    if (b_driven) work_.drivers -= b2Dot(on_b, point_velocity(r.body_b, p));
    r.point_normal_force[i] = jn / step_;
    normal_impulse += jn;
    tangent_impulse += jt;
    sliding_end += b2Dot(end_velocity, t);
  }
  if (count > 0) sliding_end /= static_cast<float>(count);
  r.normal_force = normal_impulse / step_;
  if (treatment_ != FrictionTreatment::regularized) r.friction_force = tangent_impulse / step_;
  r.sliding_velocity = sliding_end;

  if (normal_impulse <= 0.0) return;  // no load, no evidence either way: keep the state
  // A body standing on several feet touches the floor through several contacts. Being rigid,
  // it sticks or slides as a whole: its feet share one static limit, mu_s times their total
  // load, however the load happens to be split between them (which statics cannot decide for
  // three feet in a row, and the solver decides its own way). So the state is judged from the
  // totals over every contact between the two bodies; with one contact nothing changes.
  double group_normal = normal_impulse, group_tangent = tangent_impulse;
  sum_sibling_impulses(contact, t, &group_normal, &group_tangent);
  const double reached = std::abs(group_tangent) / group_normal;
  switch (treatment_) {
    case FrictionTreatment::stick_slip:
      if (r.state == ContactState::sticking) {
        if (reached >= breakaway_coefficient(pair) * (1.0 - breakaway_tolerance)) {
          r.state = ContactState::slipping;
          // Friction on B opposes B's sliding, so an unmoved contact slides against it.
          r.slip_direction = sliding_end != 0.0f ? sign(sliding_end) : -sign(static_cast<float>(tangent_impulse));
          r.breakaway_impulse = r.slip_direction * breakaway_correction(r, pair, normal_impulse, sliding_end);
        } else {
          r.held_force = std::abs(tangent_impulse) / step_;
        }
      } else {
        const bool held = reached < pair.mu_k * (1.0 - stop_tolerance);
        const bool reversed = sign(sliding_end) == -r.slip_direction;
        if (held || reversed) r.state = ContactState::sticking;
      }
      break;
    case FrictionTreatment::box2d:
      r.state = reached >= pair.mu_k * (1.0 - stop_tolerance) ? ContactState::slipping : ContactState::sticking;
      break;
    case FrictionTreatment::threshold:
    case FrictionTreatment::regularized:
      break;
  }
}

void FrictionListener::sum_sibling_impulses(const b2Contact* contact, const b2Vec2& t, double* normal,
                                            double* tangent) const {
  const b2Body* a = contact->GetFixtureA()->GetBody();
  const b2Body* b = contact->GetFixtureB()->GetBody();
  for (const b2ContactEdge* edge = b->GetContactList(); edge != nullptr; edge = edge->next) {
    const b2Contact* other = edge->contact;
    if (other == contact || edge->other != a || !other->IsTouching() || !other->IsEnabled()) continue;
    // Box2D keeps each point's accumulated impulses in the manifold for warm starting; they are
    // stored before any contact's PostSolve is called. Along this contact's tangent, and with
    // the same sign convention (on the body that is this contact's B).
    const b2Manifold* manifold = other->GetManifold();
    b2WorldManifold world;
    other->GetWorldManifold(&world);
    const float side = other->GetFixtureB()->GetBody() == b ? 1.0f : -1.0f;
    const b2Vec2 other_t = ContactRecord::tangent_of(world.normal);
    for (int i = 0; i < manifold->pointCount; ++i) {
      *normal += manifold->points[i].normalImpulse;
      *tangent += side * manifold->points[i].tangentImpulse * b2Dot(other_t, t);
    }
  }
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
double FrictionListener::breakaway_correction(const ContactRecord& r, const FrictionPair& pair,
                                              double normal_impulse, float sliding_end) const {
  const double h = step_;
  const double mass = contact_mass(r.body_a, r.body_b, r.point_count == 2, r.point, r.tangent());
  const double normal_force = normal_impulse / h;
  const double excess = mass * std::abs(sliding_end) / h;
  const double growth = (breakaway_coefficient(pair) * normal_force + excess - r.held_force) / h;
  const double late = growth > 0.0 ? std::clamp(excess / growth, 0.0, h) : 0.5 * h;
  return (breakaway_coefficient(pair) - pair.mu_k) * normal_force * (late + 0.5 * h);
}

void FrictionListener::apply_contact_forces(b2World& world, float h) {
  step_ = h;
  // The world's contact list, not the hash map, sets the order: impulses summed in a fixed
  // order keep runs bit-for-bit repeatable.
  for (b2Contact* contact = world.GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    if (!contact->IsTouching()) continue;
    auto found = records_.find(contact);
    if (found != records_.end() && !found->second.fresh) apply_velocity_terms(contact, found->second);
  }
}

void FrictionListener::apply_velocity_terms(b2Contact* contact, ContactRecord& r) {
  if (r.unpaired) return;
  const float h = step_;
  const FrictionPair& pair = pairs_.pair(r.material_a, r.material_b);
  r.damping_force = 0.0;
  if (r.breakaway_impulse != 0.0) {
    const b2Vec2 t = r.tangent();
    const bool face = r.point_count == 2;
    const double mass = contact_mass(r.body_a, r.body_b, face, r.point, t);
    const double v = sliding_speed(r.body_a, r.body_b, face, r.point, t);
    apply_tangential_impulse(r.body_a, r.body_b, r.point, t, static_cast<float>(r.breakaway_impulse), face);
    if (mass > 0.0) work_.friction += r.breakaway_impulse * (v + 0.5 * r.breakaway_impulse / mass);
    r.breakaway_impulse = 0.0;
  }
  const bool explicit_dry = treatment_ == FrictionTreatment::regularized;
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
  const float mass = contact_mass(r.body_a, r.body_b, face, p, t);
  if (mass <= 0.0f) return;
  const double v = sliding_speed(r.body_a, r.body_b, face, p, t);

  // Implicit in the velocity: stable and sign-preserving at any h·c/m.
  const double damping_impulse = mass * (damped_velocity(v, mass, h, pair) - v);
  double dry_impulse = 0.0;
  if (explicit_dry) {
    const FrictionPair dry{pair.mu_s, pair.mu_k, 0.0, 0.0};
    dry_impulse = h * regularized_friction(v, r.normal_force, threshold_speed_, dry);
  }
  const double total = damping_impulse + dry_impulse;
  if (total == 0.0) return;
  apply_tangential_impulse(r.body_a, r.body_b, p, t, static_cast<float>(total), face);
  const double mean_velocity = v + 0.5 * total / mass;
  work_.damping += damping_impulse * mean_velocity;
  work_.friction += dry_impulse * mean_velocity;
  r.damping_force = damping_impulse / h;
  if (explicit_dry) r.friction_force = dry_impulse / h;
}

void FrictionListener::forget_trial() {
  for (auto& [contact, r] : records_) {
    r.fresh = true;
    r.state = ContactState::sticking;
    r.breakaway_impulse = 0.0;
    r.held_force = 0.0;
  }
  work_ = ContactWork{};
}

ContactWork FrictionListener::take_work() {
  ContactWork done = work_;
  work_ = ContactWork{};
  return done;
}

}  // namespace frictionlab
