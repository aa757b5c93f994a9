#include "physics/scene.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "physics/validation.h"

namespace frictionlab {
namespace {

b2Vec2 world_point(const b2Body* body, const b2Vec2& local) { return body->GetWorldPoint(local); }

// What a user's function of time returns is checked before Box2D sees it: a NaN there would
// spread through the world, and a non-finite transform makes Box2D abort. The description is
// built only on failure: this runs for every spring, force and driver at every step.
template <typename Describe>
b2Vec2 checked(b2Vec2 value, double t, Describe describe) {
  if (!std::isfinite(value.x) || !std::isfinite(value.y) || std::abs(value.x) > 1e9f || std::abs(value.y) > 1e9f) {
    std::ostringstream message;
    message << describe() << " at t = " << t << " s is (" << value.x << ", " << value.y
            << "); each part must be finite and within ±1e9";
    throw InvalidInput(message.str());
  }
  return value;
}

template <typename Describe>
double checked(double value, double t, Describe describe) {
  return checked(b2Vec2{static_cast<float>(value), 0.0f}, t, describe).x;
}

}  // namespace

double Motion::at(double t) const { return offset + t * (speed + 0.5 * acceleration * t) + swing * std::sin(omega * t + phase); }

void validate(const StepSettings& s) {
  using validation::require_in_range;
  require_in_range("hz", s.hz, 1.0, 100000.0, false, " Hz");
  require_in_range("substeps", s.substeps, 1, 1000, false, "");
  require_in_range("velocity iterations", s.velocity_iterations, 1, 1000, false, "");
  require_in_range("position iterations", s.position_iterations, 0, 1000, false, "");
  require_in_range("threshold speed", s.threshold_speed, 0.0, 100.0, true, " m/s");
}

void Scene::set_velocity_iterations(int count) {
  StepSettings changed = settings_;
  changed.velocity_iterations = count;
  validate(changed);
  settings_ = changed;
}

Scene::Scene(PairTable pairs, StepSettings settings, b2Vec2 gravity)
    : pairs_(std::move(pairs)), settings_(settings), gravity_(gravity), listener_(pairs_) {
  validate(settings_);
  validation::require_in_range("gravity x", gravity.x, -1000.0, 1000.0, false, " m/s²");
  validation::require_in_range("gravity y", gravity.y, -1000.0, 1000.0, false, " m/s²");
  world_ = std::make_unique<b2World>(gravity_);
  world_->SetContactListener(&listener_);
  // A resting block must keep feeling its spring and its friction, and a time-of-impact
  // sub-step would report a second solve to the listener inside one step.
  world_->SetAllowSleeping(false);
  world_->SetContinuousPhysics(false);
  listener_.set_treatment(settings_.treatment);
  listener_.set_threshold_speed(settings_.threshold_speed);
}

void Scene::check_new_name(const std::string& name) const {
  if (name.empty()) throw InvalidInput("body: the name must not be empty");
  for (const auto& [known, body] : bodies_) {
    if (known == name) throw InvalidInput("body '" + name + "': there is already a body of that name; give each its own");
  }
}

void Scene::check_placement(const std::string& name, b2Vec2 position, float angle) const {
  // Box2D asserts (and aborts) on a non-finite transform; far away its floats lose the
  // millimetres that friction lives in.
  using validation::require_in_range;
  require_in_range("body '" + name + "': x", position.x, -1e5, 1e5, false, " m");
  require_in_range("body '" + name + "': y", position.y, -1e5, 1e5, false, " m");
  require_in_range("body '" + name + "': angle", angle, -1e4, 1e4, false, " rad");
}

b2Body* Scene::add_body(const std::string& name, const b2BodyDef& definition) {
  check_new_name(name);
  check_placement(name, definition.position, definition.angle);
  using validation::require_in_range;
  require_in_range("body '" + name + "': speed x", definition.linearVelocity.x, -1e4, 1e4, false, " m/s");
  require_in_range("body '" + name + "': speed y", definition.linearVelocity.y, -1e4, 1e4, false, " m/s");
  require_in_range("body '" + name + "': spin", definition.angularVelocity, -1e4, 1e4, false, " rad/s");
  require_in_range("body '" + name + "': linear damping", definition.linearDamping, 0.0, 1e4, false, " 1/s");
  require_in_range("body '" + name + "': angular damping", definition.angularDamping, 0.0, 1e4, false, " 1/s");
  require_in_range("body '" + name + "': gravity scale", definition.gravityScale, -100.0, 100.0, false, "");
  b2Body* created = world_->CreateBody(&definition);
  bodies_.emplace_back(name, created);
  rest_.push_back({definition.position, definition.angle, 0});
  return created;
}

int Scene::check_material(const std::string& material, b2BodyType type) const {
  const int id = pairs_.material_id(material);
  // Box2D only makes contacts where at least one body is dynamic: a floor and a fixed wedge
  // of different materials need no pair values between them.
  for (const MaterialUse& other : materials_in_use_) {
    if ((type == b2_dynamicBody || other.on_dynamic) && !pairs_.has_pair(id, other.id)) {
      throw InvalidInput("no friction values for the pair " + material + "–" + pairs_.material(other.id).name +
                         ", and both are in the scene where they can touch; set them before adding the body");
    }
  }
  return id;
}

bool Scene::can_touch(const std::string& material_a, const std::string& material_b) const {
  const int a = pairs_.find_material(material_a), b = pairs_.find_material(material_b);
  const MaterialUse* use_a = nullptr;
  const MaterialUse* use_b = nullptr;
  for (const MaterialUse& use : materials_in_use_) {
    if (use.id == a) use_a = &use;
    if (use.id == b) use_b = &use;
  }
  if (use_a == nullptr || use_b == nullptr || !(use_a->on_dynamic || use_b->on_dynamic)) return false;
  // A material meets itself only on two bodies: one metal block on a wooden floor has no
  // metal-on-metal contact, and its sliders would change nothing.
  return a != b || use_a->bodies >= 2;
}

b2Fixture* Scene::add_fixture(b2Body* body, const b2Shape& shape, const std::string& material) {
  const int id = check_material(material, body->GetType());
  b2FixtureDef definition;
  definition.shape = &shape;
  definition.density = static_cast<float>(pairs_.material(id).density);
  definition.friction = 0.0f;  // the listener sets every contact's coefficient
  definition.userData.pointer = static_cast<uintptr_t>(id + 1);
  auto use = std::find_if(materials_in_use_.begin(), materials_in_use_.end(),
                          [id](const MaterialUse& in_use) { return in_use.id == id; });
  if (use == materials_in_use_.end()) use = materials_in_use_.insert(materials_in_use_.end(), {id, false});
  use->on_dynamic = use->on_dynamic || body->GetType() == b2_dynamicBody;
  if (use->last_body != body) {
    ++use->bodies;
    use->last_body = body;
  }
  return body->CreateFixture(&definition);
}

b2Body* Scene::add_box(const std::string& name, b2BodyType type, const std::string& material, b2Vec2 center,
                       float width, float height, float angle, float skin) {
  // Box2D wraps every polygon in a 1 cm skin; a box much thinner than two skins is all skin.
  // The least size as a float, so that 0.02 given in double and rounded down to float passes.
  constexpr double least = static_cast<double>(0.02f);
  validation::require_in_range("box '" + name + "': width", width, least, 1000.0, false, " m");
  validation::require_in_range("box '" + name + "': height", height, least, 1000.0, false, " m");
  // Everything is checked before the body exists, so a refused box leaves nothing behind.
  check_new_name(name);
  check_placement(name, center, angle);
  check_material(material, type);
  b2BodyDef definition;
  definition.type = type;
  definition.position = center;
  definition.angle = angle;
  b2Body* created = add_body(name, definition);
  b2PolygonShape box;
  box.SetAsBox(0.5f * width, 0.5f * height);
  box.m_radius = skin;
  add_fixture(created, box, material);
  return created;
}

void set_mass_from_surfaces(b2Body* body) {
  if (body->GetType() != b2_dynamicBody) return;
  b2MassData total{0.0f, {0.0f, 0.0f}, 0.0f};
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    b2MassData part{};
    if (fixture->GetType() == b2Shape::e_circle) {
      b2CircleShape surface = *static_cast<const b2CircleShape*>(fixture->GetShape());
      surface.m_radius = surface_radius(surface);
      surface.ComputeMass(&part, fixture->GetDensity());
    } else {
      fixture->GetShape()->ComputeMass(&part, fixture->GetDensity());  // a polygon's skin has no mass
    }
    total.mass += part.mass;
    total.center += part.mass * part.center;
    total.I += part.I;
  }
  if (total.mass > 0.0f) total.center *= 1.0f / total.mass;
  body->SetMassData(&total);
}

