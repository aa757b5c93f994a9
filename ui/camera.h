// Metres to pixels. The zoom is chosen once from the lesson's world at t = 0 (so a block does
// not shrink as it slides away); the view then follows what moves.
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include "physics/scene.h"

namespace frictionlab::ui {

struct Camera {
  ImVec2 origin{0.0f, 0.0f};  // top-left of the view, pixels
  ImVec2 size{0.0f, 0.0f};    // pixels
  ImVec2 anchor{0.0f, 0.0f};  // where `centre` is drawn, pixels
  b2Vec2 centre{0.0f, 0.0f};  // world point drawn at the anchor, m
  float pixels_per_metre = 100.0f;

  ImVec2 to_screen(b2Vec2 p) const {
    return ImVec2(anchor.x + (p.x - centre.x) * pixels_per_metre, anchor.y - (p.y - centre.y) * pixels_per_metre);
  }
  b2Vec2 to_world(ImVec2 s) const {
    return {centre.x + (s.x - anchor.x) / pixels_per_metre, centre.y - (s.y - anchor.y) / pixels_per_metre};
  }
};

// A ground{}: a static, level box over 100 m wide and at most 2 m thick. It is drawn as the
// ground and left out of the framing; a long incline is neither.
bool is_ground(const b2Fixture* fixture);

// The part of the world a lesson is about: every body but the grounds, the spring hands and
// the pulleys.
b2AABB lesson_bounds(const Scene& scene);

// Chosen when a lesson is built and kept until it is rebuilt.
struct WorldFraming {
  b2Vec2 extent{1.0f, 1.0f};  // m, the size of lesson_bounds at t = 0
  // Frames the scene as it is now: this is meant to be called at t = 0.
  static WorldFraming of(const Scene& scene);
  // A camera on the view rectangle, zoomed to fit the extent with room around it into the part
  // of the view left free (`free_width` from its left edge), centred there on what the lesson
  // is about now.
  Camera camera(const Scene& scene, ImVec2 origin, ImVec2 size, float free_width) const;
};

}  // namespace frictionlab::ui
