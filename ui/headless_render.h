// Lesson frames to pictures with no display: an EGL context, an ImGui context with the
// projector fonts, and the frame function shared with the window.
#pragma once

#include <memory>

#include "lessons/runtime/lesson.h"
#include "ui/camera.h"
#include "ui/headless.h"
#include "ui/image.h"
#include "ui/theme.h"

struct ImGuiContext;

namespace frictionlab::ui {

class HeadlessRenderer {
 public:
  // Throws HeadlessUnavailable when EGL cannot start, std::runtime_error when the font is missing.
  HeadlessRenderer(int width, int height, ThemeName theme = ThemeName::light);
  ~HeadlessRenderer();
  HeadlessRenderer(const HeadlessRenderer&) = delete;
  HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

  // The lesson as it is now, drawn whole. The same lesson at the same moment gives the same
  // picture whatever was drawn before it.
  Image render(lessons::Lesson& lesson, const WorldFraming& framing);

  int width() const { return width_; }
  int height() const { return height_; }
  float scale() const { return fonts_.scale; }
  const HeadlessContext& context() const { return *gl_; }

 private:
  int width_, height_;
  ThemeName theme_;
  std::unique_ptr<HeadlessContext> gl_;
  ImGuiContext* imgui_ = nullptr;
  Fonts fonts_;
};

}  // namespace frictionlab::ui
