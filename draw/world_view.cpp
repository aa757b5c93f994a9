#include "draw/world_view.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "draw/drawing.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {
namespace {

constexpr float pi = 3.14159265358979f;

// A label that names a place in the world (a slope's angle, a driven body), drawn with the
// world's other labels once every arrow, mark and moving body is known to the placer: near its
// place, off the moving bodies and every other label.
struct PlaceLabel {
  ImVec2 wanted;  // its centre, where it would go with nothing in the way
  std::string text;
  ImFont* font;
  ImU32 colour, background;
};

// A ground slab's surface line on the screen, as far as the view shows it (none where it is
// out of the view's width).
std::optional<DrawnSegment> ground_surface(const b2Fixture* fixture, const Camera& camera) {
  // Box2D's box around the fixture reaches its skin's outside, the skin's radius past the shape.
  const b2AABB& box = fixture->GetAABB(0);
  const float top = box.upperBound.y - fixture->GetShape()->m_radius;
  const float left = std::max(camera.origin.x, camera.to_screen(box.lowerBound).x);
  const float right = std::min(camera.origin.x + camera.size.x, camera.to_screen(box.upperBound).x);
  if (left >= right) return std::nullopt;
  const float top_y = camera.to_screen({0.0f, top}).y;
  return DrawnSegment{ImVec2(left, top_y), ImVec2(right, top_y), 1.25f};
}

// The ground in its material's colour, as far as it really goes (a body beyond its end falls).
void draw_ground(ImDrawList* draw, const Scene& scene, const b2Fixture* fixture, const Camera& camera,
                 const Theme& theme) {
  const std::optional<DrawnSegment> surface = ground_surface(fixture, camera);
  if (!surface) return;
  const b2AABB& box = fixture->GetAABB(0);
  const float skin = fixture->GetShape()->m_radius;
  const float top = box.upperBound.y - skin;
  const ImVec2 view_end = add(camera.origin, camera.size);
  const float left = surface->from.x, right = surface->to.x, top_y = surface->from.y;
  const float bottom_y = camera.to_screen({0.0f, box.lowerBound.y + skin}).y;
  draw->AddRectFilled(ImVec2(left, top_y), ImVec2(right, std::min(bottom_y, view_end.y)),
                      fixture_colour(scene, fixture, theme));
  // Hatching fixed to the ground, so the ground is seen to stay put while the view follows.
  const float spacing = nice_length(22.0f / camera.pixels_per_metre);
  const float first = std::floor(camera.to_world(ImVec2(left, top_y)).x / spacing) * spacing;
  const float depth = 12.0f;
  for (float x = first; camera.to_screen({x, top}).x < right + depth; x += spacing) {
    const float sx = camera.to_screen({x, top}).x;
    if (sx < left || sx > right) continue;
    draw->AddLine(ImVec2(sx, top_y + 1.0f), ImVec2(sx - depth, top_y + depth), theme.ground_edge, 1.5f);
  }
  draw->AddLine(surface->from, surface->to, theme.ground_edge, 2.0f * surface->half_width);
}

// Slopes: at a corner between a level edge and a sloping one, the angle between them.
void mark_slope_angles(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera,
                       const Theme& theme, const Fonts& fonts, std::vector<PlaceLabel>& place_labels) {
  const int n = shape.m_count;
  for (int i = 0; i < n; ++i) {
    const b2Vec2 corner = body->GetWorldPoint(shape.m_vertices[i]);
    const b2Vec2 to_prev = body->GetWorldPoint(shape.m_vertices[(i + n - 1) % n]) - corner;
    const b2Vec2 to_next = body->GetWorldPoint(shape.m_vertices[(i + 1) % n]) - corner;
    for (int flip = 0; flip < 2; ++flip) {
      const b2Vec2 level = flip == 0 ? to_prev : to_next;
      const b2Vec2 slope = flip == 0 ? to_next : to_prev;
      if (std::abs(level.y) > 1e-3f * level.Length()) continue;
      const float angle = std::acos(std::clamp(b2Dot(level, slope) / (level.Length() * slope.Length()), -1.0f, 1.0f));
      if (angle < 0.5f * pi / 180.0f || angle > 89.5f * pi / 180.0f) continue;
      ImVec2 centre = camera.to_screen(corner);
      // A short view (a projector's world row, 1.9 times the fonts over a third of the height)
      // gets a smaller arc rather than none: the angle is what the lesson is about.
      const float radius = std::min(46.0f * fonts.scale, 0.2f * camera.size.y);
      // A view zoomed in on a block may have left the corner out: the angle is then marked where
      // the slope first comes into view, with a dashed level line to measure it from.
      const auto shown = [&](ImVec2 p) {
        const float room = radius + 30.0f * fonts.scale;
        return p.x >= camera.origin.x + room && p.x <= camera.origin.x + camera.size.x - room &&
               p.y >= camera.origin.y + room && p.y <= camera.origin.y + camera.size.y - 8.0f * fonts.scale;
      };
      if (!shown(centre)) {
        // A lane's strip is too thin for a mark away from its block: the corner's mark or none.
        if (radius < 24.0f * fonts.scale) continue;
        bool found = false;
        for (int k = 1; k <= 200 && !found; ++k) {
          const ImVec2 p = camera.to_screen(corner + (static_cast<float>(k) / 200.0f) * slope);
          if (shown(p)) centre = p, found = true;
        }
        if (!found) continue;
        const b2Vec2 unit_level = (1.0f / level.Length()) * level;
        const ImVec2 end = camera.to_screen(camera.to_world(centre) + (1.4f * radius / camera.pixels_per_metre) * unit_level);
        for (int dash = 0; dash < 7; dash += 2) {
          const ImVec2 a = add(centre, mul(sub(end, centre), static_cast<float>(dash) / 7.0f));
          const ImVec2 b = add(centre, mul(sub(end, centre), static_cast<float>(dash + 1) / 7.0f));
          draw->AddLine(a, b, theme.text, 1.5f * fonts.scale);
        }
      }
      // Screen angles turn the other way: y points down.
      const float level_angle = -std::atan2(level.y, level.x);
      const float slope_angle = -std::atan2(slope.y, slope.x);
      float from = level_angle, to = slope_angle;
      if (to - from > pi) to -= 2.0f * pi;
      if (from - to > pi) to += 2.0f * pi;
      draw->PathArcTo(centre, radius, from, to, 24);
      draw->PathStroke(theme.text, 0, 2.0f);
      const float middle = 0.5f * (from + to);
      char text[16];
      std::snprintf(text, sizeof text, "%.3g°", static_cast<double>(angle * 180.0f / pi));
      const ImVec2 at = add(centre, ImVec2(std::cos(middle) * (radius + 24.0f * fonts.scale),
                                           std::sin(middle) * (radius + 12.0f * fonts.scale)));
      // On a box of its own, as "driven" is: beside the corner it lies over the sky, but where the
      // corner is out of view it lies over the slope's fill (the dark theme's 4.2:1 on grey).
      place_labels.push_back({at, text, fonts.body, theme.text, theme.panel});
    }
  }
}

void draw_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const Camera& camera, const Theme& theme,
               const Fonts& fonts, std::vector<PlaceLabel>& place_labels) {
  const bool driven = body->GetType() == b2_kinematicBody;
  const ImU32 outline = driven ? theme.driven_outline : theme.outline;
  const float thickness = (driven ? 3.0f : 1.5f) * fonts.scale;
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (lessons::is_ground(fixture)) {
      // A strip's edge is its surface; the slab under it is what is drawn.
      if (fixture->GetType() != b2Shape::e_edge) draw_ground(draw, scene, fixture, camera, theme);
      continue;
    }
    const ImU32 fill = fixture_colour(scene, fixture, theme);
    if (fixture->GetType() == b2Shape::e_polygon) {
      const auto& shape = *static_cast<const b2PolygonShape*>(fixture->GetShape());
      draw_polygon(draw, body, shape, camera, fill, outline, thickness);
      if (body->GetType() == b2_staticBody) mark_slope_angles(draw, body, shape, camera, theme, fonts, place_labels);
    } else if (fixture->GetType() == b2Shape::e_circle) {
      const auto& shape = *static_cast<const b2CircleShape*>(fixture->GetShape());
      const ImVec2 centre = camera.to_screen(body->GetWorldPoint(shape.m_p));
      const float radius = surface_radius(shape) * camera.pixels_per_metre;
      draw->AddCircleFilled(centre, radius, fill, 48);
      draw->AddCircle(centre, radius, outline, 48, thickness);
      // A spoke, so rolling can be told from sliding.
      const ImVec2 rim = camera.to_screen(body->GetWorldPoint(shape.m_p + b2Vec2{surface_radius(shape), 0.0f}));
      draw->AddLine(centre, rim, outline, thickness);
    }
  }
  if (driven) {
    // At its centre, unless a moving body sits there (wedge's block rests on its plank's
    // pivot): then further along the body, the first of a few points along its length that
    // no moving body covers.
    const auto covered = [&](b2Vec2 point) {
      for (const b2Body* other = scene.world().GetBodyList(); other != nullptr; other = other->GetNext()) {
        if (other->GetType() != b2_dynamicBody) continue;
        for (const b2Fixture* f = other->GetFixtureList(); f != nullptr; f = f->GetNext()) {
          b2AABB box;
          f->GetShape()->ComputeAABB(&box, other->GetTransform(), 0);
          box.lowerBound -= b2Vec2(0.1f, 0.1f), box.upperBound += b2Vec2(0.1f, 0.1f);
          if (point.x >= box.lowerBound.x && point.x <= box.upperBound.x && point.y >= box.lowerBound.y &&
              point.y <= box.upperBound.y) {
            return true;
          }
        }
      }
      return false;
    };
    b2AABB extent;
    extent.lowerBound = extent.upperBound = body->GetLocalCenter();
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      b2AABB box;
      fixture->GetShape()->ComputeAABB(&box, b2Transform(b2Vec2_zero, b2Rot(0.0f)), 0);
      extent.Combine(box);
    }
    const b2Vec2 centre = body->GetLocalCenter();
    const float reach = 0.5f * (extent.upperBound.x - extent.lowerBound.x);
    b2Vec2 at = body->GetWorldCenter();
    for (const float share : {0.0f, 0.1f, -0.1f, 0.2f, -0.2f, 0.35f, -0.35f}) {
      const b2Vec2 candidate = body->GetWorldPoint(b2Vec2(centre.x + share * reach, centre.y));
      if (!covered(candidate)) {
        at = candidate;
        break;
      }
    }
    place_labels.push_back({camera.to_screen(at), "driven", fonts.small, theme.driven_outline, theme.panel});
  }
}


