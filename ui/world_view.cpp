#include "ui/world_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace frictionlab::ui {
namespace {

constexpr float pi = 3.14159265358979f;

ImVec2 add(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
ImVec2 sub(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
ImVec2 mul(ImVec2 a, float s) { return ImVec2(a.x * s, a.y * s); }
float length(ImVec2 a) { return std::hypot(a.x, a.y); }

bool is_ground(const b2Fixture* fixture) {
  const b2AABB& box = fixture->GetAABB(0);
  return fixture->GetBody()->GetType() == b2_staticBody && box.upperBound.x - box.lowerBound.x > 100.0f;
}

// 1, 2 or 5 times a power of ten: the nicest length near `wanted`.
float nice_length(float wanted) {
  const float power = std::pow(10.0f, std::floor(std::log10(wanted)));
  const float fraction = wanted / power;
  return (fraction < 1.5f ? 1.0f : fraction < 3.5f ? 2.0f : fraction < 7.5f ? 5.0f : 10.0f) * power;
}

std::string metres(float value) {
  char text[32];
  if (value >= 1.0f) {
    std::snprintf(text, sizeof text, "%g m", static_cast<double>(value));
  } else {
    std::snprintf(text, sizeof text, "%g cm", static_cast<double>(value * 100.0f));
  }
  return text;
}

const std::string& material_name(const Scene& scene, const b2Fixture* fixture) {
  static const std::string none = "?";
  const int id = fixture_material(const_cast<b2Fixture*>(fixture));
  return id >= 0 && id < scene.pairs().material_count() ? scene.pairs().material(id).name : none;
}

void draw_ground(ImDrawList* draw, const b2Fixture* fixture, const Camera& camera, const Theme& theme) {
  const b2AABB& box = fixture->GetAABB(0);
  const float top = box.upperBound.y - b2_polygonRadius;
  const ImVec2 view_end = add(camera.origin, camera.size);
  const float left = camera.origin.x, right = view_end.x;
  const float top_y = camera.to_screen({0.0f, top}).y;
  const float bottom_y = camera.to_screen({0.0f, box.lowerBound.y + b2_polygonRadius}).y;
  draw->AddRectFilled(ImVec2(left, top_y), ImVec2(right, std::min(bottom_y, view_end.y)), theme.ground);
  // Hatching fixed to the ground, so the ground is seen to stay put while the view follows.
  const float spacing = nice_length(22.0f / camera.pixels_per_metre);
  const b2Vec2 world_left = camera.to_world(ImVec2(left, top_y));
  const float first = std::floor(world_left.x / spacing) * spacing;
  const float depth = 12.0f;
  for (float x = first; camera.to_screen({x, top}).x < right + depth; x += spacing) {
    const float sx = camera.to_screen({x, top}).x;
    draw->AddLine(ImVec2(sx, top_y + 1.0f), ImVec2(sx - depth, top_y + depth), theme.ground_edge, 1.5f);
  }
  draw->AddLine(ImVec2(left, top_y), ImVec2(right, top_y), theme.ground_edge, 2.5f);
}

void draw_polygon(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera,
                  ImU32 fill, ImU32 outline, float thickness) {
  ImVec2 points[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) points[i] = camera.to_screen(body->GetWorldPoint(shape.m_vertices[i]));
  draw->AddConvexPolyFilled(points, shape.m_count, fill);
  draw->AddPolyline(points, shape.m_count, outline, ImDrawFlags_Closed, thickness);
}

// Slopes: at a corner between a level edge and a sloping one, the angle between them.
void mark_slope_angles(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera,
                       const Theme& theme, const Fonts& fonts) {
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
      const ImVec2 centre = camera.to_screen(corner);
      const float radius = 46.0f * fonts.scale;
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
      draw_label(draw, fonts.body, at, theme.text, 0, text);
    }
  }
}

void draw_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const Camera& camera, const Theme& theme,
               const Fonts& fonts) {
  const bool driven = body->GetType() == b2_kinematicBody;
  const ImU32 outline = driven ? theme.driven_outline : theme.outline;
  const float thickness = (driven ? 3.0f : 1.5f) * fonts.scale;
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (is_ground(fixture)) {
      draw_ground(draw, fixture, camera, theme);
      continue;
    }
    const std::string& material = material_name(scene, fixture);
    const ImU32 fill = material_colour(theme, material, scene.pairs().find_material(material));
    if (fixture->GetType() == b2Shape::e_polygon) {
      const auto& shape = *static_cast<const b2PolygonShape*>(fixture->GetShape());
      draw_polygon(draw, body, shape, camera, fill, outline, thickness);
      if (body->GetType() == b2_staticBody) mark_slope_angles(draw, body, shape, camera, theme, fonts);
    } else if (fixture->GetType() == b2Shape::e_circle) {
      const auto& shape = *static_cast<const b2CircleShape*>(fixture->GetShape());
      const ImVec2 centre = camera.to_screen(body->GetWorldPoint(shape.m_p));
      const float radius = shape.m_radius * camera.pixels_per_metre;
      draw->AddCircleFilled(centre, radius, fill, 48);
      draw->AddCircle(centre, radius, outline, 48, thickness);
      // A spoke, so rolling can be told from sliding.
      const ImVec2 rim = camera.to_screen(body->GetWorldPoint(shape.m_p + b2Vec2{shape.m_radius, 0.0f}));
      draw->AddLine(centre, rim, outline, thickness);
    }
  }
  if (driven) {
    const ImVec2 at = camera.to_screen(body->GetWorldCenter());
    draw_label(draw, fonts.small, at, theme.driven_outline, 0, "driven");
  }
}

