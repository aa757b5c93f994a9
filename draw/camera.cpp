#include "draw/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionlab::draw {

using lessons::body_box;
using lessons::lesson_bounds;
using lessons::moving_bounds;
using lessons::view_bodies;

namespace {

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

// What a body's arrows reach, m, up and down, at `pixels_per_metre`: a normal force up from its
// foot as long as the longest arrow drawn at most, its weight down from its centre (past the
// floor it stands on) as drawn, and its value's line beyond that tip. Its own box at least.
struct Reach {
  float low, high;
};
Reach arrow_reach(const b2Body* body, const ArrowRoom& arrows, float pixels_per_metre) {
  const b2AABB box = body_box(body);
  const float down = arrows.weight_pixels(body) + arrows.value_line;
  return {std::min(box.lowerBound.y, body->GetWorldCenter().y - down / pixels_per_metre),
          std::max(box.upperBound.y, box.lowerBound.y + arrows.longest / pixels_per_metre)};
}
// Every moving body's arrow_reach, together; none (low above high) where nothing moves.
Reach moving_reach(const Scene& scene, const ArrowRoom& arrows, float pixels_per_metre) {
  Reach all{1e30f, -1e30f};
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    const Reach one = arrow_reach(body, arrows, pixels_per_metre);
    all = {std::min(all.low, one.low), std::max(all.high, one.high)};
  }
  return all;
}

// Moves the camera up or down as little as shows `reach` between `edge` pixels of the lane's top
// and bottom; one taller than that is centred, into the edges; one taller than the lane is left
// where the framing put it (moving would only trade the weight's tip for the normal force's, and
// take its values' places beside them; lanes that thin stand side by side instead, lane_grid).
void show_reach(Camera& camera, Reach reach, float edge) {
  if (!(reach.low <= reach.high)) return;
  const float metres = 1.0f / camera.pixels_per_metre;
  if (reach.high - reach.low > camera.size.y * metres) return;
  const float above = (camera.anchor.y - camera.origin.y - edge) * metres;            // seen above the centre
  const float below = (camera.origin.y + camera.size.y - camera.anchor.y - edge) * metres;  // and below it
  if (reach.high - reach.low > above + below) {
    camera.centre.y = 0.5f * (reach.low + reach.high) - 0.5f * (above - below);
  } else if (reach.high > camera.centre.y + above) {
    camera.centre.y = reach.high - above;
  } else if (reach.low < camera.centre.y - below) {
    camera.centre.y = reach.low + below;
  }
}

// Whether a body touches anything (it may then have a normal force drawn up from its foot).
bool touching(const b2Body* body) {
  for (const b2ContactEdge* edge = body->GetContactList(); edge != nullptr; edge = edge->next) {
    if (edge->contact->IsTouching()) return true;
  }
  return false;
}

// A lane's arrows in its picture: the reach of the moving bodies drawn in it (those nearest its
// own body's height, as the frame's bodies_by_lane shares them out), their values' lines too
// where the lane has room for them, else the arrows' tips alone, which lane_grid made room for.
// Before, a lane stayed on its body's height and a weight ran past its foot (terrain's four
// lanes on a projector, friction_models', contact_area's at 1920 × 1080).
void show_lane_reach(Camera& camera, const Scene& scene, const std::vector<const b2Body*>& lane_bodies, std::size_t lane,
                     const ArrowRoom& arrows, float edge, float clipped_top, float clipped_bottom) {
  ArrowRoom tips = arrows;
  tips.value_line = 0.0f;
  Reach with{1e30f, -1e30f}, without{1e30f, -1e30f};
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    if (nearest_lane(body, lane_bodies) != lane) continue;
    Reach one = arrow_reach(body, arrows, camera.pixels_per_metre), two = arrow_reach(body, tips, camera.pixels_per_metre);
    if (!touching(body)) {
      // In the air: no normal force above it (the thrown box's lane stays still while it falls).
      one.high = two.high = body_box(body).upperBound.y;
    }
    with = {std::min(with.low, one.low), std::max(with.high, one.high)};
    without = {std::min(without.low, two.low), std::max(without.high, two.high)};
  }
  if (!(without.low <= without.high)) return;
  // A lane whose arrows' tips already show stays where the framing put it, on its body's height
  // (a window's lanes, whose weights end a few pixels over their feet); what shows of it is all of
  // it, less what the world's panel clips off its edges (`clipped_top`, `clipped_bottom`).
  const float top = camera.to_screen({0.0f, without.high}).y, bottom = camera.to_screen({0.0f, without.low}).y;
  const float slack = 0.01f;  // a weight of 0.4 of the lane's height ends on its foot, to the floats' rounding
  if (top >= camera.origin.y + clipped_top - slack && bottom <= camera.origin.y + camera.size.y - clipped_bottom + slack) return;
  const bool values_fit = (with.high - with.low) * camera.pixels_per_metre <= camera.size.y - 2.0f * edge;
  show_reach(camera, values_fit ? with : without, edge);
}