// How far a spring's coils reach either side of its line, line width included.
float coil_reach(float scale) { return 8.0f * scale; }

// A coil spring: its turns spread out as it stretches and crowd as it is squeezed.
void draw_spring(ImDrawList* draw, ImVec2 from, ImVec2 to, const Theme& theme, float scale) {
  const ImVec2 along = sub(to, from);
  const float span = length(along);
  if (span < 1.0f) return;
  const ImVec2 unit = mul(along, 1.0f / span);
  const ImVec2 across(-unit.y, unit.x);
  constexpr int turns = 12;
  const float lead = 0.12f * span, amplitude = coil_reach(scale) - 1.0f * scale;
  std::vector<ImVec2> points;
  points.push_back(from);
  points.push_back(add(from, mul(unit, lead)));
  for (int i = 0; i < 2 * turns; ++i) {
    const float s = lead + (span - 2.0f * lead) * (static_cast<float>(i) + 0.5f) / (2.0f * turns);
    points.push_back(add(add(from, mul(unit, s)), mul(across, (i % 2 == 0 ? 1.0f : -1.0f) * amplitude)));
  }
  points.push_back(sub(to, mul(unit, lead)));
  points.push_back(to);
  draw->AddPolyline(points.data(), static_cast<int>(points.size()), theme.spring, 0, 2.0f * scale);
}

// The hand and its word, which labels placed later keep off.
void draw_hand(ImDrawList* draw, ImVec2 at, const Theme& theme, const Fonts& fonts, LabelPlacer& labels) {
  draw->AddCircleFilled(at, 7.0f * fonts.scale, theme.hand, 24);
  const ImVec2 word(at.x, at.y - 18.0f * fonts.scale);
  // No box behind it: its ink reads 4.5:1 on the sky it is drawn over (draw/theme.h).
  draw_label(draw, fonts.small, word, readable_ink(theme.hand, theme.sky), 0, "hand");
  const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, "hand");
  labels.avoid(ImVec4(word.x - 0.5f * size.x, word.y - 0.5f * size.y, word.x + 0.5f * size.x, at.y + 7.0f * fonts.scale));
}

std::optional<b2Vec2> pulley_holder(const Scene& scene, b2Vec2 axle) {
  std::optional<b2Vec2> nearest;
  float nearest_distance = std::numeric_limits<float>::max();
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_staticBody) continue;
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      if (fixture->GetType() != b2Shape::e_polygon) continue;
      const auto* shape = static_cast<const b2PolygonShape*>(fixture->GetShape());
      // The nearest point of each edge to the axle.
      for (int k = 0; k < shape->m_count; ++k) {
        const b2Vec2 from = body->GetWorldPoint(shape->m_vertices[k]);
        const b2Vec2 to = body->GetWorldPoint(shape->m_vertices[(k + 1) % shape->m_count]);
        const b2Vec2 edge = to - from;
        const float along = std::clamp(b2Dot(axle - from, edge) / std::max(edge.LengthSquared(), 1e-12f), 0.0f, 1.0f);
        const b2Vec2 point = from + along * edge;
        const float distance = (point - axle).Length();
        if (distance < nearest_distance) nearest_distance = distance, nearest = point;
      }
    }
  }
  return nearest;
}

void draw_ropes(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                float scale, LabelPlacer& labels) {
  for (const Rope& rope : lesson.scene().ropes()) {
    const ImVec2 a = camera.to_screen(rope.end_a()), b = camera.to_screen(rope.end_b());
    const ImVec2 ga = camera.to_screen(rope.pulley_a), gb = camera.to_screen(rope.pulley_b);
    // A slack rope sags: the rope it does not need hangs in the more level of its two stretches
    // (the block's, on a table), as deep as half of it, so a class sees that it pulls nothing.
    const float slack = rope.taut() ? 0.0f : std::max(rope.length - rope.stretches(), 0.0f);
    const bool sag_a = std::abs(a.x - ga.x) >= std::abs(b.x - gb.x);
    const auto stretch = [&](ImVec2 end, ImVec2 pulley, bool sags) {
      if (!sags || slack <= 0.0f) {
        draw->AddLine(end, pulley, theme.rope, 2.5f * scale);
        return;
      }
      const ImVec2 low(0.5f * (end.x + pulley.x), 0.5f * (end.y + pulley.y) + 0.5f * slack * camera.pixels_per_metre);
      draw->AddBezierQuadratic(end, low, pulley, theme.rope, 2.5f * scale);
    };
    stretch(a, ga, sag_a);
    draw->AddLine(ga, gb, theme.rope, 2.5f * scale);
    stretch(b, gb, !sag_a);
    const ImVec2 middle = mul(add(ga, gb), 0.5f);
    const float radius = std::max(0.5f * length(sub(gb, ga)), 8.0f * scale);
    // What holds the pulley: an arm from the nearest fixed body (pulley's table corner) to its
    // axle, under the wheel. Without it the wheel hung over empty space (a teacher's trial).
    if (const std::optional<b2Vec2> held = pulley_holder(lesson.scene(), 0.5f * (rope.pulley_a + rope.pulley_b))) {
      draw->AddLine(camera.to_screen(*held), middle, theme.outline, 5.0f * scale);
      labels.avoid(DrawnSegment{camera.to_screen(*held), middle, 5.0f * scale});
    }
    draw->AddCircle(middle, radius, theme.outline, 32, 2.0f * scale);
    // The wheel and its arm are seen whole: no value goes over them.
    labels.avoid(ImVec4(middle.x - radius, middle.y - radius, middle.x + radius, middle.y + radius));
    draw->AddCircleFilled(middle, 3.0f * scale, theme.outline, 12);
  }
}


// A frictionless contact in neither state's colour: the outline's, as the bodies are drawn.
ImU32 contact_colour(const ContactMark& mark, const Theme& theme) {
  return mark.frictionless ? theme.outline : mark.state == ContactState::slipping ? theme.slipping : theme.sticking;
}

// Whether a world point lies on a body's outline, within `reach` (m): on or in one of its
// shapes, and with a point that near it outside all of them.
bool on_outline(const b2Body* body, b2Vec2 point, float reach) {
  const b2Vec2 ways[] = {{reach, 0.0f}, {-reach, 0.0f}, {0.0f, reach}, {0.0f, -reach}};
  bool near_inside = body_contains(body, point), near_outside = false;
  for (const b2Vec2& way : ways) {
    const bool in = body_contains(body, point + way);
    near_inside = near_inside || in;
    near_outside = near_outside || !in;
  }
  return near_inside && near_outside;
}

// A contact's dot, in its state's colour.
void draw_contact_dot(ImDrawList* draw, const ContactMark& mark, const Camera& camera, const Theme& theme, float scale) {
  const ImVec2 at = camera.to_screen(mark.point);
  const float r = contact_dot_radius * scale;
  draw->AddCircleFilled(at, r, contact_colour(mark, theme), 20);
  draw->AddCircle(at, r, theme.background, 20, 1.5f);
}

// A contact's word ("sticking", "← slipping") placed by its dot, to be drawn.
struct PlacedWord {
  const ContactMark* mark = nullptr;
  std::string text;
  std::optional<ImVec2> at;
  bool near_dot = false;  // within a line (its height) of the dot's rim, where a class reads it as the dot's
  std::optional<DrawnSegment> leader;  // from the dot's rim to the word, where it stands further off
};

