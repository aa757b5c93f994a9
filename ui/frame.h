// One frame of a lesson: the same function draws a window's frame and a headless PNG. It
// only draws: stepping the lesson is the caller's business.
#pragma once

#include <imgui.h>

#include "lessons/runtime/lesson.h"
#include "ui/camera.h"
#include "ui/theme.h"

namespace frictionlab::ui {

// Where each part of the frame goes, for a display of a given size: the world at the top
// left with the plots below it, the panels in a column on the right.
struct FrameLayout {
  ImVec2 title_corner, title_size;
  ImVec2 world_corner, world_size;
  ImVec2 legend_corner, legend_size;
  ImVec2 inset_corner, inset_size;  // the free-body diagram, over the world's top right
  ImVec2 plots_corner, plots_size;
  ImVec2 column_corner, column_size;
  static FrameLayout of(ImVec2 display, float scale);
};

struct FrameStyle {
  ThemeName theme = ThemeName::light;
  const Fonts* fonts = nullptr;
};

// Builds the frame's ImGui windows and draw lists; call between ImGui::NewFrame() and
// ImGui::Render(). `framing` is the one chosen when the lesson was (re)built.
void build_frame(lessons::Lesson& lesson, const WorldFraming& framing, const FrameStyle& style, ImVec2 display);

// The world view's camera and arrow scale for this frame, as build_frame draws them: tests
// use these to find the arrows in the picture.
Camera world_camera(const lessons::Lesson& lesson, const WorldFraming& framing, ImVec2 display, float scale);
float arrow_scale(const lessons::Lesson& lesson, ImVec2 display, float scale);

}  // namespace frictionlab::ui
