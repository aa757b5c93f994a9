// Letting bodies that have come to rest sleep (Scene::rest_resting_bodies): when a body is at
// rest, held by static friction, and what wakes it again.
#include <cmath>

#include "physics/scene.h"

namespace frictionlab {

namespace {
// At rest: slower than a micrometre a second (and a milliradian a second), and moved less
// than a nanometre in the last frame (Box2D's position correction moves bodies without
// velocity): in float, at a few metres from the origin, not moved at all. A block stuck by
// static friction on the ground gets there within a few frames of stopping.
constexpr float rest_speed = 1e-6f;
constexpr float rest_spin = 1e-3f;
constexpr float rest_shift = 1e-9f;
// Frames in a row at rest before a body is let sleep: it stopped, and stays stopped, for a
// twentieth of a second at 240 Hz.
constexpr int rest_frames = 12;
}  // namespace

bool Scene::at_rest(const b2Body* body, std::size_t index) const {
  if (body->GetType() != b2_dynamicBody || body->GetJointList() != nullptr) return false;
  const b2Vec2 v = body->GetLinearVelocity();
  if (b2Dot(v, v) > rest_speed * rest_speed || std::abs(body->GetAngularVelocity()) > rest_spin) return false;
  const Rest& before = rest_[index];
  if ((body->GetPosition() - before.position).LengthSquared() > rest_shift * rest_shift ||
      std::abs(body->GetAngle() - before.angle) > rest_shift) {
    return false;
  }
  // Nothing but gravity on it: no spring, applied force or hand.
  for (const Spring& spring : springs_) {
    if (spring.body == body || spring.other == body) return false;
  }
  for (const AppliedForce& force : applied_) {
    if (force.body == body) return false;
  }
  // Resting on fixed bodies only, every touch stuck under the stick-slip law.
  bool touching = false;
  for (const b2ContactEdge* edge = body->GetContactList(); edge != nullptr; edge = edge->next) {
    if (!edge->contact->IsTouching()) continue;
    if (edge->other->GetType() != b2_staticBody) return false;
    const ContactRecord* record = listener_.record(edge->contact);
    if (record == nullptr || record->identity.unpaired || record->solver.point_count == 0 ||
        listener_.treatment_of(record->identity.material_a, record->identity.material_b) !=
            FrictionTreatment::stick_slip) {
      return false;
    }
    // A frictionless touch holds nothing along itself, and the listener may call it slipping
    // however slowly the body moves; at rest on it, the body is on level ground and stays.
    const FrictionPair& pair = pairs_.pair_at(record->identity.pair_index);
    const bool frictionless = pair.mu_s == 0.0 && pair.mu_k == 0.0 && pair.c == 0.0 && pair.b == 0.0;
    if (record->friction.state != ContactState::sticking && !frictionless) return false;
    touching = true;
  }
  return touching;
}

void Scene::rest_resting_bodies() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    b2Body* body = bodies_[i].second;
    Rest& rest = rest_[i];
    if (!body->IsAwake()) continue;
    rest.frames = at_rest(body, i) ? rest.frames + 1 : 0;
    rest.position = body->GetPosition();
    rest.angle = body->GetAngle();
    if (rest.frames >= rest_frames) {
      body->SetAwake(false);
      for (const b2ContactEdge* edge = body->GetContactList(); edge != nullptr; edge = edge->next) listener_.came_to_rest(edge->contact);
      rest.frames = 0;
    }
  }
}

void Scene::wake() {
  for (const auto& [name, body] : bodies_) {
    if (body->GetType() != b2_staticBody) body->SetAwake(true);
  }
}

}  // namespace frictionlab
