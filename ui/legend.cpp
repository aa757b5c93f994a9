#include "ui/legend.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "ui/drawing.h"

namespace frictionlab::ui {
namespace {

std::string metres(float value) {
  char text[32];
  if (value >= 1.0f) {
    std::snprintf(text, sizeof text, "%g m", static_cast<double>(value));
  } else {
    std::snprintf(text, sizeof text, "%g cm", static_cast<double>(value * 100.0f));
  }
  return text;
}

// In the legend's strip, right, on the arrows' row (the materials' row below runs longer): a
// bar of a round length in metres, its end at `bottom_right`.
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

}  // namespace

void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels) {
  ImFont* font = fonts.small;
  const float s = fonts.scale, line = font->FontSize + 6.0f * s;
  draw->AddRectFilled(corner, add(corner, size), theme.panel);
  draw->AddLine(corner, ImVec2(corner.x + size.x, corner.y), theme.grid);
  const ImVec2 bottom_left(corner.x, corner.y + size.y - 2.0f * s);
  ImVec2 at(bottom_left.x + 10.0f * s, bottom_left.y - 2.0f * line);
  draw_scale_bar(draw, camera.pixels_per_metre,
                 ImVec2(corner.x + size.x, at.y + 0.5f * font->FontSize + 12.0f * s + 2.0f * s), theme, fonts);
  // The kinds of force in the picture, with the arrow scale so a teacher can read a length as
  // newtons. Friction, normal force and weight are always named: they are the lesson.
  bool present[force_kind_count] = {};
  present[static_cast<int>(ForceKind::friction)] = present[static_cast<int>(ForceKind::normal)] =
      present[static_cast<int>(ForceKind::weight)] = true;
  for (const auto& [name, body] : scene.bodies()) {
    for (const ForceOnBody& force : forces_on(scene, body)) present[static_cast<int>(force.kind)] = true;
  }
  for (int kind = 0; kind < force_kind_count; ++kind) {
    if (!present[kind]) continue;
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
      const ImU32 colour = fixture_colour(scene, fixture, theme);
      chip(colour, material, false);
    }
  }
}

}  // namespace frictionlab::ui