// `kept`: where it stood when placed before the values, taken again where that is still free.
PlacedWord place_contact_word(const ContactMark& mark, const Camera& camera, const Fonts& fonts, LabelPlacer& labels,
                              const PlacedWord* kept = nullptr) {
  const ImVec2 at = camera.to_screen(mark.point);
  PlacedWord word{&mark, contact_word(mark), std::nullopt, false, std::nullopt};
  const std::string& text = word.text;
  const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, text.c_str());
  if (kept != nullptr && kept->at && labels.free(LabelPlacer::box_around(*kept->at, size), false)) {
    labels.take(LabelPlacer::box_around(*kept->at, size), text);
    return *kept;
  }
  // Into the lower body, the surface, where nothing else is drawn, and to the side the friction
  // arrow does not point to.
  const b2Vec2 into = -upper_side(mark) * b2Cross(1.0f, mark.tangent);
  const float side = mark.friction_force > 0.0 ? -1.0f : 1.0f;
  const b2Vec2 along = side * mark.tangent;
  // The word's box by the dot, its nearest corner (or edge) 10 px across and 8 px down from it
  // at text scale 1: the way to go (along and into, on the screen) scaled so that its larger part
  // is one box's half and the gap. On a floor that is the box beside the dot and under the
  // surface; on a slope the box keeps as close. (Half the box's width along a 60° slope put
  // "← slipping" 120 px from its dot on a projector, issue 31.)
  const auto by_dot = [&](b2Vec2 sideways) {
    ImVec2 way(sideways.x + into.x, -sideways.y - into.y);
    const float larger = std::max(std::abs(way.x), std::abs(way.y));
    way = larger > 0.0f ? mul(way, 1.0f / larger) : ImVec2(0.0f, 1.0f);
    return ImVec2(at.x + way.x * (0.5f * size.x + 10.0f * fonts.scale), at.y + way.y * (0.5f * size.y + 8.0f * fonts.scale));
  };
  // Where that is taken (a slope's weight arrow passes just by the dot), the places by the dot
  // under the surface round to the friction arrow's side, before the search around the first,
  // which went a line and a half away on incline at 35°.
  for (int step = 0; step <= 8; ++step) {
    const float turn = 1.0f - 0.25f * static_cast<float>(step);  // in quarters, from the side away from friction
    const ImVec2 place = by_dot(turn * along);
    if (labels.free(LabelPlacer::box_around(place, size), false)) {
      labels.take(LabelPlacer::box_around(place, size), text);
      word.at = place;
      word.near_dot = true;
      return word;
    }
  }
  // How far a box centred at `centre` lies from the dot's rim.
  const float rim = contact_dot_radius * fonts.scale;
  const auto off_rim = [&](ImVec2 centre) {
    // The text's box, as the class sees it, without the placer's padding.
    const ImVec4 box(centre.x - 0.5f * size.x, centre.y - 0.5f * size.y, centre.x + 0.5f * size.x, centre.y + 0.5f * size.y);
    const float dx = std::max({box.x - at.x, 0.0f, at.x - box.z});
    const float dy = std::max({box.y - at.y, 0.0f, at.y - box.w});
    return std::hypot(dx, dy) - rim;
  };
  // Those taken too (a stack's contact, hemmed in by the forces at it and their values): every
  // free place within a line of the dot's rim under the surface, an eighth of a line apart round
  // it, the nearest to the first place. The search round the first place alone put
  // stacked_blocks' "← slipping" in the middle of the lower block, 150 px from its dot, where a
  // place by the dot's other side was free (issue 31).
  const ImVec2 first = by_dot(along);
  // An eighth of a line apart: at a screen's text a quarter (3.5 px) missed the one place by
  // stacked_blocks' dot, 1.5 px wide between two arrows' margins.
  const float eighth = 0.125f * size.y;
  const float reach_x = 0.5f * size.x + rim + size.y, reach_y = 0.5f * size.y + rim + size.y;
  const ImVec2 into_screen(into.x, -into.y);
  // Whether a place (a box's centre) lies under the surface, into the lower body.
  const auto under_the_surface = [&](ImVec2 place) {
    return (place.x - at.x) * into_screen.x + (place.y - at.y) * into_screen.y > 0.0f;
  };
  // Off the bodies' outlines (`nearest`) before across one (`nearest_across`, taken only where
  // no leader finds a place either: across the top block's lower edge, stacked_blocks' "sticking"
  // was read as the top block's); apart from the other labels before not.
  std::optional<ImVec2> nearest, nearest_across;
  float nearest_score = std::numeric_limits<float>::max(), across_score = nearest_score;
  for (float dy = -reach_y; dy <= reach_y; dy += eighth) {
    for (float dx = -reach_x; dx <= reach_x; dx += eighth) {
      const ImVec2 place(at.x + dx, at.y + dy);
      // Under the surface only: a box over the upper body's face is read as that body's (terrain's
      // "slipping →" over its box's corner).
      if (!under_the_surface(place) || off_rim(place) > size.y || !labels.free(LabelPlacer::box_around(place, size), false)) continue;
      const ImVec4 box = LabelPlacer::box_around(place, size);
      const float score = (labels.apart(box) ? 0.0f : 1e6f) + length(sub(place, first));
      if (labels.off_outlines(box)) {
        if (score < nearest_score) nearest_score = score, nearest = place;
      } else if (score < across_score) {
        across_score = score, nearest_across = place;
      }
    }
  }
  if (nearest) {
    labels.take(LabelPlacer::box_around(*nearest, size), text);
    word.at = nearest;
    word.near_dot = true;
    return word;
  }
  // None free there either: the nearest free place around the first, if that is within a line
  // of the dot's rim still, under the surface and across no body's edge. Taken wherever it was
  // within the line, stacked_blocks' "sticking" lay across the top block's lower edge at 1 s on
  // a projector, read as the top block's. (Found anywhere round the first place, it is also the
  // place of last resort, below.)
  LabelPlacer searched = labels;
  const std::optional<ImVec2> anywhere = searched.place_if_free(first, size, text);
  if (anywhere && off_rim(*anywhere) <= size.y && under_the_surface(*anywhere) &&
      labels.off_outlines(LabelPlacer::box_around(*anywhere, size))) {
    labels = std::move(searched);
    word.at = anywhere;
    word.near_dot = true;
    return word;
  }
  // Else the nearest free place under the surface from which a thin line in the word's colour,
  // from the dot's rim to the word's box and no longer than a value's leader, crosses no arrow
  // (but within a line of the dot, where the contact's own forces start), no label and no other
  // mark. Placed wherever it was free, stacked_blocks' "sticking" stood 131 px from its dot on a
  // projector, in the middle of the bottom block, from 2 s to the top block's slip (a teacher's
  // trial, issue 31).
  const float longest = LabelPlacer::longest_leader(size);
  const float leader_reach_x = 0.5f * size.x + rim + longest, leader_reach_y = 0.5f * size.y + rim + longest;
  const float quarter = 0.25f * size.y;
  const auto leader_to = [&](const ImVec4& box) {
    const ImVec2 on_box(std::clamp(at.x, box.x, box.z), std::clamp(at.y, box.y, box.w));
    const ImVec2 way = sub(on_box, at);
    const float reach = length(way);
    const ImVec2 unit = reach > 0.0f ? mul(way, 1.0f / reach) : ImVec2(0.0f, 1.0f);
    return DrawnSegment{add(at, mul(unit, rim + 1.5f)), on_box, 0.75f * fonts.scale};
  };
  const auto leader_clear = [&](const DrawnSegment& leader) {
    const ImVec2 way = sub(leader.to, leader.from);
    const float reach = length(way);
    if (reach > longest) return false;
    const auto crosses_box = [&](const ImVec4& box) { return overlaps(box, leader); };
    const auto own_dot = [&](const ImVec4& box) { return at.x >= box.x && at.x <= box.z && at.y >= box.y && at.y <= box.w; };
    const std::vector<ImVec4>& marks = labels.marks();
    if (std::any_of(labels.labels().begin(), labels.labels().end(), crosses_box)) return false;
    if (std::any_of(marks.begin(), marks.end(), [&](const ImVec4& other) { return !own_dot(other) && crosses_box(other); })) return false;
    if (reach <= size.y) return true;
    const DrawnSegment past_the_contact{add(leader.from, mul(way, size.y / reach)), leader.to, leader.half_width};
    // Clear of each line as drawn: an arrow is known by the width labels keep off it, four times
    // its shaft's half; half of that holds the shaft and its outline.
    return std::none_of(labels.segments().begin(), labels.segments().end(), [&](const DrawnSegment& line) {
      return gap(past_the_contact, line) < 0.5f * line.half_width + past_the_contact.half_width;
    });
  };
  std::optional<ImVec2> led;
  float led_score = std::numeric_limits<float>::max();
  for (float dy = -leader_reach_y; dy <= leader_reach_y; dy += quarter) {
    for (float dx = -leader_reach_x; dx <= leader_reach_x; dx += quarter) {
      const ImVec2 place(at.x + dx, at.y + dy);
      if (!under_the_surface(place)) continue;
      const ImVec4 box = LabelPlacer::box_around(place, size);
      if (!labels.free(box, false)) continue;
      // Wholly on a body and clear of the other labels where it can be, as the places by the dot.
      const float score = (labels.off_outlines(box) ? 0.0f : 2e6f) + (labels.apart(box) ? 0.0f : 1e6f) + off_rim(place);
      if (score < led_score && leader_clear(leader_to(box))) led_score = score, led = place;
    }
  }
  if (led) {
    labels.take(LabelPlacer::box_around(*led, size), text);
    word.at = led;
    word.leader = leader_to(LabelPlacer::box_around(*led, size));
    labels.avoid(*word.leader);
    return word;
  }
  if (nearest_across) {
    labels.take(LabelPlacer::box_around(*nearest_across, size), text);
    word.at = nearest_across;
    word.near_dot = true;
    return word;
  }
  labels = std::move(searched);
  word.at = anywhere;
  word.near_dot = anywhere && off_rim(*anywhere) <= size.y;
  return word;
}