// A coil spring: its turns spread out as it stretches and crowd as it is squeezed.
void draw_spring(ImDrawList* draw, ImVec2 from, ImVec2 to, const Theme& theme, float scale) {
  const ImVec2 along = sub(to, from);
  const float span = length(along);
  if (span < 1.0f) return;
  const ImVec2 unit = mul(along, 1.0f / span);
  const ImVec2 across(-unit.y, unit.x);
  constexpr int turns = 12;
  const float lead = 0.12f * span, amplitude = 7.0f * scale;
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

void draw_hand(ImDrawList* draw, ImVec2 at, const Theme& theme, const Fonts& fonts) {
  draw->AddCircleFilled(at, 7.0f * fonts.scale, theme.hand, 24);
  draw_label(draw, fonts.small, ImVec2(at.x, at.y - 18.0f * fonts.scale), theme.hand, 0, "hand");
}

void draw_ropes(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                float scale) {
  for (const lessons::Rope& rope : lesson.ropes()) {
    const auto* pulley = static_cast<const b2PulleyJoint*>(rope.joint);
    const ImVec2 a = camera.to_screen(pulley->GetAnchorA()), b = camera.to_screen(pulley->GetAnchorB());
    const ImVec2 ga = camera.to_screen(pulley->GetGroundAnchorA()), gb = camera.to_screen(pulley->GetGroundAnchorB());
    draw->AddLine(a, ga, theme.rope, 2.5f * scale);
    draw->AddLine(ga, gb, theme.rope, 2.5f * scale);
    draw->AddLine(gb, b, theme.rope, 2.5f * scale);
    const ImVec2 middle = mul(add(ga, gb), 0.5f);
    const float radius = std::max(0.5f * length(sub(gb, ga)), 8.0f * scale);
    draw->AddCircle(middle, radius, theme.outline, 32, 2.0f * scale);
    draw->AddCircleFilled(middle, 3.0f * scale, theme.outline, 12);
  }
}

// In the legend's strip, bottom right: a bar of a round length in metres.
void draw_scale_bar(ImDrawList* draw, float pixels_per_metre, ImVec2 bottom_right, const Theme& theme, const Fonts& fonts) {
  const float bar = nice_length(110.0f * fonts.scale / pixels_per_metre);
  const float pixels = bar * pixels_per_metre;
  const ImVec2 end(bottom_right.x - 16.0f * fonts.scale, bottom_right.y - 12.0f * fonts.scale);
  const ImVec2 start(end.x - pixels, end.y);
  const float tick = 6.0f * fonts.scale;
  draw->AddLine(start, end, theme.text, 2.0f * fonts.scale);
  draw->AddLine(ImVec2(start.x, end.y - tick), ImVec2(start.x, end.y + 1), theme.text, 2.0f * fonts.scale);
  draw->AddLine(ImVec2(end.x, end.y - tick), ImVec2(end.x, end.y + 1), theme.text, 2.0f * fonts.scale);
  draw_label(draw, fonts.small, ImVec2(0.5f * (start.x + end.x), end.y - 14.0f * fonts.scale), theme.text, 0,
             metres(bar).c_str());
}

void draw_contact_mark(ImDrawList* draw, const ContactMark& mark, const Camera& camera, const Theme& theme,
                       const Fonts& fonts, LabelPlacer& labels) {
  const ImVec2 at = camera.to_screen(mark.point);
  const bool slipping = mark.state == ContactState::slipping;
  const ImU32 colour = slipping ? theme.slipping : theme.sticking;
  const float r = 6.0f * fonts.scale;
  draw->AddCircleFilled(at, r, colour, 20);
  draw->AddCircle(at, r, theme.background, 20, 1.5f);
  // A slipping contact's label says which way the upper body slides.
  std::string text = slipping ? "slipping" : "sticking";
  if (slipping) {
    const b2Vec2 way = static_cast<float>(mark.sliding_velocity >= 0.0 ? 1.0 : -1.0) * mark.tangent;
    text = way.x >= 0.0f ? "slipping \u2192" : "\u2190 slipping";
  }
  const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, text.c_str());
  // Into the surface, where nothing else is drawn, and to the side the friction arrow does not
  // point to.
  const b2Vec2 into = -b2Cross(1.0f, mark.tangent);  // the tangent turned toward A, the surface
  const float side = mark.friction_force > 0.0 ? -1.0f : 1.0f;
  const b2Vec2 along = side * mark.tangent;
  const float reach = 0.5f * size.x + 10.0f * fonts.scale, depth = 0.5f * size.y + 8.0f * fonts.scale;
  const ImVec2 wanted(at.x + along.x * reach + into.x * depth, at.y - along.y * reach - into.y * depth);
  draw_label(draw, fonts.small, labels.place(wanted, size), colour, theme.panel, text.c_str());
}

}  // namespace

