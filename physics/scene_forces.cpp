#include "physics/scene_forces.h"

#include <algorithm>
#include <cmath>

namespace frictionlab {

std::string_view force_kind_name(ForceKind kind) {
  switch (kind) {
    case ForceKind::applied: return "applied";
    case ForceKind::spring: return "spring";
    case ForceKind::friction: return "friction";
    case ForceKind::normal: return "normal";
    case ForceKind::weight: return "weight";
    case ForceKind::tension: return "rope";
    case ForceKind::drag: return "drag";
  }
  return "force";
}


const b2Body* main_body(const Scene& scene) {
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_dynamicBody) return body;
  }
  return nullptr;
}

namespace {

// Where the contact's normal load acts on the bodies as the step left them, where they are
// drawn. Box2D keeps the manifold it found before the step moved the bodies, a step behind a
// fast block (pushed to 90 m/s it moves 0.39 m in a world step at 240 Hz, and its contact was
// drawn that far behind it), so the shapes are collided again where they are now, and each
// point is weighted by the load the solver gave the point of the same feature (as Box2D matches
// points for warm starting). A point new to this step takes no load (of a corner that came
// round the table's end, the other carries it all); with no load, the points' middle.
b2Vec2 centre_of_load(const b2Contact* contact, const ContactRecord& record) {
  const b2Fixture* fixture_a = contact->GetFixtureA();
  const b2Fixture* fixture_b = contact->GetFixtureB();
  const b2Transform& frame_a = fixture_a->GetBody()->GetTransform();
  const b2Transform& frame_b = fixture_b->GetBody()->GetTransform();
  b2Manifold now;
  // Evaluate only collides the two shapes at the frames given, into `now`; b2Contact does not
  // declare it const.
  const_cast<b2Contact*>(contact)->Evaluate(&now, frame_a, frame_b);
  // Apart now (a block off the table's end, a bounce): where the load last acted, as the step began.
  if (now.pointCount == 0) return record.solver.point;
  b2WorldManifold where;
  where.Initialize(&now, frame_a, fixture_a->GetShape()->m_radius, frame_b, fixture_b->GetShape()->m_radius);
  const b2Manifold* solved = contact->GetManifold();
  double total = 0.0;
  b2Vec2 sum{0.0f, 0.0f};
  b2Vec2 middle{0.0f, 0.0f};
  for (int i = 0; i < now.pointCount; ++i) {
    double load = 0.0;
    for (int j = 0; j < solved->pointCount && j < record.solver.point_count; ++j) {
      if (solved->points[j].id.key == now.points[i].id.key) load = record.solver.point_normal_force[j];
    }
    total += load;
    sum += static_cast<float>(load) * where.points[i];
    middle += (1.0f / static_cast<float>(now.pointCount)) * where.points[i];
  }
  return total > 1e-9 ? (1.0f / static_cast<float>(total)) * sum : middle;
}

bool touching(const ContactRecord& record) { return record.solver.point_count > 0 && !record.identity.unpaired; }

}  // namespace