void draw_contact_word(ImDrawList* draw, const PlacedWord& word, const Theme& theme, const Fonts& fonts) {
  if (!word.at) return;
  const ImU32 colour = contact_colour(*word.mark, theme);
  if (word.leader) draw->AddLine(word.leader->from, word.leader->to, colour, 2.0f * word.leader->half_width);
  draw_label(draw, fonts.small, *word.at, colour, theme.panel, word.text.c_str());
}

}  // namespace

namespace {

// A friction acts at its contact's point, where the contact's dot is drawn: one shorter than
// the dot's radius (stacked_blocks' friction between the blocks, a few newtons) lay under the
// dot and was not seen. It starts at the dot's rim instead, along its own direction, with its
// length kept (the length is the force's measure, the dot says where it acts).
void start_frictions_past_their_dots(std::vector<ScreenArrow>& arrows, const std::vector<ContactMark>& marks,
                                     const Camera& camera, float mark_radius) {
  for (ScreenArrow& arrow : arrows) {
    if (arrow.force.kind != ForceKind::friction) continue;
    const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length());
    // Feet close together: past one dot's rim may be under the next, so on until under none
    // (each move is forward along the arrow, so a dot is passed at most once).
    for (std::size_t moves = 0; moves < marks.size(); ++moves) {
      const auto under = std::find_if(marks.begin(), marks.end(), [&](const ContactMark& mark) {
        return length(sub(arrow.tail, camera.to_screen(mark.point))) < mark_radius;
      });
      if (under == marks.end()) break;
      const ImVec2 dot = camera.to_screen(under->point);
      // To the rim along the arrow's line, and past the dot's 1.5 px outline.
      const ImVec2 from_dot = sub(arrow.tail, dot);
      const float along = from_dot.x * unit.x + from_dot.y * unit.y;
      const float across_squared = std::max(0.0f, from_dot.x * from_dot.x + from_dot.y * from_dot.y - along * along);
      const float to_rim = std::sqrt(std::max(0.0f, mark_radius * mark_radius - across_squared)) - along + 1.5f;
      const ImVec2 shift = mul(unit, to_rim);
      arrow.tail = add(arrow.tail, shift);
      arrow.tip = add(arrow.tip, shift);
    }
  }
}

// The cross product's z of two screen vectors: which way one turns from the other, and by how
// much (for where two arrows' lines meet).
float cross2(ImVec2 a, ImVec2 b) { return a.x * b.y - a.y * b.x; }

// Whether two arrows' centre lines, each taken a thickness longer at both ends, cross: a margin
// for the heads and halos (a rough one: uncross_arrows measures a head's reach exactly). Parallel
// shafts lie side by side, and a zero-length one crosses nothing.
bool shafts_cross(const ScreenArrow& one, const ScreenArrow& other, float thickness) {
  const ImVec2 d = sub(one.tip, one.tail), e = sub(other.tip, other.tail), w = sub(other.tail, one.tail);
  const float denominator = cross2(d, e);
  if (std::abs(denominator) <= 1e-6f * length(d) * length(e)) return false;
  const float on_one = cross2(w, e) / denominator * length(d), on_other = cross2(w, d) / denominator * length(e);
  return on_one > -thickness && on_one < length(d) + thickness && on_other > -thickness && on_other < length(e) + thickness;
}

// Between two dynamic bodies (moved by their forces) a contact's friction is a pair, equal and
// opposite, one on each:
// drawn from the same dot, stacked_blocks' two 2.2 N frictions between its blocks lay over each
// other on the surface, and nothing said which block each pushed (a teacher's trial, issue 31).
// Each is drawn on its own body's side of the surface instead, just inside the body it acts on,
// as a textbook draws a pair on the two bodies it separates: moved across its own line (its
// direction and length kept), by one and a half thicknesses,
// so that the two shafts stand two thicknesses apart. A friction from a body that does not
// move by its forces (the floor, a driven plank) has no drawn partner and stays on the surface.
// So does one that, once started past its dot (start_frictions_past_their_dots), would cross
// another force's shaft but a weight's (a weight is drawn beneath a contact's forces)
// (the lower block's normal force from the floor, its head just under the surface): a crossing
// slides the friction away from its dot along its line (uncross_arrows), and a class reads where
// a force acts off where it starts. `started` starts frictions past their dots. Until no
// friction goes back: one put back may clear the way of another put back before it.
void place_friction_pairs_on_their_own_sides(std::vector<ScreenArrow>& arrows, const Camera& camera, float thickness,
                                            const std::function<void(std::vector<ScreenArrow>&)>& started) {
  std::vector<ScreenArrow> on_the_surface = arrows;
  started(on_the_surface);
  std::vector<bool> moved(arrows.size(), false);
  for (std::size_t i = 0; i < arrows.size(); ++i) {
    ScreenArrow& arrow = arrows[i];
    if (arrow.force.kind != ForceKind::friction || arrow.force.other == nullptr ||
        arrow.force.other->GetType() != b2_dynamicBody) {
      continue;
    }
    const float reach = arrow.length();
    if (!(reach > 0.0f)) continue;
    const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / reach);
    const ImVec2 across(-unit.y, unit.x);
    const ImVec2 to_centre = sub(camera.to_screen(arrow.force.body->GetWorldCenter()), arrow.tail);
    const float side = to_centre.x * across.x + to_centre.y * across.y >= 0.0f ? 1.0f : -1.0f;
    const ImVec2 shift = mul(across, side * 1.5f * thickness);
    arrow.tail = add(arrow.tail, shift);
    arrow.tip = add(arrow.tip, shift);
    moved[i] = true;
  }
  started(arrows);
  // A rough test of a crossing is enough here: uncross_arrows slides what it leaves.
  for (bool put_back = true; put_back;) {
    put_back = false;
    for (std::size_t i = 0; i < arrows.size(); ++i) {
      if (!moved[i]) continue;
      for (std::size_t j = 0; j < arrows.size(); ++j) {
        if (j == i || arrows[j].force.kind == ForceKind::weight || !shafts_cross(arrows[i], arrows[j], thickness)) continue;
        arrows[i] = on_the_surface[i];
        moved[i] = false;
        put_back = true;
        break;
      }
    }
  }
}