b2Body* Scene::body(const std::string& name) const {
  for (const auto& [body_name, body] : bodies_) {
    if (body_name == name) return body;
  }
  std::string known;
  for (const auto& [body_name, body] : bodies_) known += " " + body_name;
  throw InvalidInput("unknown body '" + name + "'; bodies in this scene:" + known);
}

std::size_t Scene::add_rope(const std::string& name, b2Body* a, b2Vec2 end_a, b2Body* b, b2Vec2 end_b,
                            b2Vec2 pulley_a, b2Vec2 pulley_b) {
  Rope rope;
  rope.name = name;
  rope.body_a = a;
  rope.body_b = b;
  rope.local_a = a->GetLocalPoint(end_a);
  rope.local_b = b->GetLocalPoint(end_b);
  rope.pulley_a = pulley_a;
  rope.pulley_b = pulley_b;
  rope.length = rope.stretches();
  tie(rope);
  ropes_.push_back(rope);
  return ropes_.size() - 1;
}

void Scene::tie(Rope& rope) {
  b2PulleyJointDef definition;
  definition.bodyA = rope.body_a;
  definition.bodyB = rope.body_b;
  definition.groundAnchorA = rope.pulley_a;
  definition.groundAnchorB = rope.pulley_b;
  definition.localAnchorA = rope.local_a;
  definition.localAnchorB = rope.local_b;
  // The rope's own length, however far past it the ends have gone: the joint pulls them back.
  definition.lengthA = (rope.end_a() - rope.pulley_a).Length();
  definition.lengthB = rope.length - definition.lengthA;
  definition.ratio = 1.0f;
  rope.joint = static_cast<b2PulleyJoint*>(world_->CreateJoint(&definition));
}

