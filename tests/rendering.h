// Helpers for tests that draw lessons: a built-in lesson stepped to a moment, and its picture;
// the window's fonts for measuring text.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>

#include "draw/camera.h"
#include "draw/headless.h"
#include "draw/headless_render.h"
#include "draw/imgui_host.h"
#include "draw/theme.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

constexpr int frame_width = 1280, frame_height = 720;

// A built-in lesson with some parameters set, framed at t = 0 and stepped to `t` (whole
// steps, as frictionlab render does).
struct LessonAt {
  std::unique_ptr<lessons::Lesson> lesson;
  lessons::WorldFraming framing;

  LessonAt(const std::string& name, std::map<std::string, std::string> set, double t)
      : lesson(std::make_unique<lessons::Lesson>(lessons::resolve_lesson(name), std::move(set))),
        framing(lessons::WorldFraming::of(*lesson)) {
    step_to(t);
  }
  void step_to(double t) { lesson->step_to(t); }
  const Scene& scene() const { return lesson->scene(); }
};

// Fonts for measuring text, as a frame has them at 1280 × 720; one for the test program, made
// current for the caller.
struct FontsForLayout {
  HeadlessContext gl;
  ImGuiHost host{nullptr};
  const Fonts& fonts = host.prepare(1.0f, ThemeName::light);
};

inline FontsForLayout& measuring() {
  static FontsForLayout fonts;
  fonts.host.make_current();
  return fonts;
}

}  // namespace frictionlab::draw