std::vector<ForceOnBody> forces_on(const Scene& scene, const b2Body* body) {
  std::vector<ForceOnBody> forces;
  if (body == nullptr || body->GetType() != b2_dynamicBody) return forces;
  const b2Vec2 gravity = scene.world().GetGravity();
  forces.push_back({ForceKind::weight, body, body->GetWorldCenter(), body->GetMass() * gravity});
  struct Shared {
    const b2Body* other;
    std::size_t friction;  // its friction force's place in `forces`; its drag's is the next
    float load;            // N, the normal load summed so far
  };
  std::vector<Shared> shared;
  for (const b2Contact* contact = scene.world().GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    const b2Body* a = contact->GetFixtureA()->GetBody();
    const b2Body* b = contact->GetFixtureB()->GetBody();
    if (a != body && b != body) continue;
    const ContactRecord* found = scene.friction().record(contact);
    if (found == nullptr || !touching(*found)) continue;
    const ContactRecord& record = *found;
    const b2Vec2 point = centre_of_load(contact, record);
    const b2Body* other = a == body ? b : a;
    forces.push_back({ForceKind::normal, body, point, record.normal_on(body), other});
    const b2Vec2 drag = record.side(body) * static_cast<float>(record.solver.damping_force) * record.tangent();
    // Friction (and drag) from one other body is drawn as one arrow, their sum, at the centre of
    // the load: a block on six feet has six normal forces to show but one friction force to
    // read. Each foot's normal force keeps its own arrow.
    const float load = record.normal_on(body).Length();
    const auto same = std::find_if(shared.begin(), shared.end(), [&](const Shared& s) { return s.other == other; });
    if (same == shared.end()) {
      shared.push_back({other, forces.size(), load});
      forces.push_back({ForceKind::friction, body, point, record.friction_on(body), other});
      // The viscous and quadratic terms apart from dry friction, so mu_k·N stays readable.
      forces.push_back({ForceKind::drag, body, point, drag, other});
      continue;
    }
    ForceOnBody& friction = forces[same->friction];
    ForceOnBody& damping = forces[same->friction + 1];
    const float total = same->load + load;
    if (total > 0.0f) friction.point = (same->load / total) * friction.point + (load / total) * point;
    damping.point = friction.point;
    friction.force += record.friction_on(body);
    damping.force += drag;
    same->load = total;
  }
  // A drag arrow only where there is drag.
  forces.erase(std::remove_if(forces.begin(), forces.end(),
                              [](const ForceOnBody& f) { return f.kind == ForceKind::drag && f.force.LengthSquared() == 0.0f; }),
               forces.end());
  // Springs and applied forces as the last step applied them, the step whose friction the
  // record holds: while a block sticks, the forces then add up to zero.
  for (std::size_t i = 0; i < scene.springs().size(); ++i) {
    const Spring& spring = scene.springs()[i];
    const b2Vec2 pull = scene.spring_forces_applied()[i];
    if (spring.body == body) forces.push_back({ForceKind::spring, body, body->GetWorldPoint(spring.local_point), pull});
    if (spring.other == body) {
      forces.push_back({ForceKind::spring, body, body->GetWorldPoint(spring.other_local_point), -pull});
    }
  }
  // A rope pulls each end toward its pulley with the tension the last world step's solver
  // found (its impulse over that step's length).
  for (std::size_t i = 0; i < scene.ropes().size(); ++i) {
    const Rope& rope = scene.ropes()[i];
    // A slack rope pulls with nothing, and draws no arrow.
    if (!rope.taut() || scene.frame() == 0) continue;
    const auto tension = static_cast<float>(scene.rope_tension(i));
    const auto toward = [](b2Vec2 from, b2Vec2 to) {
      b2Vec2 d = to - from;
      return d.Normalize() > 0.0f ? d : b2Vec2{0.0f, 0.0f};
    };
    if (rope.body_a == body) forces.push_back({ForceKind::tension, body, rope.end_a(), tension * toward(rope.end_a(), rope.pulley_a)});
    if (rope.body_b == body) forces.push_back({ForceKind::tension, body, rope.end_b(), tension * toward(rope.end_b(), rope.pulley_b)});
  }
  for (std::size_t i = 0; i < scene.applied_forces().size(); ++i) {
    const AppliedForce& applied = scene.applied_forces()[i];
    if (applied.body != body) continue;
    forces.push_back({ForceKind::applied, body, body->GetWorldPoint(applied.local_point), scene.forces_applied()[i]});
  }
  return forces;
}

std::vector<ContactMark> contact_marks(const Scene& scene) {
  std::vector<ContactMark> marks;
  for (const b2Contact* contact = scene.world().GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    const ContactRecord* found = scene.friction().record(contact);
    if (found == nullptr || !touching(*found)) continue;
    const ContactRecord& record = *found;
    const ContactIdentity& between = record.identity;
    if (between.body_a->GetType() != b2_dynamicBody && between.body_b->GetType() != b2_dynamicBody) continue;
    marks.push_back({between.body_a, between.body_b, centre_of_load(contact, record), record.tangent(), record.friction.state,
                     record.solver.frictionless, record.solver.sliding_velocity, record.solver.friction_force});
  }
  return marks;
}

float upper_side(const ContactMark& mark) {
  const b2Vec2 normal = b2Cross(1.0f, mark.tangent);  // from A to B
  return normal.y >= 0.0f ? 1.0f : -1.0f;
}

std::string contact_word(const ContactMark& mark) {
  // With no dry friction nothing sticks or slips: the word says so, sliding along or not.
  if (mark.frictionless) return "frictionless";
  if (mark.state != ContactState::slipping) return "sticking";
  // The record's sliding is B's relative to A; turned into the upper body's over the lower one.
  const b2Vec2 way = upper_side(mark) * static_cast<float>(mark.sliding_velocity >= 0.0 ? 1.0 : -1.0) * mark.tangent;
  return way.x >= 0.0f ? "slipping \u2192" : "\u2190 slipping";
}

namespace {

// Before the first step there are no contacts yet: a body set down on a surface (a box{} placed
// `on` one) stands on the face its own angle gives, its lowest along its own up.
std::optional<Surface> set_down_on(const b2Body* body) {
  const b2Vec2 along = body->GetWorldVector(b2Vec2(1.0f, 0.0f)), up = body->GetWorldVector(b2Vec2(0.0f, 1.0f));
  float lowest = 0.0f;
  bool any = false;
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->GetType() != b2Shape::e_polygon) continue;
    const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
    for (int i = 0; i < polygon->m_count; ++i) {
      const float height = b2Dot(body->GetWorldPoint(polygon->m_vertices[i]) - body->GetWorldCenter(), up);
      lowest = any ? std::min(lowest, height) : height;
      any = true;
    }
  }
  if (!any) return std::nullopt;
  Surface surface{body->GetWorldCenter() + lowest * up, along, up};
  if (surface.along.x < 0.0f) surface.along = -surface.along;
  return surface;
}

}  // namespace