// Arrows of different bodies along one line, side by side: place_arrows sets apart one body's
// own (weight and normal force), but stacked_blocks' forces all lie on the blocks' middle line,
// and the top block's weight ran on past the surface under the normal force the top block
// presses the bottom one with, drawn over it: a stub was all a class saw of it, and no one
// could tell which arrow was which block's (a teacher's trial, issue 31). A weight stays at its
// centre of mass and a friction at its contact's dot, its surface its line (a weight over a
// friction passes beneath it, uncross_arrows). Every other arrow keeps its place where no arrow
// lies over it along its line (under `gap` across, overlapping along it, another body's heads
// meeting nose to nose within a gap included); else it moves across its line (direction and
// length kept) to the place a gap clear of every such arrow placed before it (the longest
// first) that moves it least, at most two gaps (a normal force stays by its contact), crossing
// the fewest other shafts there (stacked_blocks' normal force on the bottom block goes to the
// side its own friction does not run along), the screen's left or top where those tie; where
// none is clear within two gaps it stays. Two arrows from one point in opposite directions (a
// contact's normal forces, each into its own body) lie along one line and stay there, a pair.
void set_apart_along_one_line(std::vector<ScreenArrow>& arrows, float gap, float thickness) {
  const auto unit_of = [](const ScreenArrow& arrow) { return mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length()); };
  const auto parallel = [&](const ScreenArrow& p, const ScreenArrow& q) {
    return std::abs(cross2(unit_of(p), unit_of(q))) <= 0.17f;  // within 10°
  };
  // Whether `p` moved `shift` px across its line lies over `q`: its ends' places along p's line.
  const auto lies_over = [&](const ScreenArrow& p, float shift, const ScreenArrow& q) {
    const ImVec2 u = unit_of(p), across(-u.y, u.x);
    const ImVec2 w0 = sub(q.tail, p.tail), w1 = sub(q.tip, p.tail);
    const float offset = w0.x * across.x + w0.y * across.y - shift;
    if (std::abs(offset) >= gap - 0.01f) return false;
    const float q0 = w0.x * u.x + w0.y * u.y, q1 = w1.x * u.x + w1.y * u.y;
    const bool pair_from_one_point = std::abs(q0) < 1.0f && std::abs(offset) < 1.0f && q1 < q0;
    if (pair_from_one_point) return false;
    // One body's own heads meeting are place_arrows' to judge (it leaves them), not this pass's.
    const float ends = q.force.body == p.force.body ? 0.0f : gap;
    return std::max(q0, q1) > -ends && std::min(q0, q1) < p.length() + ends;
  };
  // How many shafts of arrows not along p's line p's crosses, moved `shift` across (each line a
  // thickness longer at both ends, for heads and halos).
  const auto crossings = [&](const ScreenArrow& p, float shift) {
    const ImVec2 u = unit_of(p), move = mul(ImVec2(-u.y, u.x), shift);
    ScreenArrow moved = p;
    moved.tail = add(p.tail, move);
    moved.tip = add(p.tip, move);
    int count = 0;
    for (const ScreenArrow& q : arrows) {
      if (&q != &p && q.length() > 0.0f && !parallel(p, q)) count += shafts_cross(moved, q, thickness);
    }
    return count;
  };
  const auto stays = [&](const ScreenArrow& arrow) {
    return arrow.force.kind == ForceKind::weight || arrow.force.kind == ForceKind::friction || !(arrow.length() > 0.0f);
  };
  std::vector<std::size_t> order(arrows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  // Those that stay first; then the longest, lengths within a pixel taken in the arrows' order
  // (a contact's two normal forces, equal but for the floats' last digits, every frame alike).
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (stays(arrows[a]) != stays(arrows[b])) return stays(arrows[a]);
    return arrows[a].length() > arrows[b].length() + 1.0f;
  });
  std::vector<std::size_t> placed;
  for (const std::size_t i : order) {
    ScreenArrow& arrow = arrows[i];
    // Where it stands, its own body's arrows are place_arrows' to have set apart (a block's six
    // feet's normal forces stand closer than a gap, and their heads by each other); a place it
    // moves to keeps clear of them too.
    const auto clear_at = [&](float shift) {
      return std::none_of(placed.begin(), placed.end(), [&](std::size_t j) {
        return (std::abs(shift) >= 0.01f || arrows[j].force.body != arrow.force.body) && parallel(arrow, arrows[j]) &&
               lies_over(arrow, shift, arrows[j]);
      });
    };
    if (stays(arrow) || clear_at(0.0f)) {
      placed.push_back(i);
      continue;
    }
    const ImVec2 u = unit_of(arrow), across(-u.y, u.x);
    // Which way is the screen's left (or, across a level arrow, its top).
    const float leftward = std::abs(across.x) > 0.01f ? across.x : across.y;
    std::vector<float> shifts;
    for (const std::size_t j : placed) {
      if (!parallel(arrow, arrows[j])) continue;
      const ImVec2 w = sub(arrows[j].tail, arrow.tail);
      const float offset = w.x * across.x + w.y * across.y;
      for (const float shift : {offset - gap, offset + gap}) {
        if (std::abs(shift) <= 2.0f * gap + 0.01f) shifts.push_back(shift);
      }
    }
    std::optional<float> best;
    int best_crossings = 0;
    for (const float shift : shifts) {
      if (!clear_at(shift)) continue;
      const int crossed = crossings(arrow, shift);
      const bool nearer = best && std::abs(shift) < std::abs(*best) - 0.25f * gap;
      const bool as_near = best && std::abs(std::abs(shift) - std::abs(*best)) <= 0.25f * gap;
      const bool better = !best || nearer ||
                          (as_near && (crossed < best_crossings ||
                                       (crossed == best_crossings && shift * leftward < *best * leftward - 0.01f)));
      if (better) best = shift, best_crossings = crossed;
    }
    if (best) {
      const ImVec2 move = mul(across, *best);
      arrow.tail = add(arrow.tail, move);
      arrow.tip = add(arrow.tip, move);
    }
    placed.push_back(i);
  }
}

// Two arrows whose shafts cross read as a tangle: push's friction, from a contact right of the
// block's middle, crossed the shaft of the weight, which reaches past the floor, and its push
// crossed the normal force's (issue 31). Two kinds of force never move along their lines here:
// a contact's forces (friction, normal force) stay at their contact, where its dot is, for the
// class reads where a force acts off where it starts (sliding tipping_box's friction past the
// weight drew it from the middle of its bottom while the box stood on its corner); and a weight
// stays at its body's centre of mass, as a textbook draws it (sliding it back up its line until
// it cleared a contact's arrow started push's weight 50 px above its block, read as a push from
// above: a teacher's trial, issue 31). Where a weight meets a contact's force, neither moves: the
// contact's forces are drawn after every other (draw_world), over the weight, so the friction is
// seen whole from its dot and the weight passes beneath it, as in a textbook's figure. Any other
// force that meets a contact's force or a weight slides forward along its own line (which keeps
// its moment about every point) past it, as push's push past its normal force. Of two other forces, or of
// two of contacts (stacked_blocks' friction and normal forces between and under its blocks),
// the shorter slides forward until it starts a thickness past the longer's shaft.
// Crossings within half a thickness of the mover's tail are forces starting together, and stay.
void uncross_arrows(std::vector<ScreenArrow>& arrows, float thickness) {
  const auto at_contact = [](const ScreenArrow& arrow) {
    return arrow.force.kind == ForceKind::friction || arrow.force.kind == ForceKind::normal;
  };
  const auto weight = [](const ScreenArrow& arrow) { return arrow.force.kind == ForceKind::weight; };
  const auto stays = [&](const ScreenArrow& arrow) { return at_contact(arrow) || weight(arrow); };
  const float halo = arrow_halo_width(thickness);
  const auto slide = [](ScreenArrow& arrow, float by) {
    const ImVec2 shift = mul(sub(arrow.tip, arrow.tail), by / arrow.length());
    arrow.tail = add(arrow.tail, shift);
    arrow.tip = add(arrow.tip, shift);
  };
  // Moves `mover` forward off `fixed`'s arrow, which stays; whether it moved. Its head (draw_arrow's:
  // 0.45 of it each side) and both halos are measured along the fixed arrow's line: a head that
  // only comes down on the fixed arrow's tail counts as meeting it.
  const auto off_the_fixed = [&](ScreenArrow& mover, const ScreenArrow& fixed) {
    const ImVec2 d = sub(mover.tip, mover.tail), e = sub(fixed.tip, fixed.tail), w = sub(fixed.tail, mover.tail);
    const float denominator = cross2(d, e);
    if (std::abs(denominator) < 1e-6f * length(d) * length(e)) return false;  // parallel: side by side already
    const float sine = std::abs(denominator) / (length(d) * length(e));
    // Where the mover's line meets the fixed one's, px from the mover's tail and from the fixed one's tail.
    const float on_mover = cross2(w, e) / denominator * length(d), on_fixed = cross2(w, d) / denominator * length(e);
    const float head = std::min(4.0f * thickness, 0.6f * length(d));
    const float reach = (0.45f * head + 2.0f * halo) / sine;
    // Its tip stops half the fixed arrow's thickness and both halos short of the fixed one's line.
    const float short_of = (0.5f * thickness + 2.0f * halo) / sine;
    if (on_fixed <= -reach || on_fixed >= length(e) + reach) return false;
    if (on_mover <= 0.5f * thickness / sine || on_mover >= length(d) + short_of) return false;
    slide(mover, on_mover + thickness / sine);
    return true;
  };
  for (std::size_t round = 0; round < arrows.size(); ++round) {
    bool moved = false;
    for (ScreenArrow& shorter : arrows) {
      for (ScreenArrow& other : arrows) {
        if (&shorter == &other) continue;
        if (stays(other) && !stays(shorter)) {
          moved = off_the_fixed(shorter, other) || moved;
          continue;
        }
        // A weight never moves, nor does a contact's force for one: it is drawn over the weight.
        if (weight(shorter) || weight(other) || at_contact(shorter) != at_contact(other) ||
            other.length() <= shorter.length()) {
          continue;
        }
        const ScreenArrow& longer = other;
        const ImVec2 d = sub(shorter.tip, shorter.tail), e = sub(longer.tip, longer.tail), w = sub(longer.tail, shorter.tail);
        const float denominator = cross2(d, e);
        if (std::abs(denominator) < 1e-6f * length(d) * length(e)) continue;  // parallel: side by side already
        const float on_shorter = cross2(w, e) / denominator, on_longer = cross2(w, d) / denominator;
        if (on_shorter <= 0.0f || on_shorter >= 1.0f || on_longer <= 0.0f || on_longer >= 1.0f) continue;
        // The longer shaft's width measured along the shorter's line.
        const float sine = std::abs(denominator) / (length(d) * length(e));
        const float to_crossing = on_shorter * length(d);
        if (to_crossing <= 0.5f * thickness / sine) continue;
        slide(shorter, to_crossing + thickness / sine);
        moved = true;
      }
    }
    if (!moved) break;
  }
}