namespace {

// Whether something the body touches holds it against being pushed along `push` (a floor under
// a landed weight that the rope pressed down): that contact took the push, not the body. By
// direction alone: a light weight's small push is held as surely as a heavy one's.
bool held_against(const b2Body* body, b2Vec2 push) {
  if (push.Normalize() <= 0.0f) return false;
  for (const b2ContactEdge* edge = body->GetContactList(); edge != nullptr; edge = edge->next) {
    const b2Contact* contact = edge->contact;
    if (!contact->IsTouching() || !contact->IsEnabled()) continue;
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    // Box2D's normal points from A to B: onto the body when it is B.
    const b2Vec2 onto = contact->GetFixtureB()->GetBody() == body ? manifold.normal : -manifold.normal;
    if (b2Dot(onto, push) < -0.5f) return true;  // within 60° of straight against it
  }
  return false;
}

// Takes back from a body the impulse `p` (N·s) it was given at `point` in the last step, unless
// a contact held it against it; returns the kinetic energy that gives back, J. The velocities
// only: the step already moved the body by h times what is taken back, and the arm is the one
// at the step's end, not its start; both differ by one step's worth.
double take_back(b2Body* body, b2Vec2 point, b2Vec2 p) {
  if (body->GetType() != b2_dynamicBody || held_against(body, p)) return 0.0;
  const double before = kinetic_energy(body);
  body->ApplyLinearImpulse(-p, point, true);
  return kinetic_energy(body) - before;
}

// The unit vector from the pulley to a rope's end (zero when they meet).
b2Vec2 outward(b2Vec2 pulley, b2Vec2 end) {
  b2Vec2 d = end - pulley;
  return d.Normalize() > 0.0f ? d : b2Vec2{0.0f, 0.0f};
}

// How fast a rope's two ends draw apart (m/s), each along its stretch from the pulley.
float parting_speed(const Rope& rope) {
  const auto along = [](const b2Body* body, b2Vec2 end, b2Vec2 pulley) {
    return b2Dot(body->GetLinearVelocityFromWorldPoint(end), outward(pulley, end));
  };
  return along(rope.body_a, rope.end_a(), rope.pulley_a) + along(rope.body_b, rope.end_b(), rope.pulley_b);
}

// The joint's last step along the rope: positive when it pulled the ends towards the pulley.
// Box2D reports the size along the stretch from the pulley to the end on body B.
float signed_pull(const Rope& rope, float inv_dt) {
  const b2Vec2 reaction = rope.joint->GetReactionForce(inv_dt);
  return b2Dot(reaction, rope.end_b() - rope.pulley_b) >= 0.0f ? reaction.Length() : -reaction.Length();
}

}  // namespace

