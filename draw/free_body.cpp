#include "draw/free_body.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "draw/drawing.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {

double printed_net(const std::vector<b2Vec2>& forces) {
  double x = 0.0, y = 0.0, step = 1.0;
  bool any = false;
  for (const b2Vec2& force : forces) {
    const double length = force.Length();
    if (length == 0.0) continue;
    const PrintedNumber printed = printed_number(length);
    x += printed.value * force.x / length;
    y += printed.value * force.y / length;
    step = any ? std::min(step, printed.step) : printed.step;
    any = true;
  }
  if (!any) return 0.0;
  return std::round(std::hypot(x, y) / step) * step;
}

namespace {
// The diagram's area inside an inset of `size`: below its title, above its net force line.
ImVec2 diagram_size(ImVec2 size, float text, float scale) {
  const float header = text + 10.0f * scale, footer = text + 8.0f * scale;
  return ImVec2(size.x, size.y - header - footer);
}
}  // namespace

float free_body_reach(ImVec2 size, float text, float scale) {
  const ImVec2 area = diagram_size(size, text, scale);
  // The longest arrow, with its label beyond its tip, stays inside the diagram's area.
  const float label_room = text + 8.0f * scale;
  return std::max(0.32f * std::min(area.x, area.y), std::min(0.36f * std::min(area.x, area.y), 0.5f * area.y - label_room));
}

bool free_body_readable(ImVec2 size, float scale) {
  const float text = small_text_points * scale;
  return free_body_reach(size, text, scale) >= 3.0f * text;
}

namespace {

// A text of the inset noted for the layout test, in the inset's font.
void note_inset_text(const std::string& text, ImVec2 at, const ImRect& whole, const Fonts& fonts) {
  ImGui::PushFont(fonts.small);
  note_text_in(text.c_str(), at, whole);
  ImGui::PopFont();
}

// The body alone, at its own zoom, upright as it is now: the inset's camera, and the body's
// extent in metres.
Camera inset_camera(const b2Body* body, ImVec2 corner, ImVec2 size, const Fonts& fonts, b2Vec2& extent) {
  const float s = fonts.scale;
  b2AABB box;
  box.lowerBound = box.upperBound = body->GetWorldCenter();
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) box.Combine(f->GetAABB(0));
  const float header = fonts.small->FontSize + 10.0f * s;
  Camera inset;
  inset.origin = ImVec2(corner.x, corner.y + header);
  inset.size = diagram_size(size, fonts.small->FontSize, s);
  inset.centre = box.GetCenter();
  extent = box.upperBound - box.lowerBound;
  inset.anchor = ImVec2(inset.origin.x + 0.5f * inset.size.x, inset.origin.y + 0.5f * inset.size.y);
  // The body as large as leaves its arrows room: at a quarter of the height a tall crate on a
  // projector's inset was 15 px across, under its own arrows.
  inset.pixels_per_metre = std::min(0.4f * inset.size.x / std::max(extent.x, 1e-3f), 0.4f * inset.size.y / std::max(extent.y, 1e-3f));
  return inset;
}

// The body's shapes in their materials' colours, and a dot at its centre of mass.
void draw_inset_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const Camera& inset, const Theme& theme,
                     float s) {
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
    const ImU32 fill = fixture_colour(scene, f, theme);
    if (f->GetType() == b2Shape::e_polygon) {
      draw_polygon(draw, body, *static_cast<const b2PolygonShape*>(f->GetShape()), inset, fill, theme.outline, 1.5f * s);
    } else if (f->GetType() == b2Shape::e_circle) {
      const auto& circle = *static_cast<const b2CircleShape*>(f->GetShape());
      draw->AddCircleFilled(inset.to_screen(body->GetWorldPoint(circle.m_p)), surface_radius(circle) * inset.pixels_per_metre, fill, 32);
    }
  }
  draw->AddCircleFilled(inset.to_screen(body->GetWorldCenter()), 3.0f * s, theme.outline, 12);
}

// Before the first step the solver has not yet said what the contacts push with: the weight
// alone, on a block resting on a floor, showed the class unbalanced forces. No arrows until the
// run starts, and words that say so, on as many lines as the inset's width needs.
void say_forces_come_with_the_run(ImDrawList* draw, ImVec2 footer_at, ImVec2 size, const ImRect& whole,
                                  const Theme& theme, const Fonts& fonts) {
  std::vector<std::string> lines = {"forces appear once the run starts"};
  if (fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, lines.front().c_str()).x > size.x - 16.0f * fonts.scale) {
    lines = {"forces appear once", "the run starts"};
  }
  const float line_height = fonts.small->FontSize;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const ImVec2 at(footer_at.x, footer_at.y - static_cast<float>(lines.size() - 1 - i) * line_height);
    draw->AddText(fonts.small, fonts.small->FontSize, at, theme.faint_text, lines[i].c_str());
    note_inset_text(lines[i], at, whole, fonts);
  }
}

