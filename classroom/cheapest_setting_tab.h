// The Cheapest setting tab: runs the lesson at every friction treatment, step rate and sub-step
// count, each a fresh run of its script with the sliders as they are, judged by the lesson's
// own theory table, and names the cheapest setting that answers within a tolerance. One setting
// is measured a frame (measure_next), so the window stays live while it searches.
//
// It keeps its own state and draws itself, as each of Dear ImGui's demo windows does: the
// classroom holds one and calls draw() inside the books' tab bar.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "classroom/control_places.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"
#include "bench/cheapest_setting.h"

namespace frictionlab::classroom {

struct CheapestSettingTab {
  std::unique_ptr<Recommender> search;  // for the lesson it was started on
  double tolerance = 1.0;               // as typed: times the lesson's own tolerances
  std::string lesson_path;              // the lesson the search was started on
  std::string error;                    // why the last Measure could not start

  bool started() const { return search != nullptr; }
  bool measuring() const { return search != nullptr && !search->done(); }
  // One setting of the search (between frames).
  void measure_next() {
    if (measuring()) search->run_next();
  }
  // The tab, in the tab bar being drawn; `scale` is the fonts' scale. Returns the setting to
  // use when "Use it" was pressed.
  std::optional<StepSettings> draw(const lessons::Lesson& lesson, float scale, const draw::Theme& colours,
                                   ControlPlaces& controls);
};

}  // namespace frictionlab::classroom