ImVec2 LabelPlacer::place(ImVec2 wanted, ImVec2 size) {
  const float pad = 2.0f;
  const auto free_at = [&](ImVec2 c) {
    const ImVec4 box(c.x - 0.5f * size.x - pad, c.y - 0.5f * size.y - pad, c.x + 0.5f * size.x + pad,
                     c.y + 0.5f * size.y + pad);
    for (const ImVec4& t : taken_) {
      if (box.x < t.z && t.x < box.z && box.y < t.w && t.y < box.w) return false;
    }
    return true;
  };
  ImVec2 chosen = wanted;
  for (int step = 0; step < 12; ++step) {
    const float shift = static_cast<float>((step + 1) / 2) * (size.y + 2.0f * pad) * (step % 2 == 1 ? 1.0f : -1.0f);
    const ImVec2 candidate(wanted.x, wanted.y + (step == 0 ? 0.0f : shift));
    if (free_at(candidate)) {
      chosen = candidate;
      break;
    }
  }
  taken_.emplace_back(chosen.x - 0.5f * size.x - pad, chosen.y - 0.5f * size.y - pad, chosen.x + 0.5f * size.x + pad,
                      chosen.y + 0.5f * size.y + pad);
  return chosen;
}

void draw_label(ImDrawList* draw, ImFont* font, ImVec2 centre, ImU32 colour, ImU32 background, const char* text) {
  const ImVec2 size = font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text);
  const ImVec2 corner(std::round(centre.x - 0.5f * size.x), std::round(centre.y - 0.5f * size.y));
  if (background != 0) {
    const ImU32 faded = (background & 0x00FFFFFFu) | (215u << IM_COL32_A_SHIFT);
    draw->AddRectFilled(ImVec2(corner.x - 3, corner.y - 1), ImVec2(corner.x + size.x + 3, corner.y + size.y + 1), faded,
                        3.0f);
  }
  draw->AddText(font, font->FontSize, corner, colour, text);
}

void draw_arrow(ImDrawList* draw, ImVec2 tail, ImVec2 tip, ImU32 colour, float thickness) {
  const ImVec2 along = sub(tip, tail);
  const float span = length(along);
  if (span < 1e-3f) return;
  const ImVec2 unit = mul(along, 1.0f / span);
  const ImVec2 across(-unit.y, unit.x);
  const float head = std::min(4.0f * thickness, 0.6f * span);
  const ImVec2 base = sub(tip, mul(unit, head));
  // The shaft runs on under the head, so no seam of anti-aliased edges shows between them.
  draw->AddLine(tail, add(base, mul(unit, 0.3f * head)), colour, thickness);
  draw->AddTriangleFilled(tip, add(base, mul(across, 0.45f * head)), sub(base, mul(across, 0.45f * head)), colour);
}