double Scene::rope_tension(std::size_t index) const {
  const Rope& rope = ropes_.at(index);
  if (rope.joint == nullptr) return 0.0;
  return signed_pull(rope, static_cast<float>(settings_.hz * settings_.substeps));
}

void Scene::slacken_or_tie_ropes() {
  for (Rope& rope : ropes_) {
    const b2Vec2 out_a = outward(rope.pulley_a, rope.end_a()), out_b = outward(rope.pulley_b, rope.end_b());
    if (rope.joint != nullptr) {
      // The step's impulse, positive when the rope pulled each end towards the pulley.
      const float impulse = signed_pull(rope, 1.0f);
      if (impulse >= 0.0f) {
        // A pull does work on the ends as they part: none while the rope keeps its length, a
        // loss when it jerks taut (the impulse times the mean of the parting speeds before and
        // after it, as the contacts' impacts are booked).
        ledger_.work_impacts -= impulse * 0.5 * (rope.parting_before + parting_speed(rope));
        continue;
      }
      // It pushed each end away from the pulley with -impulse: a rope cannot. What the push did
      // to the ends is undone, and the energy that gives back books against the impacts that
      // the push made the contacts absorb (a landing weight stopped the block through the rope).
      ledger_.work_impacts += take_back(rope.body_a, rope.end_a(), -impulse * out_a);
      ledger_.work_impacts += take_back(rope.body_b, rope.end_b(), -impulse * out_b);
      world_->DestroyJoint(rope.joint);
      rope.joint = nullptr;
      continue;
    }
    // Slack: taut again once the ends are as far apart as the rope is long and still parting.
    if (rope.stretches() >= rope.length && parting_speed(rope) > 0.0f) tie(rope);
  }
}

void Scene::add_spring(const Spring& spring) {
  if (spring.body == nullptr) throw InvalidInput("spring '" + spring.name + "': it must be attached to a body");
  if (spring.other == nullptr && !spring.hand) {
    throw InvalidInput("spring '" + spring.name + "': its far end needs a body or a hand");
  }
  validation::require_in_range("spring '" + spring.name + "': stiffness k", spring.stiffness, 0.0, 1e9, true, " N/m");
  validation::require_in_range("spring '" + spring.name + "': rest length", spring.rest_length, 0.0, 1e4, false, " m");
  // The spring force is explicit: it stays stable only while h·sqrt(k/m) < 2, with m the mass
  // it moves (the reduced mass between two bodies).
  double inverse_mass = 0.0;
  for (const b2Body* end : {spring.body, spring.other}) {
    if (end != nullptr && end->GetType() == b2_dynamicBody && end->GetMass() > 0.0f) inverse_mass += 1.0 / end->GetMass();
  }
  if (inverse_mass > 0.0) {
    const double h = frame_step() / settings_.substeps;
    const double limit = 4.0 / (inverse_mass * h * h);
    if (spring.stiffness >= limit) {
      std::ostringstream message;
      message << "spring '" << spring.name << "': stiffness k = " << spring.stiffness
              << " N/m is too stiff for the step h = " << h << " s; an explicit spring on "
              << 1.0 / inverse_mass << " kg is stable only for k < 4·m/h² = " << limit
              << " N/m (raise hz or substeps, or soften the spring)";
      throw InvalidInput(message.str());
    }
  }
  springs_.push_back(spring);
  spring_forces_applied_.push_back({0.0f, 0.0f});
}

void Scene::add_applied_force(const AppliedForce& force) {
  if (force.body == nullptr || (!force.force && !force.torque)) {
    throw InvalidInput("applied force '" + force.name + "': it needs a body and a force or a torque");
  }
  applied_.push_back(force);
  if (!applied_.back().force) applied_.back().force = [](double) { return b2Vec2{0.0f, 0.0f}; };
  forces_applied_.push_back({0.0f, 0.0f});
  torques_applied_.push_back(0.0);
}

namespace {
constexpr const char* grab_name = "hand (mouse)";
}