// Half the shorter side of a body's own box, m, taken in its own frame so that it does not
// change as the body turns: at least this much of it lies between its foot and its centre.
float half_shorter_side(const b2Body* body) {
  const b2Transform own(b2Vec2(0.0f, 0.0f), b2Rot(0.0f));
  b2AABB box{};
  bool any = false;
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    for (int child = 0; child < fixture->GetShape()->GetChildCount(); ++child) {
      b2AABB one;
      fixture->GetShape()->ComputeAABB(&one, own, child);
      if (any) {
        box.Combine(one);
      } else {
        box = one;
        any = true;
      }
    }
  }
  if (!any) return 0.0f;
  const b2Vec2 side = box.upperBound - box.lowerBound;
  return 0.5f * std::min(side.x, side.y);
}

// Whether every moving body's arrows fit in `room` px of a lane's height at `pixels_per_metre`:
// its normal force up from its foot (or its top, if that is higher), its weight down from its
// centre (ArrowRoom::weight_pixels), their values' lines left to go beside them.
bool arrows_fit(const Scene& scene, const ArrowRoom& arrows, float pixels_per_metre, float room) {
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    const float half = half_shorter_side(body) * pixels_per_metre;
    if (std::max(arrows.longest - half, half) + arrows.weight_pixels(body) > room) return false;
  }
  return true;
}

// The free width of a column of lanes, px: the view's `free_width` from its left edge is free
// (the free-body inset covers the rest), and each column keeps what of it is in the column.
float column_free_width(float width, float free_width, std::size_t columns, std::size_t column) {
  const float column_width = width / static_cast<float>(columns);
  return std::clamp(free_width - column_width * static_cast<float>(column), 1.0f, column_width);
}

// The highest foot of a moving body, m: now or at t = 0 (WorldFraming::highest_foot), whichever
// is higher; -infinity where none moves.
float highest_foot(const lessons::WorldFraming& framing, const Scene& scene) {
  float foot = std::isnan(framing.highest_foot) ? -std::numeric_limits<float>::infinity() : framing.highest_foot;
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_dynamicBody) foot = std::max(foot, body_box(body).lowerBound.y);
  }
  return foot;
}

// Room around the lesson for the arrows and their labels.
constexpr float room = 1.45f;
// Pixels (at text scale 1) kept between a lane's floor and the lane's foot, and above a body.
constexpr float lane_ground_edge = 6.0f;

// The world's scale, pixels a metre, for the view's kind (one for every lane); and whether it
// had to zoom in past the fit to keep the smallest body readable (then the view frames what
// moves, not everything).
struct FramingScale {
  float pixels_per_metre = 1.0f;
  bool zoomed_in = false;
};

FramingScale framing_scale(const lessons::WorldFraming& framing, const Scene& scene, lessons::View::Kind kind,
                           const b2AABB& moving, ImVec2 size, float free_width, float strip_height, float edge, float scale,
                           const ArrowRoom& arrows) {
  using Kind = lessons::View::Kind;
  const lessons::View& view = framing.view;
  const b2Vec2 extent = framing.extent;
  const float tallest_body = framing.tallest_body, moving_span = framing.moving_span, smallest_body = framing.smallest_body;
  const std::vector<float>& lane_ground = framing.lane_ground;
  const std::vector<float>& lane_top = framing.lane_top;
  const float fit = std::min(free_width / (room * extent.x), size.y / (room * extent.y));
  float pixels_per_metre = fit;
  if (kind == Kind::window) {
    const b2Vec2 span = view.high - view.low;
    pixels_per_metre = std::min(free_width / span.x, size.y / span.y);
    // The window the script fixed, and the moving bodies' normal forces at the longest arrow's
    // drawn length up from their feet (pulley's 9.81 N, 0.4 of the view's height up from the
    // block's foot, ran out of its top): the arrows' pixels do not shrink with the world, so the
    // metres from the window's foot to a body's foot and the arrow's pixels share the view's
    // height, (metres)·ppm + (pixels) <= height. Weights point down into the floor the window
    // stands on, and are left to it: paired with a normal force above they shrank a window
    // of two floors to a tenth.
    // The highest foot is the highest at t = 0 or now, whichever is higher: growing from the feet
    // of the moment, incline's window zoomed in as its block slid down (a projector trial, issue
    // 31); a body that climbs past where it started still has its arrows in sight.
    if (arrows.longest > 0.0f) {
      const float height_left = size.y - 2.0f * edge;
      const float foot = highest_foot(framing, scene);
      if (foot > view.low.y && height_left > arrows.longest) {
        pixels_per_metre = std::min(pixels_per_metre, (height_left - arrows.longest) / (foot - view.low.y));
      }
    }
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
  return {pixels_per_metre, zoomed_in};
}

// Where the view is centred (a lane's height is its own body's: framing_cameras).
b2Vec2 framing_centre(lessons::View::Kind kind, bool zoomed_in, const lessons::View& view, const Scene& scene,
                      const std::vector<const b2Body*>& bodies, const b2AABB& moving) {
  using Kind = lessons::View::Kind;
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
  return centre;
}

}  // namespace

