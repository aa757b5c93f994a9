#include "ui/camera.h"

#include <algorithm>
#include <cmath>

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

// The view's bodies in this scene; empty when one of them is missing (a script since
// reloaded that no longer makes it): the camera then frames the whole lesson.
std::vector<const b2Body*> view_bodies(const Scene& scene, const lessons::View& view) {
  std::vector<const b2Body*> found;
  for (const std::string& name : view.bodies) {
    const auto at = std::find_if(scene.bodies().begin(), scene.bodies().end(),
                                 [&](const auto& entry) { return entry.first == name; });
    if (at == scene.bodies().end()) return {};
    found.push_back(at->second);
  }
  return found;
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

// Moves a camera that shows less than the whole lesson so that it shows as much of the lesson
// as it can: its view stays inside `bounds` (with a little room), along each axis on which it
// is smaller than them; but what moves (`moving`) stays in view with room for its arrows, the
// most above it, where the normal force and its label go.
void keep_within(Camera& camera, const b2AABB& bounds, const b2AABB& moving, float free_width) {
  const float ppm = camera.pixels_per_metre;
  // The world seen left, right, above and below the anchor, m.
  const float left = (camera.anchor.x - camera.origin.x) / ppm;
  const float right = (camera.origin.x + free_width - camera.anchor.x) / ppm;
  const float above = (camera.anchor.y - camera.origin.y) / ppm;
  const float below = (camera.origin.y + camera.size.y - camera.anchor.y) / ppm;
  const float room_x = 0.12f * (left + right), room_y = 0.08f * (above + below);
  const auto clamp_axis = [](float centre, float low, float high, float before, float after) {
    if (high - low < before + after) return centre;  // the view is wider than the lesson here
    return std::clamp(centre, low + before, high - after);
  };
  camera.centre.x = clamp_axis(camera.centre.x, bounds.lowerBound.x - room_x, bounds.upperBound.x + room_x, left, right);
  camera.centre.y = clamp_axis(camera.centre.y, bounds.lowerBound.y - room_y, bounds.upperBound.y + room_y, below, above);
  const auto shift_to_show = [](float centre, float low, float high, float before, float after) {
    if (low < centre - before) centre = low + before;      // show the low end first...
    if (high > centre + after) centre = high - after;      // ...and the high end wins: arrows go up
    return centre;
  };
  const float arrows_above = 0.3f * (above + below), arrows_aside = 0.12f * (left + right);
  camera.centre.x = shift_to_show(camera.centre.x, moving.lowerBound.x - arrows_aside, moving.upperBound.x + arrows_aside,
                                  left, right);
  camera.centre.y = shift_to_show(camera.centre.y, moving.lowerBound.y - room_y, moving.upperBound.y + arrows_above,
                                  below, above);
}

// Room around the lesson for the arrows and their labels.
constexpr float room = 1.45f;
// Pixels (at text scale 1) kept between a lane's floor and the lane's foot, and above a body.
constexpr float lane_ground_edge = 6.0f;

}  // namespace