void Scene::grab(b2Body* body, b2Vec2 local_point, b2Vec2 target) {
  if (body == nullptr || body->GetType() != b2_dynamicBody) {
    throw InvalidInput("grab: only a body that moves freely (dynamic) can be taken by the hand");
  }
  release();
  // The gauge starts slack: its far end where the hand took hold.
  grab_ = std::make_unique<Grab>(Grab{body, target, body->GetWorldPoint(local_point)});
  applied_.push_back({grab_name, body, local_point, {}});
  applied_.back().force = [this, index = applied_.size() - 1](double) { return grab_force(applied_[index]); };
  forces_applied_.push_back({0.0f, 0.0f});
  torques_applied_.push_back(0.0);
}

void Scene::move_grab(b2Vec2 target) {
  if (grab_) grab_->target = target;
}

void Scene::release() {
  if (!grab_) return;
  grab_.reset();
  // The hand is always the last applied force: it is added last and removed before another.
  applied_.pop_back();
  forces_applied_.pop_back();
  torques_applied_.pop_back();
}

double Scene::grab_omega() const {
  const double h = frame_step() / settings_.substeps;
  return std::min(2.0 * b2_pi * grab_gauge_hz, 0.5 / h);
}

double Scene::grab_stiffness() const {
  if (!grab_) return 0.0;
  const double omega = grab_omega();
  return static_cast<double>(grab_->body->GetMass()) * omega * omega;
}

b2Vec2 Scene::grab_force(const AppliedForce& hand) const {
  const b2Body& body = *hand.body;
  const b2Vec2 point = body.GetWorldPoint(hand.local_point);
  const b2Vec2 velocity = body.GetLinearVelocityFromWorldPoint(point);
  // Damped against the body's own velocity, not the stretch's rate: the hand's end moves in
  // bursts as the mouse is read once a display frame, and a damper on its speed would put each
  // burst into the reading. A body held still (stuck) feels the spring alone, so the reading
  // rises smoothly to static friction's limit.
  const double omega = grab_omega();
  const double mass = body.GetMass();
  b2Vec2 force = static_cast<float>(mass * omega * omega) * (grab_->hand - point) -
                 static_cast<float>(2.0 * grab_damping_ratio * mass * omega) * velocity;
  const double cap = 20.0 * mass * gravity_.Length();
  if (cap > 0.0 && force.Length() > cap) force *= static_cast<float>(cap / force.Length());
  return force;
}

void Scene::set_velocity(b2Body* body, b2Vec2 velocity) {
  // A script may call this every step: the body's name is looked up only for a message.
  if (body == nullptr || body->GetType() != b2_dynamicBody) {
    throw InvalidInput("body '" + name_of(body) + "': only a body that moves freely (dynamic) has a velocity to set");
  }
  using validation::in_range;
  using validation::require_in_range;
  if (!in_range(velocity.x, -1e4, 1e4, false) || !in_range(velocity.y, -1e4, 1e4, false)) {
    require_in_range("body '" + name_of(body) + "': velocity x", velocity.x, -1e4, 1e4, false, " m/s");
    require_in_range("body '" + name_of(body) + "': velocity y", velocity.y, -1e4, 1e4, false, " m/s");
  }
  const b2Vec2 before = body->GetLinearVelocity();
  body->SetLinearVelocity(velocity);
  // Booked with the very formula mechanical_energy() uses, so the residual does not move; the
  // ledger's kinetic line follows at once, so the panel adds up between frames too.
  const double change = 0.5 * static_cast<double>(body->GetMass()) *
                        (static_cast<double>(b2Dot(velocity, velocity)) - static_cast<double>(b2Dot(before, before)));
  ledger_.work_script += change;
  if (ledger_started_) ledger_.kinetic += change;
}

namespace {
bool same(const b2Transform& a, const b2Transform& b) {
  return a.p.x == b.p.x && a.p.y == b.p.y && a.q.s == b.q.s && a.q.c == b.q.c;
}
}  // namespace

