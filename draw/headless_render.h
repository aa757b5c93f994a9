// Lesson frames to pictures with no display: an EGL context, an ImGui context with the
// projector fonts, and the frame function shared with the window.
#pragma once

#include <imgui.h>

#include <memory>

#include "draw/camera.h"
#include "draw/chart.h"
#include "draw/frame.h"
#include "draw/headless.h"
#include "draw/image.h"
#include "draw/imgui_host.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

// Where the last render's time went, in wall-clock seconds (llvmpipe draws on several
// threads). For the benchmark only: nothing drawn depends on it.
struct FrameTimes {
  double ui = 0.0;        // building the frame's windows and draw lists (both passes)
  double raster = 0.0;    // OpenGL drawing, to glFinish
  double readback = 0.0;  // glReadPixels and the row flip
  double total() const { return ui + raster + readback; }
};

class HeadlessRenderer {
 public:
  // Throws HeadlessUnavailable when EGL cannot start, std::runtime_error when the font is missing.
  // `scale`: the text scale, as the window's projector mode makes it; 0: the size's own.
  HeadlessRenderer(int width, int height, ThemeName theme = ThemeName::light, float scale = 0.0f);
  ~HeadlessRenderer();
  HeadlessRenderer(const HeadlessRenderer&) = delete;
  HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

  // The lesson as it is now, drawn whole. The same lesson at the same moment gives the same
  // picture whatever was drawn before it.
  // With `record`, also where the frame put things in the world view.
  Image render(lessons::Lesson& lesson, const lessons::WorldFraming& framing, FrameRecord* record = nullptr);

  // Values the pictures must not show (a mystery pair's), from now on.
  void hide(HiddenValues hidden) { hidden_ = std::move(hidden); }

  const FrameTimes& last_times() const { return times_; }
  int width() const { return width_; }
  int height() const { return height_; }
  float scale() const { return host_->fonts().scale; }
  const HeadlessContext& context() const { return *gl_; }

 private:
  int width_, height_;
  ThemeName theme_;
  std::unique_ptr<HeadlessContext> gl_;
  std::unique_ptr<ImGuiHost> host_;  // after gl_: its renderer goes while the context lives
  FrameTimes times_;
  HiddenValues hidden_;
};

// The charts in a grid of `columns`, on one picture, drawn headless (EGL). Throws
// HeadlessUnavailable where EGL cannot start.
Image render_charts(const std::vector<Chart>& charts, int columns, int width, int height);

}  // namespace frictionlab::draw