WorldFraming WorldFraming::of(const lessons::Lesson& lesson) {
  const Scene& scene = lesson.scene();
  const b2AABB box = lesson_bounds(scene);
  WorldFraming framing;
  framing.view = lesson.view();
  // Thin scenes (a block on a bench) still get some height, so arrows have room.
  framing.extent = b2Vec2{std::max(box.upperBound.x - box.lowerBound.x, 0.3f),
                          std::max(box.upperBound.y - box.lowerBound.y, 0.3f)};
  framing.smallest_body = smallest_moving_body(scene);
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_dynamicBody) framing.tallest_body = std::max(framing.tallest_body, body_size(body).y);
  }
  const b2AABB moving = moving_bounds(scene);
  framing.moving_span = moving.upperBound.x - moving.lowerBound.x;
  if (framing.view.kind == lessons::View::Kind::lanes) {
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

std::vector<Camera> WorldFraming::cameras(const Scene& scene, ImVec2 origin, ImVec2 size, float free_width, float scale,
                                          const ViewAdjust& adjust) const {
  using Kind = lessons::View::Kind;
  // A window squeezed to nothing still gets a camera with a positive, finite scale.
  free_width = std::max(free_width, 1.0f);
  size = ImVec2(std::max(size.x, 1.0f), std::max(size.y, 1.0f));
  const std::vector<const b2Body*> bodies = view_bodies(scene, view);
  // What moves now, worked out once: the framing, the centre and each lane read it.
  const b2AABB moving = moving_bounds(scene);
  const Kind kind = bodies.empty() && view.kind != Kind::window ? Kind::whole : view.kind;
  const std::size_t strips = kind == Kind::lanes ? bodies.size() : 1;
  const float strip_height = size.y / static_cast<float>(strips);
  const float fit = std::min(free_width / (room * extent.x), size.y / (room * extent.y));
  float pixels_per_metre = fit;
  if (kind == Kind::window) {
    const b2Vec2 span = view.high - view.low;
    pixels_per_metre = std::min(free_width / span.x, size.y / span.y);
  } else if (view.width > 0.0) {
    pixels_per_metre = free_width / static_cast<float>(view.width);
  }
  if (kind == Kind::lanes) {
    // Each lane's bodies, with room above for the normal force and below for the ground, fit
    // in its strip: the tallest moving body a third of the strip high, and every moving body
    // across the free width, unless a width says.
    // Both as they were at t = 0, so the scale does not breathe as a box tumbles or the bodies
    // spread.
    if (tallest_body > 0.0f) {
      if (view.width <= 0.0) {
        pixels_per_metre = strip_height / (3.0f * tallest_body);
        if (moving_span > 0.0f) pixels_per_metre = std::min(pixels_per_metre, free_width / (1.2f * moving_span));
      }
      pixels_per_metre = std::min(pixels_per_metre, strip_height / (2.0f * tallest_body));
      // A body in the air at t = 0 keeps its floor in its lane, from the floor to half a body
      // above its top (the thrown box fell towards a floor out of sight), unless that makes it
      // too small to read (below).
      if (view.width <= 0.0) {
        float span = 0.0f;
        for (std::size_t i = 0; i < lane_ground.size() && i < lane_top.size(); ++i) {
          if (std::isfinite(lane_ground[i])) span = std::max(span, lane_top[i] - lane_ground[i]);
        }
        const float edges = 2.0f * lane_ground_edge * scale;
        if (span > 0.0f && strip_height > edges) {
          pixels_per_metre = std::min(pixels_per_metre, (strip_height - edges) / (span + 0.5f * tallest_body));
        }
      }
    }
  }
  // Readable bodies: a lesson that spreads them wide is followed rather than shrunk.
  float readable = smallest_body > 0.0f ? min_body_pixels * scale / smallest_body : 0.0f;
  if (kind == Kind::whole) {
    // ...but not so close that what moves now falls out of the picture.
    const b2Vec2 span = moving.upperBound - moving.lowerBound;
    if (span.x > 0.0f && span.y > 0.0f) {
      readable = std::min(readable, std::min(free_width / (1.2f * span.x), size.y / (1.2f * span.y)));
    }
  }
  const bool zoomed_in = kind != Kind::window && pixels_per_metre < readable;
  if (kind != Kind::window) pixels_per_metre = std::max(pixels_per_metre, readable);
  if (!std::isfinite(pixels_per_metre) || pixels_per_metre <= 0.0f) pixels_per_metre = 1.0f;

  b2Vec2 centre{0.0f, 0.0f};
  switch (kind) {
    case Kind::whole:
      // Everything when it fits; what moves when the view had to zoom in to keep it readable.
      centre = (zoomed_in ? moving : lesson_bounds(scene)).GetCenter();
      break;
    case Kind::follow:
      centre = bodies.front()->GetWorldCenter();
      break;
    case Kind::window:
      centre = 0.5f * (view.low + view.high);
      break;
    case Kind::lanes:
      // One horizontal window for every lane, so distances compare across lanes: centred on
      // what moves, from the body furthest behind to the one furthest ahead.
      centre.x = moving.GetCenter().x;
      break;
  }

  const b2AABB lesson = kind == Kind::whole && zoomed_in ? lesson_bounds(scene) : b2AABB{};
  std::vector<Camera> made;
  for (std::size_t i = 0; i < strips; ++i) {
    Camera camera;
    camera.origin = ImVec2(origin.x, origin.y + strip_height * static_cast<float>(i));
    camera.size = ImVec2(size.x, strip_height);
    camera.pixels_per_metre = pixels_per_metre * adjust.zoom;
    // A little below the middle: forces drawn above bodies need more room than the ground.
    // A window the script fixed is centred exactly, so all of it is in view.
    const float down = kind == Kind::window ? 0.5f : strips > 1 ? 0.6f : 0.56f;
    camera.anchor = ImVec2(origin.x + 0.5f * free_width, camera.origin.y + down * strip_height);

    camera.centre = centre;
    // Each lane on its own body's height.
    if (kind == Kind::lanes) {
      camera.centre.y = bodies[i]->GetWorldCenter().y;
      // Not so high that the floor under the body drops out of the lane's foot, while the
      // body's top stays in it: the lane stays still and the body falls to its floor.
      if (i < lane_ground.size() && std::isfinite(lane_ground[i])) {
        const float metres = 1.0f / camera.pixels_per_metre, edge = lane_ground_edge * scale * metres;
        const float floor_in_view = lane_ground[i] + (1.0f - down) * strip_height * metres - edge;
        const float top_in_view = body_box(bodies[i]).upperBound.y + edge - down * strip_height * metres;
        camera.centre.y = std::max(std::min(camera.centre.y, floor_in_view), top_in_view);
      }
      // Once the lanes' bodies have spread wider than the view, one window would lose some of
      // them: each lane then follows its own body (the ground's hatching still shows who moved).
      if ((moving.upperBound.x - moving.lowerBound.x) * camera.pixels_per_metre > 0.9f * free_width) {
        camera.centre.x = bodies[i]->GetWorldCenter().x;
      }
    }
    if (kind == Kind::whole && zoomed_in) keep_within(camera, lesson, moving, free_width);
    camera.centre += adjust.pan;
    made.push_back(camera);
  }
  return made;
}

}  // namespace frictionlab::ui