// The forces' arrows with their values, and a motor's torque round the centre of mass; the
// forces drawn, as printed (place_arrows leaves out only a force too small to show in them).
std::vector<b2Vec2> draw_inset_forces(ImDrawList* draw, const Scene& scene, const b2Body* body, const Camera& inset,
                                      b2Vec2 extent, float newtons_to_pixels, const Theme& theme, const Fonts& fonts,
                                      LabelPlacer& labels) {
  const float s = fonts.scale;
  // Weight and normal force side by side 9 px times the scale apart, as before the world's gap
  // grew (side_by_side_gap): the inset is drawn only where it is read from near (not on a
  // projector: free_body_readable), its arrows thinner, and its values are placed in that room
  // (a wider gap left tipping_box's 1.48 N friction 46 px from its arrow at 2.49 s).
  const std::vector<ScreenArrow> arrows = place_arrows(forces_on(scene, body), inset, newtons_to_pixels, s, 0.0f, 9.0f * s, false);
  for (const ScreenArrow& arrow : arrows) labels.arrow(DrawnSegment{arrow.tail, arrow.tip, 6.0f * s});
  std::vector<TorqueArc> torques;
  for (std::size_t i = 0; i < scene.applied_forces().size(); ++i) {
    if (scene.applied_forces()[i].body != body || scene.torques_applied()[i] == 0.0) continue;
    const float half = 0.5f * std::min(extent.x, extent.y) * inset.pixels_per_metre;
    torques.push_back(torque_arc(inset.to_screen(body->GetWorldCenter()), std::max(1.3f * half, 12.0f * s),
                                 scene.torques_applied()[i]));
    avoid_arc(labels, torques.back(), 6.0f * s);
  }
  for (const ScreenArrow& arrow : arrows) draw_force(draw, arrow, theme, fonts.small, 3.0f * s, labels);
  for (const TorqueArc& arc : torques) {
    draw_torque(draw, arc, theme.force[static_cast<int>(ForceKind::applied)], fonts.small, theme.panel, 2.0f * s,
                place_torque_value(arc, fonts.small, 2.0f * s, labels));
  }
  std::vector<b2Vec2> drawn;
  for (const ScreenArrow& arrow : arrows) drawn.push_back(arrow.force.force);
  return drawn;
}

}  // namespace

void draw_free_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const std::string& name, ImVec2 corner,
                    ImVec2 size, const Theme& theme, const Fonts& fonts, FreeBodyRecord* record) {
  const float s = fonts.scale;
  draw->AddRectFilled(corner, add(corner, size), theme.panel, 4.0f);
  draw->AddRect(corner, add(corner, size), theme.axis, 4.0f, 0, 1.0f);
  // Shortened when the inset is narrow (large text): the name must show.
  const std::string body_name = lessons::class_words(name);
  std::string title = "Free-body diagram: " + body_name;
  if (fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, title.c_str()).x > size.x - 16.0f * s) {
    title = body_name + ", forces";
  }
  const ImRect whole(corner, add(corner, size));
  draw->AddText(fonts.small, fonts.small->FontSize, ImVec2(corner.x + 8 * s, corner.y + 5 * s), theme.text, title.c_str());
  note_inset_text(title, ImVec2(corner.x + 8 * s, corner.y + 5 * s), whole, fonts);
  if (body == nullptr) return;

  b2Vec2 extent;
  const Camera inset = inset_camera(body, corner, size, fonts, extent);
  float largest = 1e-6f;
  for (const ForceOnBody& force : forces_on(scene, body)) largest = std::max(largest, force.force.Length());
  const float newtons_to_pixels = free_body_reach(size, fonts.small->FontSize, s) / largest;

  draw->PushClipRect(corner, add(corner, size), true);
  draw_inset_body(draw, scene, body, inset, theme, s);
  const float footer = fonts.small->FontSize + 8.0f * s;
  const ImVec2 footer_at(corner.x + 8 * s, corner.y + size.y - footer + 2 * s);
  if (scene.frame() == 0) {
    draw->PopClipRect();
    say_forces_come_with_the_run(draw, footer_at, size, whole, theme, fonts);
    return;
  }
  // Labels between the title and the net force line, off every arrow.
  LabelPlacer labels(inset.origin, inset.size);
  const std::vector<b2Vec2> drawn = draw_inset_forces(draw, scene, body, inset, extent, newtons_to_pixels, theme, fonts, labels);
  draw->PopClipRect();
  const std::string net_text = "net force: " + format_quantity(printed_net(drawn), "N");
  if (record != nullptr) {
    record->drawn = true;
    record->forces = labels.force_labels();
    record->directions = drawn;
    record->labels = labels.labels();
    record->bounds = labels.bounds();
    record->net_text = net_text;
  }
  draw->AddText(fonts.small, fonts.small->FontSize, footer_at, theme.faint_text, net_text.c_str());
  note_inset_text(net_text, footer_at, whole, fonts);
}

}  // namespace frictionlab::draw