std::size_t nearest_lane(const b2Body* body, const std::vector<const b2Body*>& lane_bodies) {
  const float y = body->GetWorldCenter().y;
  std::size_t nearest = 0;
  for (std::size_t lane = 1; lane < lane_bodies.size(); ++lane) {
    if (std::abs(y - lane_bodies[lane]->GetWorldCenter().y) < std::abs(y - lane_bodies[nearest]->GetWorldCenter().y)) {
      nearest = lane;
    }
  }
  return nearest;
}

LaneGrid lane_grid(const lessons::WorldFraming& framing, const Scene& scene, ImVec2 size, float free_width, float scale,
                   const std::function<ArrowRoom(float lane_height)>& arrows_at) {
  using Kind = lessons::View::Kind;
  const std::size_t lanes = framing.view.bodies.size();
  if (framing.view.kind != Kind::lanes) return {1, 1};
  if (lanes < 2 || !arrows_at || view_bodies(scene, framing.view).empty()) return {1, std::max<std::size_t>(lanes, 1)};
  free_width = std::max(free_width, 1.0f);
  size = ImVec2(std::max(size.x, 1.0f), std::max(size.y, 1.0f));
  const float edge = lane_ground_edge * scale;
  const b2AABB moving = moving_bounds(scene);
  std::size_t rows_before = 0;
  for (std::size_t columns = 1; columns <= lanes; ++columns) {
    const std::size_t rows = (lanes + columns - 1) / columns;
    if (rows == rows_before) continue;  // another column, and the lanes no taller
    rows_before = rows;
    const float height = size.y / static_cast<float>(rows);
    const ArrowRoom arrows = arrows_at(height);
    const float column_free = column_free_width(size.x, free_width, columns, columns - 1);
    const float pixels_per_metre =
        framing_scale(framing, scene, Kind::lanes, moving, ImVec2(size.x / static_cast<float>(columns), size.y), column_free,
                      height, edge, scale, arrows)
            .pixels_per_metre;
    if (arrows_fit(scene, arrows, pixels_per_metre, height - 2.0f * edge)) return {columns, rows};
  }
  return {1, lanes};
}