bool Scene::touching_now(b2Contact* contact) const {
  // A contact the solver pressed in the step just taken still touches at its end: a positive
  // normal impulse means the solver held the two bodies with no normal relative speed, so the
  // step left them where they touched, up to the position correction's slop, well inside the
  // margin within which Box2D's collision keeps points. Only an unloaded contact may have come
  // apart, and only that one is collided again. (Touching at the step's start, the contact was
  // solved in it, so its record's normal force is this step's.)
  if (contact->IsTouching()) {
    const ContactRecord* record = listener_.record(contact);
    if (record != nullptr && record->solver.normal_force > 0.0) return true;
  }
  if (touching_checked_at_ != world_steps_) {
    touching_before_.swap(touching_);
    touching_.clear();
    touching_checked_at_ = world_steps_;
  }
  for (const Touching& known : touching_) {
    if (known.contact == contact) return known.touching;
  }
  const b2Fixture* fixture_a = contact->GetFixtureA();
  const b2Fixture* fixture_b = contact->GetFixtureB();
  const int child_a = contact->GetChildIndexA(), child_b = contact->GetChildIndexB();
  const b2Transform& transform_a = fixture_a->GetBody()->GetTransform();
  const b2Transform& transform_b = fixture_b->GetBody()->GetTransform();
  for (const Touching& known : touching_before_) {
    if (known.contact == contact && known.fixture_a == fixture_a && known.fixture_b == fixture_b &&
        known.child_a == child_a && known.child_b == child_b && same(known.transform_a, transform_a) &&
        same(known.transform_b, transform_b)) {
      touching_.push_back(known);
      return known.touching;
    }
  }
  b2Manifold now;
  contact->Evaluate(&now, transform_a, transform_b);
  touching_.push_back({contact, fixture_a, fixture_b, child_a, child_b, transform_a, transform_b, now.pointCount > 0});
  return now.pointCount > 0;
}

void Scene::drive(b2Body* body, PointOfTime position, ScalarOfTime angle) {
  if (body == nullptr || body->GetType() != b2_kinematicBody) {
    throw InvalidInput("drive: only a kinematic body can be moved by a function of time");
  }
  drivers_.push_back({body, std::move(position), std::move(angle)});
}

void Scene::add_probe(const std::string& name, std::function<double()> measure) {
  for (const Probe& probe : probes_) {
    if (probe.name == name) throw InvalidInput("probe '" + name + "': there is already a probe of that name; give each its own");
  }
  probes_.push_back({name, std::move(measure), {}});
}

std::string Scene::name_of(const b2Body* body) const {
  for (const auto& [name, known] : bodies_) {
    if (known == body) return name;
  }
  return "(unnamed)";
}

const Probe& Scene::probe(const std::string& name) const {
  for (const Probe& p : probes_) {
    if (p.name == name) return p;
  }
  std::string known;
  for (const Probe& p : probes_) known += (known.empty() ? " " : ", ") + p.name;
  throw InvalidInput("unknown probe '" + name + "'; probes in this scene:" + (known.empty() ? " none" : known));
}

b2Vec2 Scene::hand_position(const Spring& spring) const {
  return spring.other ? world_point(spring.other, spring.other_local_point) : spring.hand(time_);
}

b2Vec2 Scene::spring_force(const Spring& spring) const {
  const b2Vec2 from = world_point(spring.body, spring.local_point);
  const b2Vec2 to = hand_position(spring);
  b2Vec2 along = to - from;
  const float length = along.Normalize();
  return static_cast<float>(spring.stiffness * (length - spring.rest_length)) * along;
}

void Scene::mechanical_energy(double* kinetic, double* potential, double* elastic) const {
  double k = 0.0, p = 0.0, s = 0.0;
  for (const b2Body* body = world_->GetBodyList(); body != nullptr; body = body->GetNext()) {
    if (body->GetType() != b2_dynamicBody) continue;
    k += kinetic_energy(body);
    p -= static_cast<double>(body->GetMass()) * b2Dot(gravity_, body->GetWorldCenter());
  }
  for (const Spring& spring : springs_) {
    const double stretch = (hand_position(spring) - world_point(spring.body, spring.local_point)).Length() -
                           spring.rest_length;
    s += 0.5 * spring.stiffness * stretch * stretch;
  }
  *kinetic = k;
  *potential = p;
  *elastic = s;
}

void Scene::update_ledger_state() {
  double potential = 0.0;
  mechanical_energy(&ledger_.kinetic, &potential, &ledger_.spring);
  if (!ledger_started_) {
    ledger_started_ = true;
    ledger_.potential_reference = potential;
    ledger_.initial = ledger_.kinetic + ledger_.spring;
  }
  ledger_.potential = potential - ledger_.potential_reference;
}

