#include "lessons/runtime/framing.h"

#include <algorithm>
#include <cmath>

namespace frictionlab::lessons {
namespace {

void grow(b2AABB& box, bool& empty, b2Vec2 p) {
  if (empty) {
    box.lowerBound = box.upperBound = p;
    empty = false;
    return;
  }
  box.lowerBound = b2Min(box.lowerBound, p);
  box.upperBound = b2Max(box.upperBound, p);
}

}  // namespace

bool is_ground(const b2Fixture* fixture) {
  // Judged on the whole body: a floor of strips (ground{ strips = ... }) is level edges with a
  // slab under each, none of them wide alone.
  const b2Body* body = fixture->GetBody();
  if (body->GetType() != b2_staticBody) return false;
  b2AABB box = body->GetFixtureList()->GetAABB(0);
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
    const bool slab = f->GetType() == b2Shape::e_polygon && static_cast<const b2PolygonShape*>(f->GetShape())->m_count == 4;
    if (!slab && f->GetType() != b2Shape::e_edge) return false;
    box.Combine(f->GetAABB(0));
  }
  const float width = box.upperBound.x - box.lowerBound.x, height = box.upperBound.y - box.lowerBound.y;
  return width > 100.0f && height <= 2.0f + 2.0f * b2_polygonRadius;
}

b2AABB lesson_bounds(const Scene& scene) {
  b2AABB box;
  box.lowerBound = box.upperBound = b2Vec2{0.0f, 0.0f};
  bool empty = true;
  for (const auto& [name, body] : scene.bodies()) {
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      if (is_ground(fixture)) continue;
      const b2AABB& fixture_box = fixture->GetAABB(0);
      grow(box, empty, fixture_box.lowerBound);
      grow(box, empty, fixture_box.upperBound);
    }
  }
  for (const Spring& spring : scene.springs()) {
    grow(box, empty, spring.other ? spring.other->GetWorldPoint(spring.other_local_point) : scene.hand_position(spring));
  }
  for (const Rope& rope : scene.ropes()) {
    grow(box, empty, rope.pulley_a);
    grow(box, empty, rope.pulley_b);
  }
  return box;
}

b2AABB body_box(const b2Body* body) {
  b2AABB box;
  box.lowerBound = box.upperBound = body->GetWorldCenter();
  bool empty = true;
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    grow(box, empty, fixture->GetAABB(0).lowerBound);
    grow(box, empty, fixture->GetAABB(0).upperBound);
  }
  return box;
}

b2AABB moving_bounds(const Scene& scene) {
  b2AABB box;
  box.lowerBound = box.upperBound = b2Vec2{0.0f, 0.0f};
  bool empty = true;
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody || body->GetFixtureList() == nullptr) continue;
    const b2AABB covers = body_box(body);
    grow(box, empty, covers.lowerBound);
    grow(box, empty, covers.upperBound);
  }
  return box;
}

std::vector<const b2Body*> view_bodies(const Scene& scene, const View& view) {
  std::vector<const b2Body*> found;
  for (const std::string& name : view.bodies) {
    const auto at = std::find_if(scene.bodies().begin(), scene.bodies().end(),
                                 [&](const auto& entry) { return entry.first == name; });
    if (at == scene.bodies().end()) return {};
    found.push_back(at->second);
  }
  return found;
}

namespace {

// A body's width and height as its fixtures' boxes cover it now (a body on feet counts whole), m.
b2Vec2 body_size(const b2Body* body) {
  const b2AABB box = body_box(body);
  return box.upperBound - box.lowerBound;
}

// The longer side of the smallest moving body, m; 0 with none.
float smallest_moving_body(const Scene& scene) {
  float smallest = 0.0f;
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    const b2Vec2 size = body_size(body);
    const float side = std::max(size.x, size.y);
    if (side > 0.0f && (smallest == 0.0f || side < smallest)) smallest = side;
  }
  return smallest;
}

// The top of the fixed surface straight under `body`'s centre, at most `reach` below its foot;
// NaN when there is none. Other moving bodies are looked through: a lane's floor is what counts.
float ground_under(const Scene& scene, const b2Body* body, float reach) {
  struct Nearest : b2RayCastCallback {
    float y = std::nanf("");
    float ReportFixture(b2Fixture* fixture, const b2Vec2& point, const b2Vec2&, float fraction) override {
      if (fixture->GetBody()->GetType() != b2_staticBody || fixture->IsSensor()) return -1.0f;  // look through it
      y = point.y;
      return fraction;  // only nearer ones from now on
    }
  } nearest;
  const b2Vec2 from = body->GetWorldCenter();
  const b2Vec2 to(from.x, body_box(body).lowerBound.y - reach);
  if (to.y < from.y) scene.world().RayCast(&nearest, from, to);
  return nearest.y;
}


}  // namespace

WorldFraming WorldFraming::of(const Lesson& lesson) {
  const Scene& scene = lesson.scene();
  const b2AABB box = lesson_bounds(scene);
  WorldFraming framing;
  framing.view = lesson.view();
  // Thin scenes (a block on a bench) still get some height, so arrows have room.
  framing.extent = b2Vec2{std::max(box.upperBound.x - box.lowerBound.x, 0.3f),
                          std::max(box.upperBound.y - box.lowerBound.y, 0.3f)};
  framing.smallest_body = smallest_moving_body(scene);
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    framing.tallest_body = std::max(framing.tallest_body, body_size(body).y);
    const float foot = body_box(body).lowerBound.y;
    if (std::isnan(framing.highest_foot) || foot > framing.highest_foot) framing.highest_foot = foot;
  }
  const b2AABB moving = moving_bounds(scene);
  framing.moving_span = moving.upperBound.x - moving.lowerBound.x;
  framing.lesson_centre = box.GetCenter();
  framing.moving_centre = moving.GetCenter();
  if (framing.view.kind == View::Kind::lanes) {
    for (const b2Body* body : view_bodies(scene, framing.view)) {
      // Only a body clear of its floor: one standing on it (on a slope, its lowest corner under
      // the floor's height at its centre) is framed on itself as before, wherever it goes.
      const float ground = ground_under(scene, body, ground_reach * framing.tallest_body);
      const b2AABB covers = body_box(body);
      const bool in_the_air = covers.lowerBound.y - ground > 0.1f * framing.tallest_body;
      framing.lane_ground.push_back(in_the_air ? ground : std::nanf(""));
      framing.lane_top.push_back(covers.upperBound.y);
    }
  }
  return framing;
}

}  // namespace frictionlab::lessons
