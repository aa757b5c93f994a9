// The Stability map tab: where the regularized law settles or chatters for a block with this
// lesson's mu_s (on its slope, when it has one), at Box2D's integrator, with the lesson's own
// step and threshold speeds marked, so a class sees which side of the boundary it is on. The
// tab says it in words and opens the map in a window of its own (the tab is too small for it).
//
// It keeps its own state and draws itself, as each of Dear ImGui's demo windows does: the
// classroom holds one, calls draw_tab() inside the books' tab bar and draw_window() after the
// frame's panels.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "classroom/control_places.h"
#include "draw/chart.h"
#include "draw/panels.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"
#include "physics/stability.h"

namespace frictionlab::classroom {

struct StabilityMapTab {
  // The map for a mu_s and the g·cos θ of the slope, made once for each.
  std::vector<StabilityCell> cells;
  std::pair<double, double> made_for{-1.0, -1.0};
  draw::Chart chart;                     // as last drawn: the map and the lesson's marks
  std::vector<std::string> words;  // each threshold's side of the boundary, in words
  bool mu_s_hidden = false;        // no map: the lesson's μs is a mystery's, and its boundary would give it away
  bool window_open = false;

  // The chart and words for the lesson as it stands; none for a hidden μs.
  void update(const lessons::Lesson& lesson, const draw::HiddenValues& hidden);
  // The tab, in the tab bar being drawn.
  void draw_tab(const lessons::Lesson& lesson, const draw::HiddenValues& hidden, ControlPlaces& controls);
  // The map's own window, while it is open.
  void draw_window(const lessons::Lesson& lesson, const draw::HiddenValues& hidden, const draw::Theme& colours, const draw::Fonts& fonts);
};

}  // namespace frictionlab::classroom