void Scene::start(float h) {
  // Box2D integrates leapfrog-style: x(t+h) = x(t) + h·v, with v the velocity of the middle
  // of the step, so the velocity it starts from belongs to t = -h/2, not t = 0. Given as
  // v(0), a launched block stops v0·h/2 short: an O(h) error in an otherwise second-order
  // scheme. The usual leapfrog start fixes it: v(-h/2) = v(0) - (h/2)·a(0). The acceleration
  // is found by a trial half step (friction, springs and all), after which the bodies are put
  // back. A body at rest at t = 0 is taken to have been held until then, so it keeps v = 0.
  struct Launch {
    b2Body* body;
    b2Vec2 velocity;
    float spin;
  };
  std::vector<Launch> launches;
  for (b2Body* body = world_->GetBodyList(); body != nullptr; body = body->GetNext()) {
    if (body->GetType() == b2_dynamicBody) launches.push_back({body, body->GetLinearVelocity(), body->GetAngularVelocity()});
  }
  advance(0.0, 0.5f * h, 0.5 * frame_step() / settings_.substeps, false);
  for (const Launch& launch : launches) {
    const bool moving = launch.velocity.LengthSquared() > 0.0f || launch.spin != 0.0f;
    launch.body->SetLinearVelocity(moving ? 2.0f * launch.velocity - launch.body->GetLinearVelocity() : launch.velocity);
    launch.body->SetAngularVelocity(moving ? 2.0f * launch.spin - launch.body->GetAngularVelocity() : launch.spin);
  }
  listener_.forget_trial();
  ledger_ = EnergyLedger{};
  update_ledger_state();
}

void Scene::step() {
  const float h = static_cast<float>(frame_step() / settings_.substeps);
  if (!ledger_started_) start(h);
  for (int i = 0; i < settings_.substeps; ++i) {
    time_ = (static_cast<double>(frame_) + static_cast<double>(i) / settings_.substeps) * frame_step();
    // The end of the sub-step in double: t + h in float would ask for a time a hair off the
    // next one, and functions of time would be asked twice a step instead of once.
    const double end = (static_cast<double>(frame_) + static_cast<double>(i + 1) / settings_.substeps) * frame_step();
    advance(time_, h, end, true);
    if (after_substep_) after_substep_(end);
  }
  ++frame_;
  time_ = static_cast<double>(frame_) * frame_step();
  rest_resting_bodies();
  update_ledger_state();
  // The time joins the record with the probes' values, so whatever runs before they sample
  // sees a record whose columns all have the same length.
  if (before_probes_) before_probes_();
  for (Probe& probe : probes_) probe.history.push_back(probe.measure());
  times_.push_back(time_);
  bool any_slipping = false, any_touching = false;
  for (const ContactRecord& record : listener_.contacts()) {
    any_slipping = any_slipping || (record.solver.point_count > 0 && record.seen_slipping());
    // Where the shapes are now, as the probes read a contact: a block that has just left the
    // floor reads no contact in the very step it leaves (its friction reads 0 there).
    any_touching = any_touching || (record.solver.point_count > 0 && touching_now(record.identity.contact));
  }
  slipping_.push_back(any_slipping ? 1 : 0);
  touching_record_.push_back(any_touching ? 1 : 0);
}

