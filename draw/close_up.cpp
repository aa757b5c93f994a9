#include "draw/close_up.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "draw/overlays.h"
#include "draw/text_record.h"
#include "draw/world_view.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {

float own_length(const b2Body* body) {
  b2Vec2 low(0.0f, 0.0f), high(0.0f, 0.0f);
  bool any = false;
  const auto take = [&](b2Vec2 point) {
    low = any ? b2Min(low, point) : point;
    high = any ? b2Max(high, point) : point;
    any = true;
  };
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    const b2Shape* shape = fixture->GetShape();
    if (shape->GetType() == b2Shape::e_polygon) {
      const auto& polygon = *static_cast<const b2PolygonShape*>(shape);
      for (int k = 0; k < polygon.m_count; ++k) take(polygon.m_vertices[k]);
    } else if (shape->GetType() == b2Shape::e_circle) {
      const auto& circle = *static_cast<const b2CircleShape*>(shape);
      take(circle.m_p - b2Vec2(circle.m_radius, circle.m_radius));
      take(circle.m_p + b2Vec2(circle.m_radius, circle.m_radius));
    }
  }
  return any ? std::max(high.x - low.x, high.y - low.y) : 0.0f;
}

namespace {

// How much of a corner's area the fixed bodies cover: points on a 12 by 8 grid over it, each
// in a fixed body's shape or not.
int covered_points(const Scene& scene, const Camera& world, ImVec4 place) {
  constexpr int across = 12, down = 8;
  int covered = 0;
  for (int i = 0; i <= across; ++i) {
    for (int j = 0; j <= down; ++j) {
      const ImVec2 at(place.x + (place.z - place.x) * static_cast<float>(i) / across,
                      place.y + (place.w - place.y) * static_cast<float>(j) / down);
      const b2Vec2 point = world.to_world(at);
      bool inside = false;
      for (const auto& [name, body] : scene.bodies()) {
        inside = body->GetType() == b2_staticBody && body_contains(body, point);
        if (inside) break;
      }
      covered += inside ? 1 : 0;
    }
  }
  return covered;
}

// The highest corner of the fixed bodies' polygons (incline's slope's top), if they have any.
std::optional<b2Vec2> highest_fixed_point(const Scene& scene) {
  std::optional<b2Vec2> top;
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_staticBody) continue;
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      if (fixture->GetShape()->GetType() != b2Shape::e_polygon) continue;
      const auto& polygon = *static_cast<const b2PolygonShape*>(fixture->GetShape());
      for (int k = 0; k < polygon.m_count; ++k) {
        const b2Vec2 point = body->GetWorldPoint(polygon.m_vertices[k]);
        if (!top || point.y > top->y) top = point;
      }
    }
  }
  return top;
}

}  // namespace

std::optional<CloseUp> close_up_place(const lessons::Lesson& lesson, const b2Body* body, const Camera& world,
                                      ImVec2 world_corner, ImVec2 world_size, float scale, float title_line) {
  if (body == nullptr || body->GetType() != b2_dynamicBody) return std::nullopt;
  if (lesson.view().kind != lessons::View::Kind::window) return std::nullopt;
  const float drawn = own_length(body) * world.pixels_per_metre;
  const float readable = min_body_pixels * scale;
  if (drawn <= 0.0f || drawn >= readable) return std::nullopt;
  // A quarter of the world's width and under two thirds of its height at most, room for the body twice
  // readable and its contact's word beside it: the rest of the window (incline's slope, its foot
  // and angle, and the values of the forces the world draws) stays in sight.
  const float margin = 6.0f * scale;
  const float width = std::min(0.25f * world_size.x, 300.0f * scale);
  const Scene& scene = lesson.scene();
  const float top = world_corner.y + margin;
  const float right_edge = world_corner.x + world_size.x - margin;
  const auto left = [&](float height) { return ImVec4(world_corner.x + margin, top, world_corner.x + margin + width, top + height); };
  const auto right = [&](float height) { return ImVec4(right_edge - width, top, right_edge, top + height); };
  // The corner the fixed bodies cover less; where they cover both alike, the one away from their
  // highest point, where a body set on them starts (incline's block, 5.5 m up its 6 m slope,
  // whose arrows and values need the sky above the slope's top). Lower where it would cover
  // them (a gentle slope crosses the whole window), down to a third of the world's height.
  const std::optional<b2Vec2> highest = highest_fixed_point(scene);
  const float middle = world_corner.x + 0.5f * world_size.x;
  const bool left_first = highest && world.to_screen(*highest).x > middle;
  std::optional<ImVec4> place;
  for (float height = std::min(0.62f * world_size.y, 240.0f * scale); height >= world_size.y / 3.0f && !place;
       height -= 4.0f * scale) {
    for (const ImVec4 corner : left_first ? std::array{left(height), right(height)} : std::array{right(height), left(height)}) {
      if (covered_points(scene, world, corner) == 0) {
        place = corner;
        break;
      }
    }
  }
  if (!place) return std::nullopt;
  CloseUp close_up;
  close_up.place = *place;
  close_up.title_strip = title_line + 8.0f * scale;
  // The body about half the close-up's height long, in whole times the world's zoom, and at
  // least readable; but standing whole in 85 % of the height under the title, turned
  // any way (incline's block at 60° stood into the title at half the height).
  const float under_title = place->w - place->y - close_up.title_strip;
  const float wanted = std::max(0.5f * (place->w - place->y), readable);
  close_up.zoom = std::max(2, static_cast<int>(std::ceil(wanted / drawn)));
  while (close_up.zoom > 2 && static_cast<float>(close_up.zoom) * drawn > 0.85f * under_title) --close_up.zoom;
  return close_up;
}