std::vector<Camera> framing_cameras(const lessons::WorldFraming& framing, const Scene& scene, ImVec2 origin, ImVec2 size,
                                    float free_width, float scale, const ViewAdjust& adjust, const ArrowRoom& arrows,
                                    std::size_t lane_columns, bool foot_clipped) {
  const lessons::View& view = framing.view;
  const std::vector<float>& lane_ground = framing.lane_ground;
  using Kind = lessons::View::Kind;
  // A window squeezed to nothing still gets a camera with a positive, finite scale.
  free_width = std::max(free_width, 1.0f);
  size = ImVec2(std::max(size.x, 1.0f), std::max(size.y, 1.0f));
  const std::vector<const b2Body*> bodies = view_bodies(scene, view);
  // What moves now, worked out once: the framing, the centre and each lane read it.
  const b2AABB moving = moving_bounds(scene);
  const Kind kind = bodies.empty() && view.kind != Kind::window ? Kind::whole : view.kind;
  const std::size_t strips = kind == Kind::lanes ? bodies.size() : 1;
  // The lanes in a grid (lane_grid): `columns` side by side, in reading order.
  const std::size_t columns = kind == Kind::lanes ? std::clamp<std::size_t>(lane_columns, 1, strips) : 1;
  const std::size_t rows = (strips + columns - 1) / columns;
  const float strip_height = size.y / static_cast<float>(rows);
  const float column_width = size.x / static_cast<float>(columns);
  // Pixels kept between what must show and a lane's top or bottom: the world's panel clips half
  // its padding off its edges.
  const float edge = lane_ground_edge * scale;
  // One scale for every lane, as the narrowest column's free width allows.
  const FramingScale framed =
      framing_scale(framing, scene, kind, moving, ImVec2(column_width, size.y),
                    column_free_width(size.x, free_width, columns, columns - 1), strip_height, edge, scale, arrows);
  const float pixels_per_metre = framed.pixels_per_metre;
  const bool zoomed_in = framed.zoomed_in;
  b2Vec2 centre = framing_centre(kind, zoomed_in, view, scene, bodies, moving);
  if (kind == Kind::whole) {
    // Not following what moves: a view that followed the block kept it still on the screen, and
    // only the floor's hatching showed that it moved (a teacher's projector trial). The view
    // stands still from where it framed the lesson at t = 0, and moves by a page when the
    // lesson has moved half a page. A page is as far as the lesson can move from the view's
    // centre with all of it still in view: it is at most 1/room of the view wide.
    const float page = free_width / pixels_per_metre * (1.0f - 1.0f / room);
    const float start = (zoomed_in ? framing.moving_centre : framing.lesson_centre).x;
    centre.x = start + page * std::round((centre.x - start) / page);
  }

  const b2AABB lesson = kind == Kind::whole && zoomed_in ? lesson_bounds(scene) : b2AABB{};
  std::vector<Camera> made;
  for (std::size_t i = 0; i < strips; ++i) {
    Camera camera;
    const std::size_t column = i % columns, row = i / columns;
    // A last row with fewer lanes shares the whole width among them (three lanes: two above, one
    // below as wide as both), rather than leave a cell empty.
    const std::size_t in_row = std::min(columns, strips - row * columns);
    const float width = size.x / static_cast<float>(in_row);
    const float lane_free = column_free_width(size.x, free_width, in_row, column);
    camera.origin = ImVec2(origin.x + width * static_cast<float>(column), origin.y + strip_height * static_cast<float>(row));
    camera.size = ImVec2(width, strip_height);
    camera.pixels_per_metre = pixels_per_metre * adjust.zoom;
    // A little below the middle: forces drawn above bodies need more room than the ground.
    // A window the script fixed is centred exactly, so all of it is in view.
    const float down = kind == Kind::window ? 0.5f : strips > 1 ? 0.6f : 0.56f;
    camera.anchor = ImVec2(camera.origin.x + 0.5f * lane_free, camera.origin.y + down * strip_height);

    camera.centre = centre;
    // Each lane on its own body's height.
    if (kind == Kind::lanes) {
      camera.centre.y = bodies[i]->GetWorldCenter().y;
      // Not so high that the floor under the body drops out of the lane's foot, while the
      // body's top stays in it: the lane stays still and the body falls to its floor.
      if (i < lane_ground.size() && std::isfinite(lane_ground[i])) {
        const float metres = 1.0f / camera.pixels_per_metre, edge_metres = edge * metres;
        const float floor_in_view = lane_ground[i] + (1.0f - down) * strip_height * metres - edge_metres;
        const float top_in_view = body_box(bodies[i]).upperBound.y + edge_metres - down * strip_height * metres;
        camera.centre.y = std::max(std::min(camera.centre.y, floor_in_view), top_in_view);
      }
      // Once the lanes' bodies have spread wider than the view, one window would lose some of
      // them: each lane then follows its own body (the ground's hatching still shows who moved).
      if ((moving.upperBound.x - moving.lowerBound.x) * camera.pixels_per_metre > 0.9f * lane_free) {
        camera.centre.x = bodies[i]->GetWorldCenter().x;
      }
      // Its arrows in the lane, the camera moved up or down as little as shows them.
      // (The world's panel clips the view's top, and its foot where no legend is under it.)
      if (arrows.longest > 0.0f) {
        show_lane_reach(camera, scene, bodies, i, arrows, edge, row == 0 ? edge : 0.0f,
                        row + 1 == rows && foot_clipped ? edge : 0.0f);
      }
    }
    if (kind == Kind::whole && zoomed_in) keep_within(camera, lesson, moving, free_width);
    // The arrows in the picture, at their drawn length (ArrowRoom): the view moves up or down as
    // little as shows them (a lane, its own body's), and a window the script fixed grew above to
    // hold them; centred on it, all of it is still in view. (A lane's were shown above.)
    if (arrows.longest > 0.0f && kind != Kind::lanes) {
      Reach reach = moving_reach(scene, arrows, camera.pixels_per_metre);
      if (kind == Kind::window) {
        // The window's corners, and the normal forces up from the feet it grew to hold.
        // From the highest foot of the run's start or now, as the window grew: the view does
        // not move up and down as a block slides.
        reach = {view.low.y, view.high.y};
        const float foot = highest_foot(framing, scene);
        if (std::isfinite(foot)) reach.high = std::max(reach.high, foot + arrows.longest / camera.pixels_per_metre);
      }
      show_reach(camera, reach, edge);
    }
    camera.centre += adjust.pan;
    made.push_back(camera);
  }
  return made;
}

}  // namespace frictionlab::draw