void draw_world(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                const Fonts& fonts, float newtons_to_pixels, LabelPlacer& labels) {
  const Scene& scene = lesson.scene();
  draw->AddRectFilled(camera.origin, add(camera.origin, camera.size), theme.sky);
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_staticBody) draw_body(draw, scene, body, camera, theme, fonts);
  }
  draw_ropes(draw, lesson, camera, theme, fonts.scale);
  for (const Spring& spring : scene.springs()) {
    const ImVec2 from = camera.to_screen(spring.body->GetWorldPoint(spring.local_point));
    const ImVec2 to = camera.to_screen(spring.other ? spring.other->GetWorldPoint(spring.other_local_point)
                                                    : scene.hand_position(spring));
    draw_spring(draw, from, to, theme, fonts.scale);
    if (!spring.other) draw_hand(draw, to, theme, fonts);
  }
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_staticBody) draw_body(draw, scene, body, camera, theme, fonts);
  }
  for (const ContactMark& mark : contact_marks(scene)) draw_contact_mark(draw, mark, camera, theme, fonts, labels);
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    for (const ScreenArrow& arrow : place_arrows(forces_on(scene, body), camera, newtons_to_pixels)) {
      const ImU32 colour = theme.force[static_cast<int>(arrow.force.kind)];
      draw_arrow(draw, arrow.tail, arrow.tip, colour, 3.5f * fonts.scale);
      const std::string text = format_quantity(arrow.force.force.Length(), "N");
      const ImVec2 size = fonts.body->CalcTextSizeA(fonts.body->FontSize, 1e6f, 0.0f, text.c_str());
      const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length());
      // Just beyond the tip, far enough along the arrow's line that the text clears the head.
      const float reach = 0.5f * (std::abs(unit.x) * size.x + std::abs(unit.y) * size.y) + 6.0f * fonts.scale;
      const ImVec2 wanted = add(arrow.tip, mul(unit, reach));
      draw_label(draw, fonts.body, labels.place(wanted, size), colour, theme.panel, text.c_str());
    }
  }
}

void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels) {
  ImFont* font = fonts.small;
  const float s = fonts.scale, line = font->FontSize + 6.0f * s;
  draw->AddRectFilled(corner, add(corner, size), theme.panel);
  draw->AddLine(corner, ImVec2(corner.x + size.x, corner.y), theme.grid);
  draw_scale_bar(draw, camera.pixels_per_metre, add(corner, size), theme, fonts);
  const ImVec2 bottom_left(corner.x, corner.y + size.y - 2.0f * s);
  ImVec2 at(bottom_left.x + 10.0f * s, bottom_left.y - 2.0f * line);
  // Forces, with the arrow scale so a teacher can read a length as newtons.
  for (int kind = 0; kind < force_kind_count; ++kind) {
    const ImU32 colour = theme.force[kind];
    draw_arrow(draw, ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + 26.0f * s, at.y + 0.5f * font->FontSize),
               colour, 3.0f * s);
    const std::string name(force_kind_name(static_cast<ForceKind>(kind)));
    draw->AddText(font, font->FontSize, ImVec2(at.x + 32.0f * s, at.y), theme.text, name.c_str());
    at.x += 40.0f * s + font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, name.c_str()).x + 10.0f * s;
  }
  const float newtons = nice_length(40.0f * s / newtons_to_pixels);
  char scale_text[48];
  std::snprintf(scale_text, sizeof scale_text, "= %g N", static_cast<double>(newtons));
  draw->AddLine(ImVec2(at.x, at.y + 0.5f * font->FontSize), ImVec2(at.x + newtons * newtons_to_pixels, at.y + 0.5f * font->FontSize),
                theme.text, 3.0f * s);
  draw->AddText(font, font->FontSize, ImVec2(at.x + newtons * newtons_to_pixels + 6.0f * s, at.y), theme.text, scale_text);

  // Contact states and the materials in the picture.
  at = ImVec2(bottom_left.x + 10.0f * s, bottom_left.y - line);
  const auto chip = [&](ImU32 colour, const std::string& text, bool round) {
    const ImVec2 centre(at.x + 7.0f * s, at.y + 0.5f * font->FontSize);
    if (round) {
      draw->AddCircleFilled(centre, 6.0f * s, colour, 16);
    } else {
      draw->AddRectFilled(ImVec2(centre.x - 7 * s, centre.y - 6 * s), ImVec2(centre.x + 7 * s, centre.y + 6 * s), colour);
      draw->AddRect(ImVec2(centre.x - 7 * s, centre.y - 6 * s), ImVec2(centre.x + 7 * s, centre.y + 6 * s), theme.outline);
    }
    draw->AddText(font, font->FontSize, ImVec2(at.x + 20.0f * s, at.y), theme.text, text.c_str());
    at.x += 32.0f * s + font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()).x;
  };
  chip(theme.sticking, "sticking contact", true);
  chip(theme.slipping, "slipping contact", true);
  std::vector<std::string> shown;
  for (const auto& [name, body] : scene.bodies()) {
    for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
      const std::string& material = material_name(scene, fixture);
      if (std::find(shown.begin(), shown.end(), material) != shown.end()) continue;
      shown.push_back(material);
      const ImU32 colour = is_ground(fixture) ? theme.ground : material_colour(theme, material, scene.pairs().find_material(material));
      chip(colour, material, false);
    }
  }
}