// Marks each arrow that lies over a fill it does not stand out from: a body, a ground's slab or
// the sky under 3:1 against its colour (WCAG 2.1's non-text contrast), tested every half
// thickness along its shaft and just past its outline either side. Its thin outline alone showed driven_wheel's dark grey weight on
// the dark rubber wheel as an empty arrow (a teacher's trial, issue 31); such an arrow is drawn
// on a plate (draw_arrow's `plate`). For every arrow and fill, not for one lesson.
void mark_arrows_over_their_like(std::vector<ScreenArrow>& arrows, const Scene& scene, const Camera& camera,
                                 const Theme& theme, float thickness) {
  for (ScreenArrow& arrow : arrows) {
    const ImU32 colour = theme.force[static_cast<int>(arrow.force.kind)];
    const auto like = [&](ImU32 fill) { return contrast_ratio(colour, fill) < 3.0; };
    const int samples = std::max(2, static_cast<int>(arrow.length() / (0.5f * thickness)));
    const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length());
    // Along its centre line and just past its outline each side: a friction along a floor's
    // surface lies half over the floor.
    const ImVec2 beside = mul(ImVec2(-unit.y, unit.x), 0.5f * thickness + arrow_halo_width(thickness) + 1.0f);
    for (int k = 0; k <= 3 * samples + 2 && !arrow.over_its_like; ++k) {
      const ImVec2 on_line = add(arrow.tail, mul(sub(arrow.tip, arrow.tail), static_cast<float>(k / 3) / static_cast<float>(samples)));
      const ImVec2 at = k % 3 == 0 ? on_line : k % 3 == 1 ? add(on_line, beside) : sub(on_line, beside);
      const b2Vec2 point = camera.to_world(at);
      // What is drawn there: the topmost fixture's fill (moving bodies are drawn over fixed ones),
      // else the sky.
      std::optional<ImU32> fill;
      for (const b2Body* body = scene.world().GetBodyList(); body != nullptr; body = body->GetNext()) {
        for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
          bool inside = false;
          if (lessons::is_ground(fixture)) {
            // A ground's slab is drawn as its box, its top the surface (draw_ground); a strip's edge draws none.
            if (fixture->GetType() == b2Shape::e_edge) continue;
            const b2AABB& box = fixture->GetAABB(0);
            const float skin = fixture->GetShape()->m_radius;
            inside = point.x >= box.lowerBound.x && point.x <= box.upperBound.x && point.y >= box.lowerBound.y + skin &&
                     point.y <= box.upperBound.y - skin;
          } else {
            inside = fixture->TestPoint(point);
          }
          if (inside && (!fill || body->GetType() == b2_dynamicBody)) fill = fixture_colour(scene, fixture, theme);
        }
      }
      arrow.over_its_like = like(fill.value_or(theme.sky));
    }
  }
}

// A body on feet has a normal force at each foot: each drawn, their sum labelled once, at the
// longest (each foot's own value is a probe away). One label per foot crowds the picture.
// A friction between two moving bodies names the body it acts on: of stacked_blocks' two
// 2.20 N frictions between the blocks, equal and opposite, nothing said which pushed which
// block, and the bottom block's backward friction, its value beside the top block, read as the
// top block's, the answer the lesson asks the class for turned round (a teacher's trial, issue
// 31). A friction from a body that does not move has no partner drawn, and its value stays a
// number. (The pair's normal forces keep theirs short: each points into its own block, and
// "9.81 N on bottom" found no place wholly on or off the bottom block on a projector.)
std::vector<std::string> force_value_texts(const std::vector<ScreenArrow>& arrows, const Scene& scene) {
  std::vector<std::string> texts(arrows.size());
  for (std::size_t i = 0; i < arrows.size(); ++i) {
    const ForceOnBody& force = arrows[i].force;
    texts[i] = format_quantity(force.force.Length(), "N");
    const bool paired = force.kind == ForceKind::friction && force.other != nullptr && force.other->GetType() == b2_dynamicBody;
    if (paired) texts[i] += " on " + scene.name_of(force.body);
    if (force.kind != ForceKind::normal) continue;
    int count = 0;
    b2Vec2 sum{0.0f, 0.0f};
    std::size_t longest = i;
    for (std::size_t j = 0; j < arrows.size(); ++j) {
      // The same two bodies: a body's feet on one floor, not a block's floor and the block on it.
      if (arrows[j].force.kind != ForceKind::normal || arrows[j].force.body != force.body ||
          arrows[j].force.other != force.other) {
        continue;
      }
      ++count;
      sum += arrows[j].force.force;
      if (arrows[j].length() > arrows[longest].length()) longest = j;
    }
    if (count > 1) texts[i] = i == longest ? format_quantity(sum.Length(), "N") + " in all" : "";
  }
  return texts;
}

// A picture's force values as placed, and the placer they leave.
struct PlacedValues {
  std::vector<PlacedForce> values;
  LabelPlacer labels;
  int away;  // how many found no place beside their own arrows
};

// The values placed in an order on a copy of the placer; where some found no place beside
// their own arrows (nor one joined by a leader), again with those first, for they have the
// fewest places (a short friction where a normal force starts), and the others after. Tried
// from the arrows' order and from the shortest arrow's first, the order that leaves the fewest
// values away from their arrows is drawn (the arrows' own order where they tie). (Issue 31: in
// a projector's thin lanes the values placed early took the only places by a short arrow.)
// Returns them, with `labels` as they leave it.
PlacedValues place_force_values(const std::vector<ScreenArrow>& arrows, const std::vector<std::string>& texts, const Fonts& fonts,
                                float thickness, const LabelPlacer& labels) {
  const auto place_all = [&](const std::vector<std::size_t>& order, LabelPlacer& placer) {
    std::vector<PlacedForce> placed(arrows.size());
    for (const std::size_t i : order) placed[i] = place_force_label(arrows[i], fonts.body, thickness, placer, texts[i], i);
    return placed;
  };
  const auto away = [](const std::vector<PlacedForce>& placed) {
    return static_cast<int>(std::count_if(placed.begin(), placed.end(), [](const PlacedForce& p) { return !p.beside; }));
  };
  std::vector<std::size_t> in_order(arrows.size());
  for (std::size_t i = 0; i < in_order.size(); ++i) in_order[i] = i;
  std::vector<std::size_t> shortest_first = in_order;
  std::stable_sort(shortest_first.begin(), shortest_first.end(),
                   [&](std::size_t a, std::size_t b) { return arrows[a].length() < arrows[b].length(); });
  // Rounds of placing again, with the values that `placed` left away from their arrows first,
  // while each leaves fewer away than the last, whose values and placer then replace `placed`'s.
  const auto place_again = [&](std::vector<std::size_t> order, std::vector<PlacedForce>& placed, LabelPlacer& placer) {
    for (int round = 0; round < 4 && away(placed) > 0; ++round) {
      std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return !placed[i].beside; });
      LabelPlacer again_placer = labels;
      std::vector<PlacedForce> again = place_all(order, again_placer);
      if (away(again) >= away(placed)) break;
      placed = std::move(again);
      placer = std::move(again_placer);
    }
  };
  using clock = std::chrono::steady_clock;
  const clock::time_point start_time = clock::now();
  LabelPlacer best_placer = labels;
  std::vector<PlacedForce> best = place_all(in_order, best_placer);
  const clock::time_point retries_time = clock::now();
  ForceLabelTimes& times = force_label_times();
  ++times.views;
  if (away(best) > 0) {
    ++times.retried;
    // The arrows' order's rounds start from its placing, `best`, rather than placing it again.
    place_again(in_order, best, best_placer);
    if (away(best) > 0) {
      LabelPlacer placer = labels;
      std::vector<PlacedForce> placed = place_all(shortest_first, placer);
      place_again(shortest_first, placed, placer);
      if (away(placed) < away(best)) {
        best = std::move(placed);
        best_placer = std::move(placer);
      }
    }
  }
  times.arrows_order += std::chrono::duration<double>(retries_time - start_time).count();
  times.retries += std::chrono::duration<double>(clock::now() - retries_time).count();
  const int best_away = away(best);  // before `best` is moved from
  return PlacedValues{std::move(best), std::move(best_placer), best_away};
}

}  // namespace

ForceLabelTimes& force_label_times() {
  thread_local ForceLabelTimes times;
  return times;
}

namespace {

// The world's things, sky first: the fixed bodies, ropes and springs (a hand at a spring's free
// end), then the moving bodies over them. The labels that name places on them are handed back,
// to be placed once every arrow and mark is known.
std::vector<PlaceLabel> draw_scenery(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera,
                                     const Theme& theme, const Fonts& fonts, LabelPlacer& labels) {
  const Scene& scene = lesson.scene();
  draw->AddRectFilled(camera.origin, add(camera.origin, camera.size), theme.sky);
  std::vector<PlaceLabel> place_labels;
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_staticBody) draw_body(draw, scene, body, camera, theme, fonts, place_labels);
  }
  draw_ropes(draw, lesson, camera, theme, fonts.scale, labels);
  for (const Spring& spring : scene.springs()) {
    const ImVec2 from = camera.to_screen(spring.body->GetWorldPoint(spring.local_point));
    const ImVec2 to = camera.to_screen(spring.other ? spring.other->GetWorldPoint(spring.other_local_point)
                                                    : scene.hand_position(spring));
    draw_spring(draw, from, to, theme, fonts.scale);
    // A spring's force label beyond its arrow's tip would lie on the coils: they are kept clear.
    labels.avoid(DrawnSegment{from, to, coil_reach(fonts.scale)});
    if (!spring.other) draw_hand(draw, to, theme, fonts, labels);
  }
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_staticBody) draw_body(draw, scene, body, camera, theme, fonts, place_labels);
  }
  return place_labels;
}

// What a view shows of the forces: the contact marks, the force arrows and the torques' arcs.
struct ForcesInView {
  std::vector<ContactMark> marks;
  std::vector<ScreenArrow> arrows;
  std::vector<TorqueArc> torques;
};

