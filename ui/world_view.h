// The world as a teacher sees it: ground, bodies in their materials' colours, springs that
// stretch, ropes over pulleys, hands and driven bodies, slopes with their angle marked, a scale
// bar, the force arrows with their values, every contact's state and the legend.
#pragma once

#include <imgui.h>

#include <vector>

#include "lessons/runtime/lesson.h"
#include "ui/camera.h"
#include "ui/overlays.h"
#include "ui/theme.h"

namespace frictionlab::ui {

// Keeps text labels from landing on each other within one picture.
class LabelPlacer {
 public:
  // Where a label of this size goes: at `wanted` (its centre) or the nearest free place
  // above or below it.
  ImVec2 place(ImVec2 wanted, ImVec2 size);

 private:
  std::vector<ImVec4> taken_;  // x0, y0, x1, y1
};

// A label with a background that keeps it readable over bodies and lines; `centre` is where
// the middle of the text goes.
void draw_label(ImDrawList* draw, ImFont* font, ImVec2 centre, ImU32 colour, ImU32 background, const char* text);
void draw_arrow(ImDrawList* draw, ImVec2 tail, ImVec2 tip, ImU32 colour, float thickness);

// The world, the arrows on every dynamic body and the contact marks into `camera`'s view.
void draw_world(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                const Fonts& fonts, float newtons_to_pixels, LabelPlacer& labels);
// The legend in its strip: force colours with the arrow scale, contact states, materials and
// the scale bar.
void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels);
// The free-body diagram of `body` in the rectangle: the body alone, every force on it at its
// point of action with its value, and the net force.
void draw_free_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const std::string& name, ImVec2 corner,
                    ImVec2 size, const Theme& theme, const Fonts& fonts);

}  // namespace frictionlab::ui