namespace {

// The fixed body's polygons projected on the surface's line: where the marks may run.
void reach_of(const b2Body* fixed, Surface* surface) {
  bool any = false;
  for (const b2Fixture* fixture = fixed->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->GetType() != b2Shape::e_polygon) return;  // a chain or a circle: leave it unbounded
    const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
    for (int i = 0; i < polygon->m_count; ++i) {
      const float at = b2Dot(fixed->GetWorldPoint(polygon->m_vertices[i]) - surface->point, surface->along);
      surface->low = any ? std::min(surface->low, at) : at;
      surface->high = any ? std::max(surface->high, at) : at;
      any = true;
    }
  }
  if (!any) surface->low = -1e30f, surface->high = 1e30f;
}

}  // namespace

namespace {

// Whether a face of the fixed body runs along `along` through `point`: the body stands on that
// surface, not on one of its corners. Box2D's contact with a corner takes the moving body's own
// face for its normal, so a block dragged over the top of the incline gave the weight split of
// its own tilt (1.24 N "m·g·sin θ" beside a 30° slope). A body of circles or chains is taken as
// a surface wherever it touches.
bool along_a_face(const b2Body* fixed, b2Vec2 point, b2Vec2 along) {
  const float near = 4.0f * b2_linearSlop + 2.0f * b2_polygonRadius;
  for (const b2Fixture* fixture = fixed->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    b2Vec2 ends[b2_maxPolygonVertices];
    int count = 0;
    if (fixture->GetType() == b2Shape::e_polygon) {
      const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
      count = polygon->m_count;
      for (int i = 0; i < count; ++i) ends[i] = fixed->GetWorldPoint(polygon->m_vertices[i]);
    } else if (fixture->GetType() == b2Shape::e_edge) {
      const auto* edge = static_cast<const b2EdgeShape*>(fixture->GetShape());
      ends[0] = fixed->GetWorldPoint(edge->m_vertex1);
      ends[1] = fixed->GetWorldPoint(edge->m_vertex2);
      count = 2;
    } else {
      return true;
    }
    for (int i = 0; i < count; ++i) {
      const b2Vec2 from = ends[i], to = ends[(i + 1) % count];
      b2Vec2 side = to - from;
      const float length = side.Normalize();
      if (length <= 0.0f || std::abs(b2Cross(side, along)) > 1e-3f) continue;
      const float across = std::abs(b2Cross(side, point - from)), at = b2Dot(point - from, side);
      if (across <= near && at >= -near && at <= length + near) return true;
    }
  }
  return false;
}

}  // namespace

std::optional<Surface> surface_under(const Scene& scene, const b2Body* body) {
  if (body == nullptr) return std::nullopt;
  // A body given a velocity at t = 0 (thrown, launched) stands on nothing yet.
  if (scene.frame() == 0) {
    if (body->GetLinearVelocity().Length() != 0.0f || body->GetAngularVelocity() != 0.0f) return std::nullopt;
    std::optional<Surface> surface = set_down_on(body);
    // Set down on a fixed body's face, it reaches no further than that body does, as after the
    // first step: unbounded, the incline's distance marks ran the view's width along the slope's
    // line, past its top into the sky and past its foot into the ground (issue 31).
    for (const b2Body* other = scene.world().GetBodyList(); surface && other != nullptr; other = other->GetNext()) {
      if (other->GetType() != b2_staticBody || !along_a_face(other, surface->point, surface->along)) continue;
      reach_of(other, &*surface);
      break;
    }
    return surface;
  }
  for (const ContactMark& mark : contact_marks(scene)) {
    const b2Body* other = mark.body_a == body ? mark.body_b : mark.body_b == body ? mark.body_a : nullptr;
    if (other == nullptr || other->GetType() != b2_staticBody) continue;
    if (!along_a_face(other, mark.point, mark.tangent)) continue;  // on a corner: no surface to speak of
    Surface surface;
    surface.point = mark.point;
    surface.along = mark.tangent;
    surface.along.Normalize();
    if (surface.along.x < 0.0f || (surface.along.x == 0.0f && surface.along.y < 0.0f)) surface.along = -surface.along;
    surface.normal = b2Vec2(-surface.along.y, surface.along.x);
    if (b2Dot(surface.normal, body->GetWorldCenter() - surface.point) < 0.0f) surface.normal = -surface.normal;
    // Under the centre of mass, not where the load is centred: friction shifts the load towards
    // the leading edge of a sliding block (by mu_k·h/2), and a mark there would not be its place.
    surface.point += b2Dot(body->GetWorldCenter() - surface.point, surface.along) * surface.along;
    reach_of(other, &surface);
    return surface;
  }
  return std::nullopt;
}

}  // namespace frictionlab