void draw_free_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const std::string& name, ImVec2 corner,
                    ImVec2 size, const Theme& theme, const Fonts& fonts) {
  const float s = fonts.scale;
  draw->AddRectFilled(corner, add(corner, size), theme.panel, 4.0f);
  draw->AddRect(corner, add(corner, size), theme.axis, 4.0f, 0, 1.0f);
  const std::string title = "Free-body diagram: " + name;
  draw->AddText(fonts.small, fonts.small->FontSize, ImVec2(corner.x + 8 * s, corner.y + 5 * s), theme.text, title.c_str());
  if (body == nullptr) return;

  // The body alone, at its own zoom, upright as it is now.
  b2AABB box;
  box.lowerBound = box.upperBound = body->GetWorldCenter();
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) box.Combine(f->GetAABB(0));
  const float header = fonts.small->FontSize + 10.0f * s, footer = fonts.small->FontSize + 8.0f * s;
  Camera inset;
  inset.origin = ImVec2(corner.x, corner.y + header);
  inset.size = ImVec2(size.x, size.y - header - footer);
  inset.centre = box.GetCenter();
  const b2Vec2 extent = box.upperBound - box.lowerBound;
  inset.anchor = ImVec2(inset.origin.x + 0.5f * inset.size.x, inset.origin.y + 0.5f * inset.size.y);
  inset.pixels_per_metre = std::min(0.42f * inset.size.x / std::max(extent.x, 1e-3f), 0.36f * inset.size.y / std::max(extent.y, 1e-3f));
  const std::vector<ForceOnBody> forces = forces_on(scene, body);
  float largest = 1e-6f;
  for (const ForceOnBody& force : forces) largest = std::max(largest, force.force.Length());
  const float newtons_to_pixels = 0.36f * std::min(inset.size.x, inset.size.y) / largest;

  draw->PushClipRect(corner, add(corner, size), true);
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
    const std::string& material = material_name(scene, f);
    const ImU32 fill = material_colour(theme, material, scene.pairs().find_material(material));
    if (f->GetType() == b2Shape::e_polygon) {
      draw_polygon(draw, body, *static_cast<const b2PolygonShape*>(f->GetShape()), inset, fill, theme.outline, 1.5f * s);
    } else if (f->GetType() == b2Shape::e_circle) {
      const auto& circle = *static_cast<const b2CircleShape*>(f->GetShape());
      draw->AddCircleFilled(inset.to_screen(body->GetWorldPoint(circle.m_p)), circle.m_radius * inset.pixels_per_metre, fill, 32);
    }
  }
  draw->AddCircleFilled(inset.to_screen(body->GetWorldCenter()), 3.0f * s, theme.outline, 12);
  LabelPlacer labels;
  b2Vec2 net{0.0f, 0.0f};
  for (const ScreenArrow& arrow : place_arrows(forces, inset, newtons_to_pixels)) {
    const ImU32 colour = theme.force[static_cast<int>(arrow.force.kind)];
    draw_arrow(draw, arrow.tail, arrow.tip, colour, 3.0f * s);
    const std::string text = format_quantity(arrow.force.force.Length(), "N");
    const ImVec2 text_size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, text.c_str());
    const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length());
    const float reach = 0.5f * (std::abs(unit.x) * text_size.x + std::abs(unit.y) * text_size.y) + 4.0f * s;
    draw_label(draw, fonts.small, labels.place(add(arrow.tip, mul(unit, reach)), text_size), colour, theme.panel,
               text.c_str());
  }
  for (const ForceOnBody& force : forces) net += force.force;
  draw->PopClipRect();
  const std::string net_text = "net force: " + format_quantity(net.Length(), "N");
  draw->AddText(fonts.small, fonts.small->FontSize, ImVec2(corner.x + 8 * s, corner.y + size.y - footer + 2 * s),
                theme.faint_text, net_text.c_str());
}

}  // namespace frictionlab::ui
