// How a lesson's world is framed, in metres alone: the part of it the lesson is about, what
// moves, and the sizes the camera scales by, chosen at t = 0. No pixels here: the drawing
// (draw/camera.h) turns a framing into cameras, and the classroom's playback keeps one per build.
#pragma once

#include <box2d/box2d.h>

#include <cmath>
#include <vector>

#include "lessons/runtime/lesson.h"
#include "physics/scene.h"

namespace frictionlab::lessons {

// A ground{}: a static, level box over 100 m wide and at most 2 m thick. It is drawn as the
// ground and left out of the framing; a long incline is neither.
bool is_ground(const b2Fixture* fixture);

// The part of the world a lesson is about: every body but the grounds, with the spring hands
// and the pulleys.
b2AABB lesson_bounds(const Scene& scene);

// The box a body's fixtures cover now (a body on feet counts whole).
b2AABB body_box(const b2Body* body);

// The part of the world that moves: every dynamic body. Empty (zero box) when none does.
b2AABB moving_bounds(const Scene& scene);

// The view's bodies in this scene; empty when one of them is missing (a script since
// reloaded that no longer makes it): the camera then frames the whole lesson.
std::vector<const b2Body*> view_bodies(const Scene& scene, const View& view);

// Chosen when a lesson is built and kept until it is rebuilt.
struct WorldFraming {
  View view;                     // the lesson's view{} (its bodies belong to that build)
  b2Vec2 extent{1.0f, 1.0f};     // m, the size of lesson_bounds at t = 0
  float smallest_body = 0.0f;    // m, the longer side of the smallest moving body at t = 0
  float tallest_body = 0.0f;     // m, the height of the tallest moving body at t = 0 (lanes' scale)
  float moving_span = 0.0f;      // m, how wide what moves spread at t = 0 (lanes' scale)
  // m, the centres of lesson_bounds and of moving_bounds at t = 0: a whole-lesson view stands
  // still from there while the lesson moves across it, and turns a page when it nears an edge.
  b2Vec2 lesson_centre{0.0f, 0.0f}, moving_centre{0.0f, 0.0f};
  // Per lane, at t = 0: the height of the fixed surface straight under its body's centre
  // (within ground_reach of its foot; NaN: none), and of the body's top. A body that starts in
  // the air (a thrown box) is framed with the floor it will land on.
  std::vector<float> lane_ground, lane_top;
  // m, the highest foot of a moving body at t = 0 (its box's bottom; NaN: none moves). A window
  // the lesson fixed grows from it to hold the normal forces above the feet, so that its scale
  // does not change as a block slides down (incline's 2 m bar was 93 px at 0.6 s, 133 px at 1.5 s).
  float highest_foot = std::nanf("");
  static constexpr float ground_reach = 5.0f;  // × the tallest moving body
  // Frames the lesson as it is now: this is meant to be called at t = 0.
  static WorldFraming of(const Lesson& lesson);
};

}  // namespace frictionlab::lessons
