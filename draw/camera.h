// Metres to pixels. The zoom is chosen once from the lesson's world at t = 0 (so a block does
// not shrink as it slides away) and its view{}; the view then follows what moves. The
// window's wheel and drag change it on top (ViewAdjust).
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include "lessons/runtime/framing.h"
#include "lessons/runtime/lesson.h"
#include "physics/scene.h"

namespace frictionlab::draw {

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

// What the user did to the view in the window (the wheel zooms, a drag on empty space pans),
// on top of what the lesson asks for. Kept while the lesson is rebuilt (a slider moved), so a
// teacher's close-up stays; a double click or another lesson puts it back.
struct ViewAdjust {
  float zoom = 1.0f;           // times the lesson's scale
  b2Vec2 pan{0.0f, 0.0f};      // m, added to every camera's centre
  bool operator==(const ViewAdjust&) const = default;
};

// The cameras on the view rectangle as the lesson's view asks (one per lane; one otherwise),
// with room for arrows, centred on the part of the view left free (`free_width` from its
// left edge). `scale` is the frame's text scale: no moving body is drawn with its longer side
// under min_body_pixels × scale, except in a window the lesson fixed. With `arrows`, the view
// keeps the world's arrows in sight at their drawn length: a window the lesson fixed grows to
// hold them, other views move up or down.
struct ArrowRoom {
  float longest = 0.0f;            // px, the longest arrow drawn (a normal force, up from a foot); 0: no room kept
  float pixels_per_newton = 0.0f;  // the arrows' scale: a body's weight is drawn m·g times it...
  float legible = 0.0f;            // px, ...or this long where that is shorter
  float value_line = 0.0f;         // px, a value's line beyond a weight's tip (under the floor, where nothing else is)
  float weight_pixels(const b2Body* body) const {
    const float weight = body->GetMass() * body->GetWorld()->GetGravity().Length();
    return std::max(weight * pixels_per_newton, legible);
  }
};
// How a lesson's lanes stand in the view: one column of strips, or, where a strip would be too
// thin for its bodies' arrows, `columns` side by side in `rows`, the lanes in reading order
// (left to right, then down). Terrain's four strips on a projector were 85 px high, where a
// normal force and a weight of 61 px each, up from a box's foot and down from its centre, need
// about 110: its lanes stand two by two there.
struct LaneGrid {
  std::size_t columns = 1, rows = 1;
};
// The fewest columns whose lanes hold every moving body's arrows (a normal force up from its
// foot, its weight down from its centre, each as `arrows_at` the lane's height draws them) between
// the lane's edges; one column where none does, or where the view has no lanes. Decided from
// the bodies' sizes and weights, not where they are, so the grid stays as the run goes on.
LaneGrid lane_grid(const lessons::WorldFraming& framing, const Scene& scene, ImVec2 size, float free_width, float scale,
                   const std::function<ArrowRoom(float lane_height)>& arrows_at);
// The lane a moving body's forces are drawn in: the one whose own body (`lane_bodies`, the
// view's, in its order) is nearest its height. Not the nearest camera: a lane's camera moves up
// or down to show its arrows, and where_methods_fail's lanes, 0.4 m apart on one slope, then
// drew a block's forces in the lane above.
std::size_t nearest_lane(const b2Body* body, const std::vector<const b2Body*>& lane_bodies);
// `lane_columns`: lane_grid's columns. `foot_clipped`: the world's panel ends at the view's foot
// (no legend under it), and clips its padding's half off it, as off its top.
std::vector<Camera> framing_cameras(const lessons::WorldFraming& framing, const Scene& scene, ImVec2 origin, ImVec2 size,
                                    float free_width, float scale, const ViewAdjust& adjust = {}, const ArrowRoom& arrows = {},
                                    std::size_t lane_columns = 1, bool foot_clipped = true);
inline constexpr float min_body_pixels = 48.0f;

}  // namespace frictionlab::draw