void Scene::advance(double t, float h, double t_end, bool move) {
  if (before_substep_) before_substep_(t);
  std::vector<std::pair<b2Body*, b2Transform>> held;
  if (!move) {
    for (b2Body* body = world_->GetBodyList(); body != nullptr; body = body->GetNext()) {
      if (body->GetType() != b2_staticBody) held.emplace_back(body, body->GetTransform());
    }
  }
  listener_.apply_contact_forces(*world_, h);
  for (Rope& rope : ropes_) rope.parting_before = parting_speed(rope);

  for (const Driver& driver : drivers_) {
    const auto named = [&](const char* what) { return "driven body '" + name_of(driver.body) + "': " + what; };
    const std::array<double, 2> now = driver.position(t), next = driver.position(t_end);
    checked(b2Vec2{static_cast<float>(now[0]), static_cast<float>(now[1])}, t, [&] { return named("position"); });
    checked(b2Vec2{static_cast<float>(next[0]), static_cast<float>(next[1])}, t_end, [&] { return named("position"); });
    const double angle_now = driver.angle ? checked(driver.angle(t), t, [&] { return named("angle"); }) : 0.0;
    const double angle_next = driver.angle ? checked(driver.angle(t_end), t_end, [&] { return named("angle"); }) : 0.0;
    const double span = t_end - t;  // the step, in double as the path is
    driver.body->SetTransform(b2Vec2{static_cast<float>(now[0]), static_cast<float>(now[1])}, static_cast<float>(angle_now));
    driver.body->SetLinearVelocity(
        b2Vec2{static_cast<float>((next[0] - now[0]) / span), static_cast<float>((next[1] - now[1]) / span)});
    driver.body->SetAngularVelocity(static_cast<float>((angle_next - angle_now) / span));
  }

  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const Spring& spring = springs_[i];
    const b2Vec2 force = checked(spring_force(spring), t, [&] { return "spring '" + spring.name + "': force"; });
    if (move) spring_forces_applied_[i] = force;
    spring.body->ApplyForce(force, world_point(spring.body, spring.local_point), true);
    if (spring.other) {
      spring.other->ApplyForce(-force, world_point(spring.other, spring.other_local_point), true);
    } else {
      const b2Vec2 next = checked(spring.hand(t_end), t_end, [&] { return "spring '" + spring.name + "': hand"; });
      // The hand does work on the spring as it moves its end.
      if (move) ledger_.work_applied += b2Dot(force, next - hand_position(spring));
    }
  }

  // Kept between steps, so that a step allocates nothing for them.
  std::vector<Pending>& pending = pending_;
  pending.clear();
  std::vector<Turning>& turning = turning_;
  turning.clear();
  for (std::size_t i = 0; i < applied_.size(); ++i) {
    const AppliedForce& applied = applied_[i];
    const b2Vec2 point = world_point(applied.body, applied.local_point);
    const b2Vec2 force = checked(applied.force(t), t, [&] { return "applied force '" + applied.name + "'"; });
    if (move) forces_applied_[i] = force;
    applied.body->ApplyForce(force, point, true);
    pending.push_back({applied.body, applied.local_point, force, applied.body->GetLinearVelocityFromWorldPoint(point)});
    if (applied.torque) {
      const double torque = applied.torque(t);
      if (!std::isfinite(torque) || std::abs(torque) > 1e9) {
        throw InvalidInput("applied force '" + applied.name + "': torque " + std::to_string(torque) + " N·m at t = " +
                           std::to_string(t) + " s is outside ±1e9");
      }
      if (move) torques_applied_[i] = torque;
      applied.body->ApplyTorque(static_cast<float>(torque), true);
      turning.push_back({applied.body, torque, applied.body->GetAngularVelocity()});
    }
  }

  world_->Step(h, settings_.velocity_iterations, settings_.position_iterations);
  listener_.finish_step();
  // Not in the trial half step at t = 0, whose bodies are put back: a rope let go there would
  // stay let go.
  if (move) slacken_or_tie_ropes();
  // The hand's end of the gauge closes on the mouse, exactly for a mouse held still over the step.
  if (grab_ && move) grab_->hand += static_cast<float>(1.0 - std::exp(-h / grab_hand_lag)) * (grab_->target - grab_->hand);
  ++world_steps_;
  if (std::string error = listener_.take_error(); !error.empty()) throw InvalidInput(error);
  for (const auto& [body, transform] : held) body->SetTransform(transform.p, transform.q.GetAngle());

  for (const Pending& p : pending) {
    // The point moved with the body; its velocity is taken where the body now holds it.
    const b2Vec2 end_velocity = p.body->GetLinearVelocityFromLocalPoint(p.local_point);
    ledger_.work_applied += h * b2Dot(p.force, 0.5f * (p.start_velocity + end_velocity));
  }
  // A torque's work is itself times the angle turned: h times the mean of the spins.
  for (const Turning& turn : turning) {
    ledger_.work_applied += h * turn.torque * 0.5 * (turn.start_spin + turn.body->GetAngularVelocity());
  }
  const ContactWork work = listener_.take_work();
  ledger_.work_friction += work.friction;
  ledger_.work_damping += work.damping;
  ledger_.work_impacts += work.impacts;
  ledger_.work_drivers += work.drivers;
}

}  // namespace frictionlab
