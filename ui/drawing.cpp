#include "ui/drawing.h"

#include <algorithm>

namespace frictionlab::ui {

float nice_length(float wanted) {
  const float power = std::pow(10.0f, std::floor(std::log10(wanted)));
  const float fraction = wanted / power;
  return (fraction < 1.5f ? 1.0f : fraction < 3.5f ? 2.0f : fraction < 7.5f ? 5.0f : 10.0f) * power;
}

const std::string& material_name(const Scene& scene, const b2Fixture* fixture) {
  static const std::string none = "?";
  const int id = fixture_material(const_cast<b2Fixture*>(fixture));
  return id >= 0 && id < scene.pairs().material_count() ? scene.pairs().material(id).name : none;
}

ImU32 fixture_colour(const Scene& scene, const b2Fixture* fixture, const Theme& theme) {
  const std::string& material = material_name(scene, fixture);
  return material_colour(theme, material, scene.pairs().find_material(material));
}

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
  // Inside the view, so a label near its edge is moved in rather than cut.
  const float half_x = 0.5f * size.x + pad, half_y = 0.5f * size.y + pad;
  const float top = low_.y + half_y, bottom = std::max(top, high_.y - half_y);
  wanted.x = std::clamp(wanted.x, low_.x + half_x, std::max(low_.x + half_x, high_.x - half_x));
  wanted.y = std::clamp(wanted.y, top, bottom);
  ImVec2 chosen = wanted;
  for (int step = 0; step < 12; ++step) {
    const float shift = static_cast<float>((step + 1) / 2) * (size.y + 2.0f * pad) * (step % 2 == 1 ? 1.0f : -1.0f);
    const ImVec2 candidate(wanted.x, std::clamp(wanted.y + (step == 0 ? 0.0f : shift), top, bottom));
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

void draw_force(ImDrawList* draw, const ScreenArrow& arrow, const Theme& theme, ImFont* font, float thickness,
                LabelPlacer& labels) {
  const ImU32 colour = theme.force[static_cast<int>(arrow.force.kind)];
  draw_arrow(draw, arrow.tail, arrow.tip, colour, thickness);
  const std::string text = format_quantity(arrow.force.force.Length(), "N");
  const ImVec2 size = font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str());
  const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length());
  // Just beyond the tip, far enough along the arrow's line that the text clears the head.
  const float reach = 0.5f * (std::abs(unit.x) * size.x + std::abs(unit.y) * size.y) + 1.5f * thickness;
  draw_label(draw, font, labels.place(add(arrow.tip, mul(unit, reach)), size), colour, theme.panel, text.c_str());
}

void draw_polygon(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera,
                  ImU32 fill, ImU32 outline, float thickness) {
  ImVec2 points[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) points[i] = camera.to_screen(body->GetWorldPoint(shape.m_vertices[i]));
  draw->AddConvexPolyFilled(points, shape.m_count, fill);
  draw->AddPolyline(points, shape.m_count, outline, ImDrawFlags_Closed, thickness);
}


}  // namespace frictionlab::ui