// Marks and arrows only for what is in this view: a lane's neighbours are drawn (clipped) but
// their labels would otherwise be pushed into the lane by the label placer.
ForcesInView forces_in_view(const Scene& scene, const Camera& camera, const Fonts& fonts, float newtons_to_pixels,
                            const std::vector<const b2Body*>* labelled) {
  const auto ours = [&](const b2Body* body) {
    return labelled == nullptr || std::find(labelled->begin(), labelled->end(), body) != labelled->end();
  };
  const auto in_view = [&](b2Vec2 point) {
    const ImVec2 at = camera.to_screen(point);
    return at.x >= camera.origin.x && at.x <= camera.origin.x + camera.size.x && at.y >= camera.origin.y &&
           at.y <= camera.origin.y + camera.size.y;
  };
  ForcesInView shown;
  // A contact between two moving bodies is either's (stacked_blocks' blocks, each drawn alone).
  const auto moving_and_ours = [&](const b2Body* body) { return body->GetType() == b2_dynamicBody && ours(body); };
  for (const ContactMark& mark : contact_marks(scene)) {
    if (in_view(mark.point) && (moving_and_ours(mark.body_a) || moving_and_ours(mark.body_b))) shown.marks.push_back(mark);
  }
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody || !in_view(body->GetWorldCenter()) || !ours(body)) continue;
    // None shorter than a back row can read: the legend says under which force they are not to scale.
    for (const ScreenArrow& arrow : place_arrows(forces_on(scene, body), camera, newtons_to_pixels, fonts.scale,
                                                 legible_arrow_pixels(fonts.scale))) {
      shown.arrows.push_back(arrow);
    }
  }
  for (std::size_t i = 0; i < scene.applied_forces().size(); ++i) {
    const b2Body* body = scene.applied_forces()[i].body;
    const double torque = scene.torques_applied()[i];
    if (torque == 0.0 || !in_view(body->GetWorldCenter()) || !ours(body)) continue;
    const b2AABB box = lessons::body_box(body);
    const float half = 0.5f * std::min(box.upperBound.x - box.lowerBound.x, box.upperBound.y - box.lowerBound.y);
    shown.torques.push_back(torque_arc(camera.to_screen(body->GetWorldCenter()),
                                       std::max(0.55f * half * camera.pixels_per_metre, 14.0f * fonts.scale), torque));
  }
  return shown;
}

// Whether a moving body is thinner, on the screen, than a contact's dot is wide (its shapes'
// least extent along its own axes under the dot's diameter at text scale `scale`): incline's
// block on a projector, 23 by 12 px, lay whole under its 24 px dot, the arrows that start on it
// and the plates they lie on, and the class saw no block (issue 31). Such a body is drawn again
// over its marks and arrows (draw_world), and no label lies on it.
bool thinner_than_its_dot(const b2Body* body, const Camera& camera, float scale) {
  if (body->GetType() != b2_dynamicBody) return false;
  b2Vec2 low(std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity());
  b2Vec2 high = -low;
  const auto reach = [&](b2Vec2 point, float radius) {
    low = b2Min(low, point - b2Vec2(radius, radius));
    high = b2Max(high, point + b2Vec2(radius, radius));
  };
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->GetType() == b2Shape::e_circle) {
      const auto* circle = static_cast<const b2CircleShape*>(fixture->GetShape());
      reach(circle->m_p, circle->m_radius);
    } else if (fixture->GetType() == b2Shape::e_polygon) {
      const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
      for (int k = 0; k < polygon->m_count; ++k) reach(polygon->m_vertices[k], 0.0f);
    }
  }
  if (!(high.x >= low.x)) return false;  // no shape that has a size
  const float least = std::min(high.x - low.x, high.y - low.y) * camera.pixels_per_metre;
  return least < 2.0f * contact_dot_radius * scale;
}

// Every arrow, arc, mark and moving body is known to the placer before any label is placed, so
// no label lands on one.
void tell_the_placer(LabelPlacer& labels, const ForcesInView& shown, const Scene& scene, const Camera& camera,
                     float thickness, float mark_radius, float fonts_scale) {
  for (const ScreenArrow& arrow : shown.arrows) labels.arrow(DrawnSegment{arrow.tail, arrow.tip, 2.0f * thickness});
  for (const TorqueArc& arc : shown.torques) avoid_arc(labels, arc, 2.0f * thickness);
  for (const ContactMark& mark : shown.marks) {
    const ImVec2 at = camera.to_screen(mark.point);
    labels.avoid(ImVec4(at.x - mark_radius, at.y - mark_radius, at.x + mark_radius, at.y + mark_radius));
  }
  // A ground's surface line, which a value keeps off where it can (LabelPlacer::surface).
  for (const b2Body* body = scene.world().GetBodyList(); body != nullptr; body = body->GetNext()) {
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      if (!lessons::is_ground(fixture) || fixture->GetType() == b2Shape::e_edge) continue;
      if (const std::optional<DrawnSegment> surface = ground_surface(fixture, camera)) labels.surface(*surface);
    }
  }
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    const b2AABB box = lessons::body_box(body);
    const ImVec2 a = camera.to_screen(box.lowerBound), b = camera.to_screen(box.upperBound);
    const ImVec4 on_screen(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y));
    labels.body(on_screen, body);
    // Drawn over every label too (draw_world): none may lie on it, not even its own value. Its
    // edges are kept off, not its box: a tilted block's box reaches over the slope beside it,
    // where its contact's word goes (ContactWords); a label too small to hold the body whole
    // that lies on it crosses an edge.
    if (thinner_than_its_dot(body, camera, fonts_scale)) {
      for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
        if (fixture->GetType() == b2Shape::e_circle) {
          // A wheel's box is its own size, whatever it turns.
          const auto& circle = *static_cast<const b2CircleShape*>(fixture->GetShape());
          const ImVec2 centre = camera.to_screen(body->GetWorldPoint(circle.m_p));
          const float r = circle.m_radius * camera.pixels_per_metre;
          labels.avoid(ImVec4(centre.x - r, centre.y - r, centre.x + r, centre.y + r));
        }
        if (fixture->GetType() != b2Shape::e_polygon) continue;
        const auto& shape = *static_cast<const b2PolygonShape*>(fixture->GetShape());
        for (int k = 0; k < shape.m_count; ++k) {
          labels.avoid(DrawnSegment{camera.to_screen(body->GetWorldPoint(shape.m_vertices[k])),
                                    camera.to_screen(body->GetWorldPoint(shape.m_vertices[(k + 1) % shape.m_count])),
                                    0.75f * fonts_scale});
        }
      }
    }
  }
}

// A body thinner than its dot, over its marks and arrows, which start where the class sees it
// (thinner_than_its_dot); the labels its first drawing asked for are placed already. Its
// contacts' dots first, over the arrows (the weight's shaft through the dot, the friction's
// plate by it hid all but a sliver of incline's), so the half of each dot under the surface
// still says the contact's state.
void draw_thin_bodies_over_their_forces(ImDrawList* draw, const Scene& scene, const std::vector<ContactMark>& marks,
                                        const Camera& camera, const Theme& theme, const Fonts& fonts) {
  const auto thin = [&](const b2Body* body) { return thinner_than_its_dot(body, camera, fonts.scale); };
  for (const ContactMark& mark : marks) {
    if (thin(mark.body_a) || thin(mark.body_b)) draw_contact_dot(draw, mark, camera, theme, fonts.scale);
  }
  std::vector<PlaceLabel> placed_already;
  for (const auto& [name, body] : scene.bodies()) {
    if (thin(body)) draw_body(draw, scene, body, camera, theme, fonts, placed_already);
  }
}

}  // namespace

