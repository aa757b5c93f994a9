// An ImGui context for a window or a test: its fonts and style follow the size of the display
// and the theme, rebuilt only when those change. The OpenGL renderer runs on whatever GL
// context is current when the host is made (a GLFW window, or an EGL context in tests).
#pragma once

#include <imgui.h>

#include "draw/theme.h"

namespace frictionlab::draw {

class ImGuiHost {
 public:
  // `ini_path`: where ImGui keeps its windows' places between runs; null keeps nothing.
  // Throws std::runtime_error when OpenGL cannot be loaded or the font is missing.
  explicit ImGuiHost(const char* ini_path);
  ~ImGuiHost();
  ImGuiHost(const ImGuiHost&) = delete;
  ImGuiHost& operator=(const ImGuiHost&) = delete;

  void make_current() const { ImGui::SetCurrentContext(context_); }
  // Fonts at `scale` and ImGui's style for `theme`; call outside a frame. The font atlas is
  // built again only when the scale moved by more than 2 % (a resize, projector mode).
  const Fonts& prepare(float scale, ThemeName theme);
  const Fonts& fonts() const { return fonts_; }

  // One frame: ImGui::NewFrame() before, ImGui::Render() and drawing into the current
  // framebuffer after. The caller clears it first and handles input and presenting.
  void begin_frame();
  void end_frame();

 private:
  ImGuiContext* context_ = nullptr;
  ImVector<ImWchar> glyph_ranges_;  // the atlas points into them while it lives
  Fonts fonts_;
  float built_scale_ = 0.0f;
  ThemeName styled_theme_ = ThemeName::light;
  float styled_scale_ = 0.0f;
};

}  // namespace frictionlab::draw
