#include "ui/camera.h"

#include <algorithm>

namespace frictionlab::ui {
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
  if (fixture->GetBody()->GetType() != b2_staticBody || fixture->GetType() != b2Shape::e_polygon) return false;
  const auto& shape = *static_cast<const b2PolygonShape*>(fixture->GetShape());
  const b2AABB& box = fixture->GetAABB(0);
  const float width = box.upperBound.x - box.lowerBound.x, height = box.upperBound.y - box.lowerBound.y;
  return shape.m_count == 4 && width > 100.0f && height <= 2.0f + 2.0f * b2_polygonRadius;
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
  for (const b2Joint* joint = scene.world().GetJointList(); joint != nullptr; joint = joint->GetNext()) {
    if (joint->GetType() != e_pulleyJoint) continue;
    const auto* pulley = static_cast<const b2PulleyJoint*>(joint);
    grow(box, empty, pulley->GetGroundAnchorA());
    grow(box, empty, pulley->GetGroundAnchorB());
  }
  return box;
}

WorldFraming WorldFraming::of(const Scene& scene) {
  const b2AABB box = lesson_bounds(scene);
  WorldFraming framing;
  // Thin scenes (a block on a bench) still get some height, so arrows have room.
  framing.extent = b2Vec2{std::max(box.upperBound.x - box.lowerBound.x, 0.3f),
                          std::max(box.upperBound.y - box.lowerBound.y, 0.3f)};
  return framing;
}

Camera WorldFraming::camera(const Scene& scene, ImVec2 origin, ImVec2 size, float free_width) const {
  Camera camera;
  camera.origin = origin;
  camera.size = size;
  // Room around the lesson for the arrows and their labels.
  constexpr float room = 1.45f;
  camera.pixels_per_metre = std::min(free_width / (room * extent.x), size.y / (room * extent.y));
  camera.centre = lesson_bounds(scene).GetCenter();
  // A little below the middle: forces drawn above bodies need more room than the ground.
  camera.anchor = ImVec2(origin.x + 0.5f * free_width, origin.y + 0.56f * size.y);
  return camera;
}

}  // namespace frictionlab::ui
