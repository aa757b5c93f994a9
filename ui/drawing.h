// Drawing pieces the world view, the legend and the free-body inset share: labels that keep
// out of each other's way, arrows, force arrows with their values, polygons, and a few facts
// about fixtures (is it ground, what is it made of).
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

#include "physics/scene.h"
#include "ui/camera.h"
#include "ui/overlays.h"
#include "ui/theme.h"

namespace frictionlab::ui {

inline ImVec2 add(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
inline ImVec2 sub(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
inline ImVec2 mul(ImVec2 a, float s) { return ImVec2(a.x * s, a.y * s); }
inline float length(ImVec2 a) { return std::hypot(a.x, a.y); }

// 1, 2 or 5 times a power of ten: the nicest length near `wanted`.
float nice_length(float wanted);
const std::string& material_name(const Scene& scene, const b2Fixture* fixture);
ImU32 fixture_colour(const Scene& scene, const b2Fixture* fixture, const Theme& theme);

// Keeps text labels from landing on each other, and inside the view, within one picture.
class LabelPlacer {
 public:
  LabelPlacer(ImVec2 corner, ImVec2 size) : low_(corner), high_(add(corner, size)) {}
  // Where a label of this size goes: at `wanted` (its centre) or the nearest free place
  // above or below it.
  ImVec2 place(ImVec2 wanted, ImVec2 size);

 private:
  ImVec2 low_, high_;          // the view labels must stay in
  std::vector<ImVec4> taken_;  // x0, y0, x1, y1
};

// A label with a background that keeps it readable over bodies and lines; `centre` is where
// the middle of the text goes. No background when `background` is 0.
void draw_label(ImDrawList* draw, ImFont* font, ImVec2 centre, ImU32 colour, ImU32 background, const char* text);
void draw_arrow(ImDrawList* draw, ImVec2 tail, ImVec2 tip, ImU32 colour, float thickness);
// A force's arrow in its kind's colour, with its value in newtons just beyond the tip.
void draw_force(ImDrawList* draw, const ScreenArrow& arrow, const Theme& theme, ImFont* font, float thickness,
                LabelPlacer& labels);
void draw_polygon(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera, ImU32 fill,
                  ImU32 outline, float thickness);

}  // namespace frictionlab::ui
