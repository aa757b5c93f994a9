// The lesson's plots, drawn from the probes' record with ImGui's draw lists: axes with tick
// labels and units, a legend, the current time marked on time series, and the slip regime
// shaded (time series) or coloured (X–Y against one quantity) from the scene's record of
// which frames had a slipping contact.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"
#include "ui/theme.h"

namespace frictionlab::ui {

// Tick positions for an axis from low to high: 1, 2 or 5 times a power of ten apart, about
// `count` of them.
std::vector<double> axis_ticks(double low, double high, int count);
// A tick's label with as many decimals as the step needs, and a true minus sign.
std::string tick_text(double value, double step);

// Where everything of a lesson plot goes, in screen points: worked out before drawing, so that
// tests can check it without reading pixels.
struct PlotLayout {
  ImVec2 low_left, high_right;  // the data area
  double x_low = 0.0, x_high = 1.0, y_low = 0.0, y_high = 1.0;
  std::vector<ImVec2> points;  // the measured points drawn (every few, at most two a pixel)
  std::vector<std::vector<std::vector<ImVec2>>> theory;  // [curve][piece][point]
  int active = -1;  // the theory curve drawn bold: the branch that applies now
  std::string theory_error;  // a curve function's script error, shown in the plot
  ImVec2 legend_min, legend_max;
  bool legend_outside = false;  // above the data: no corner inside was free of points

  ImVec2 to_screen(double x, double y) const {
    return ImVec2(low_left.x + static_cast<float>((x - x_low) / (x_high - x_low)) * (high_right.x - low_left.x),
                  low_left.y - static_cast<float>((y - y_low) / (y_high - y_low)) * (low_left.y - high_right.y));
  }
};

// Lays out plot number `plot` of the lesson in the rectangle. `time_span` is the time axis'
// length (the lesson's duration, or longer once the lesson has run past it). Samples the
// plot's theory curves (kept between frames while the range and parameters stay).
PlotLayout layout_plot(lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner, ImVec2 size,
                       const Fonts& fonts);

// Draws plot number `plot` of the lesson into the rectangle.
void draw_plot(ImDrawList* draw, lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner, ImVec2 size,
               const Theme& theme, const Fonts& fonts);

}  // namespace frictionlab::ui