Camera close_up_camera(const CloseUp& close_up, const b2Body* body, const Camera& world) {
  Camera camera;
  camera.origin = ImVec2(close_up.place.x, close_up.place.y);
  camera.size = ImVec2(close_up.place.z - close_up.place.x, close_up.place.w - close_up.place.y);
  // The body in the middle of what the title leaves.
  camera.anchor = add(camera.origin, ImVec2(0.5f * camera.size.x, 0.5f * (camera.size.y + close_up.title_strip)));
  camera.centre = body->GetWorldCenter();
  camera.pixels_per_metre = world.pixels_per_metre * static_cast<float>(close_up.zoom);
  return camera;
}

void draw_close_up(ImDrawList* draw, const lessons::Lesson& lesson, const b2Body* body, const CloseUp& close_up,
                   const Camera& world, const Theme& theme, const Fonts& fonts, LabelPlacer& labels) {
  const float s = fonts.scale;
  const Camera camera = close_up_camera(close_up, body, world);
  const ImVec2 low = camera.origin, high = add(camera.origin, camera.size);
  draw->PushClipRect(low, high, true);
  // Its name first, in its top left corner, where the body's word and dot then keep off it.
  std::string name;
  for (const auto& [body_name, each] : lesson.scene().bodies()) {
    if (each == body) name = lessons::class_words(body_name);
  }
  const std::string title = name + ", close-up \u00d7" + std::to_string(close_up.zoom);
  const ImVec2 title_size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, title.c_str());
  const ImVec2 title_centre(low.x + 6.0f * s + 0.5f * title_size.x + 3.0f, low.y + 4.0f * s + 0.5f * title_size.y + 1.0f);
  labels.avoid(ImVec4(title_centre.x - 0.5f * title_size.x - 3.0f, title_centre.y - 0.5f * title_size.y - 1.0f,
                      title_centre.x + 0.5f * title_size.x + 3.0f, title_centre.y + 0.5f * title_size.y + 1.0f));
  // The body kept clear, its edges and inside: its contact's word goes by its dot, on the
  // slope's side, not over the body it is there to show (incline's word crossed its block's
  // corner at 35°, and lay inside it at 2°). Its box would also keep the word off the slope
  // beside a turned block, where it belongs.
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->GetType() != b2Shape::e_polygon) continue;
    const auto& shape = *static_cast<const b2PolygonShape*>(fixture->GetShape());
    b2Vec2 least = shape.m_vertices[0], most = least;
    for (int k = 0; k < shape.m_count; ++k) {
      least = b2Min(least, shape.m_vertices[k]);
      most = b2Max(most, shape.m_vertices[k]);
      labels.avoid(DrawnSegment{camera.to_screen(body->GetWorldPoint(shape.m_vertices[k])),
                                camera.to_screen(body->GetWorldPoint(shape.m_vertices[(k + 1) % shape.m_count])), 1.5f * s});
    }
    constexpr int across = 8, down = 4;
    for (int i = 1; i < across; ++i) {
      for (int j = 1; j < down; ++j) {
        const b2Vec2 local(least.x + (most.x - least.x) * static_cast<float>(i) / across,
                           least.y + (most.y - least.y) * static_cast<float>(j) / down);
        if (!shape.TestPoint(b2Transform(b2Vec2_zero, b2Rot(0.0f)), local)) continue;
        const ImVec2 at = camera.to_screen(body->GetWorldPoint(local));
        labels.avoid(ImVec4(at.x - 1.0f, at.y - 1.0f, at.x + 1.0f, at.y + 1.0f));
      }
    }
  }
  // The forces stay in the world's view, at the legend's scale: drawn here too they would be
  // the same values twice, at another length.
  const std::vector<const b2Body*> labelled{body};
  draw_world(draw, lesson, camera, theme, fonts, 1.0f, labels, &labelled, {}, WorldArrows::none);
  draw_label(draw, fonts.small, title_centre, theme.text, theme.panel, title.c_str());
  note_text_at(title.c_str(), ImRect(sub(title_centre, ImVec2(0.5f * title_size.x, 0.5f * title_size.y)),
                                     add(title_centre, ImVec2(0.5f * title_size.x, 0.5f * title_size.y))));
  draw->PopClipRect();
  draw->AddRect(low, high, theme.axis, 0.0f, 0, 1.5f * s);
}

}  // namespace frictionlab::draw