void draw_world(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                const Fonts& fonts, float newtons_to_pixels, LabelPlacer& labels,
                const std::vector<const b2Body*>* labelled, const std::function<void()>& fixed_labels, WorldArrows drawn_arrows) {
  const Scene& scene = lesson.scene();
  const std::vector<PlaceLabel> place_labels = draw_scenery(draw, lesson, camera, theme, fonts, labels);
  ForcesInView shown = forces_in_view(scene, camera, fonts, newtons_to_pixels, labelled);
  if (drawn_arrows == WorldArrows::none) {
    shown.arrows.clear();
    shown.torques.clear();
  }
  std::vector<ScreenArrow>& arrows = shown.arrows;
  const float mark_radius = contact_dot_radius * fonts.scale;
  const float thickness = world_arrow_thickness(fonts.scale);
  place_friction_pairs_on_their_own_sides(arrows, camera, thickness, [&](std::vector<ScreenArrow>& frictions_among) {
    start_frictions_past_their_dots(frictions_among, shown.marks, camera, mark_radius);
  });
  set_apart_along_one_line(arrows, side_by_side_gap(thickness), thickness);
  uncross_arrows(arrows, thickness);
  // A contact's forces are drawn last, over every other: a weight from its centre of mass that
  // passes under a friction's start (push's, spring_pull's) is covered there, and the friction is
  // seen whole from its dot (uncross_arrows moves neither).
  std::stable_partition(arrows.begin(), arrows.end(), [](const ScreenArrow& arrow) {
    return arrow.force.kind != ForceKind::friction && arrow.force.kind != ForceKind::normal;
  });
  mark_arrows_over_their_like(arrows, scene, camera, theme, thickness);
  tell_the_placer(labels, shown, scene, camera, thickness, mark_radius, fonts.scale);
  // Before the run, where each of the lesson's forces that acts at its body's outline (a hand's
  // push at a face) will act: a ring at its point in the applied forces' colour, with its name
  // (below). No applied force has an arrow before the first step applies it, and tipping_box's
  // question (how hard, when the box tips) turns on how high it pushes, which its slider sets
  // (a teacher's trial, issue 31). One at a body's middle (push's) acts where the weight's arrow
  // starts, and a torque alone (a motor) acts at no point.
  std::vector<std::pair<const AppliedForce*, ImVec2>> force_points;
  if (scene.frame() == 0 && drawn_arrows != WorldArrows::none) {
    for (std::size_t i = 0; i < scene.applied_forces().size(); ++i) {
      const AppliedForce& applied = scene.applied_forces()[i];
      if (applied.body == nullptr || !applied.force) continue;
      if (labelled != nullptr && std::find(labelled->begin(), labelled->end(), applied.body) == labelled->end()) continue;
      const b2Vec2 point = applied.body->GetWorldPoint(applied.local_point);
      if (!on_outline(applied.body, point, 2.0f / camera.pixels_per_metre)) continue;
      const ImVec2 at = camera.to_screen(point);
      labels.avoid(ImVec4(at.x - mark_radius, at.y - mark_radius, at.x + mark_radius, at.y + mark_radius));
      force_points.emplace_back(&applied, at);
    }
  }
  // Labels that name a place (a distance mark's number) go there or nowhere: first, while every
  // place not under an arrow or a mark is free; the lesson's labels, which may move, then keep off them.
  if (fixed_labels) fixed_labels();
  // The labels of places (a slope's angle, a driven body), before the labels that go with an
  // arrow or a mark, which keep off them; none on a moving body (the trial found a slope's angle
  // under a block, a driven plank's word under the block on it).
  for (const PlaceLabel& label : place_labels) {
    const ImVec2 size = label.font->CalcTextSizeA(label.font->FontSize, 1e6f, 0.0f, label.text.c_str());
    draw_label(draw, label.font, labels.place(label.wanted, size, label.text, true), label.colour, label.background,
               label.text.c_str());
  }
  // Before the first step no contact, spring or rope has been solved, and the weight alone is
  // drawn: a block at rest on its floor looked pushed down by a force nothing balanced (a
  // teacher's trial, issue 31). The view says when the others come, as the free-body inset
  // does, above the lesson's body, in the lane that draws it; where no free place near holds the
  // words whole (a thin lane, the tools' readings), it says nothing rather than cover them.
  const b2Body* main = main_body(scene);
  if (scene.frame() == 0 && drawn_arrows != WorldArrows::none && main != nullptr &&
      (labelled == nullptr || std::find(labelled->begin(), labelled->end(), main) != labelled->end())) {
    const char* text = "the other forces appear once the run starts";
    const ImVec2 size = fonts.body->CalcTextSizeA(fonts.body->FontSize, 1e6f, 0.0f, text);
    const b2AABB box = lessons::body_box(main);
    const ImVec2 above = camera.to_screen(b2Vec2(0.5f * (box.lowerBound.x + box.upperBound.x), box.upperBound.y));
    const std::optional<ImVec2> at =
        labels.place_if_free(ImVec2(above.x, above.y - 1.5f * fonts.body->FontSize), size, text, true);
    if (at) draw_label(draw, fonts.body, *at, theme.text, theme.panel, text);
  }
  const ImU32 applied_colour = theme.force[static_cast<int>(ForceKind::applied)];
  for (const auto& [applied, at] : force_points) {
    draw->AddCircle(at, mark_radius, theme.panel, 20, 4.0f * fonts.scale);
    draw->AddCircle(at, mark_radius, applied_colour, 20, 2.0f * fonts.scale);
    // The name out from the body's middle, off the bodies, as a place's label.
    const std::string name = lessons::class_words(applied->name);
    const ImVec2 size = fonts.body->CalcTextSizeA(fonts.body->FontSize, 1e6f, 0.0f, name.c_str());
    ImVec2 out = sub(at, camera.to_screen(applied->body->GetWorldCenter()));
    const float reach = length(out);
    out = reach > 0.0f ? mul(out, 1.0f / reach) : ImVec2(-1.0f, 0.0f);
    const ImVec2 wanted = add(at, ImVec2(out.x * (mark_radius + 0.5f * size.x + 6.0f * fonts.scale),
                                         out.y * (mark_radius + 0.5f * size.y + 4.0f * fonts.scale)));
    if (const std::optional<ImVec2> placed = labels.place_if_free(wanted, size, name, true)) {
      draw_label(draw, fonts.body, *placed, applied_colour, theme.panel, name.c_str());
    }
  }
  // One word per touching pair and state: a block on six feet says "slipping" once, not six times.
  std::vector<std::tuple<const b2Body*, const b2Body*, ContactState, bool, bool>> said;
  std::vector<const ContactMark*> worded;
  for (const ContactMark& mark : shown.marks) {
    const bool rightward = mark.sliding_velocity >= 0.0;
    const auto key = std::make_tuple(mark.body_a, mark.body_b, mark.state, mark.frictionless, rightward);
    if (std::find(said.begin(), said.end(), key) != said.end()) continue;
    said.push_back(key);
    worded.push_back(&mark);
  }
  const auto place_words = [&](LabelPlacer& placer) {
    std::vector<PlacedWord> words;
    for (const ContactMark* mark : worded) words.push_back(place_contact_word(*mark, camera, fonts, placer));
    return words;
  };
  const auto place_torques = [&](LabelPlacer& placer) {
    std::vector<PlacedTorque> values;
    for (const TorqueArc& arc : shown.torques) values.push_back(place_torque_value(arc, fonts.body, thickness, placer));
    return values;
  };
  const std::vector<std::string> texts = force_value_texts(arrows, scene);
  // The contacts' words by their dots first, then the torques' and forces' values.
  LabelPlacer words_placer = labels;
  std::vector<PlacedWord> words = place_words(words_placer);
  std::vector<PlacedTorque> torques = place_torques(words_placer);
  PlacedValues values = place_force_values(arrows, texts, fonts, thickness, words_placer);
  // Where a value then finds no place beside its own arrow: the words that stood within a line
  // of their dots kept there, then the values, then the other words, if that leaves fewer values
  // away and as many words by their dots. A word away from its dot is read as its contact's by
  // its colour and arrow; a value beside another's arrow is misread. (Issue 31: stacked_blocks'
  // friction on the bottom block, 3.43 N at 4.23 s in projector mode, stood 127 px from its
  // arrow, for "← slipping", itself not within a line of its dot, had taken the only place
  // beside the arrow.)
  //
  // Where that still leaves a value away, the same with one of those words placed after the
  // values too, each in turn (stacked_blocks' pressing force, 9.81 N at 2.12 s on a projector,
  // stood 74 px off with a leader, nearer the lower block's weight: "sticking", by its dot,
  // held the one gap beside the force's tip). A value beside another's arrow is misread; a word
  // a little off its dot is still read as its contact's by its colour. The arrangement drawn
  // leaves the fewest values away, then the most words by their dots, every word still drawn;
  // one that takes a word from its dot must bring a value to its arrow.
  const auto near_dots = [](const std::vector<PlacedWord>& placed) {
    return std::count_if(placed.begin(), placed.end(), [](const PlacedWord& word) { return word.near_dot; });
  };
  const auto drawn = [](const std::vector<PlacedWord>& placed) {
    return std::count_if(placed.begin(), placed.end(), [](const PlacedWord& word) { return word.at.has_value(); });
  };
  const std::vector<PlacedWord> words_first = words;
  const auto arrange_values_first = [&](std::size_t word_after) {
    LabelPlacer values_placer = labels;
    std::vector<PlacedWord> words_again(worded.size());
    const auto kept = [&](std::size_t k) { return words_first[k].near_dot && k != word_after; };
    for (std::size_t k = 0; k < worded.size(); ++k) {
      if (kept(k)) words_again[k] = place_contact_word(*worded[k], camera, fonts, values_placer, &words_first[k]);
    }
    std::vector<PlacedTorque> torques_again = place_torques(values_placer);
    PlacedValues values_again = place_force_values(arrows, texts, fonts, thickness, values_placer);
    for (std::size_t k = 0; k < worded.size(); ++k) {
      if (!kept(k)) words_again[k] = place_contact_word(*worded[k], camera, fonts, values_again.labels);
    }
    const bool better = values_again.away < values.away ||
                        (values_again.away == values.away && near_dots(words_again) > near_dots(words));
    if (better && drawn(words_again) >= drawn(words_first)) {
      words = std::move(words_again);
      torques = std::move(torques_again);
      values = std::move(values_again);
    }
  };
  // Every word by its dot kept (word_after past the last), then each of them in turn after the values.
  if (values.away > 0) arrange_values_first(worded.size());
  for (std::size_t k = 0; k < worded.size() && values.away > 0; ++k) {
    if (words_first[k].near_dot) arrange_values_first(k);
  }
  for (const ContactMark& mark : shown.marks) draw_contact_dot(draw, mark, camera, theme, fonts.scale);
  for (const PlacedWord& word : words) draw_contact_word(draw, word, theme, fonts);
  for (std::size_t k = 0; k < shown.torques.size(); ++k) {
    draw_torque(draw, shown.torques[k], theme.force[static_cast<int>(ForceKind::applied)], fonts.body, theme.panel,
                thickness, torques[k]);
  }
  for (const PlacedForce& placed : values.values) draw_placed_force(draw, placed, theme, fonts.body, thickness);
  labels = std::move(values.labels);
  draw_thin_bodies_over_their_forces(draw, scene, shown.marks, camera, theme, fonts);
}

}  // namespace frictionlab::draw
