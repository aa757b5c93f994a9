// Charts of measurements rather than of a lesson: error against cost, stability maps. Drawn
// with the same draw lists, fonts and colours as the lesson plots, on linear or logarithmic
// axes, and rendered headless to a picture for the benchmark's output.
#pragma once

#include <imgui.h>

#include <string>
#include <utility>
#include <vector>

#include "ui/image.h"
#include "ui/theme.h"

namespace frictionlab::ui {

enum class Marker { none, dot, cross };

struct ChartSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y); points not finite, or not > 0 on a log axis, are left out
  ImU32 colour = IM_COL32(0, 0, 0, 255);
  bool line = true;
  Marker marker = Marker::none;
  std::vector<std::string> labels;  // beside each point, when given (a step rate, say)
};

// One cell of a map: the point of a grid it stands for, and the category that colours it.
struct ChartCell {
  double x, y;
  int category;
};

struct Chart {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  // A map under the series: each cell fills the space half-way to its neighbours.
  std::vector<ChartCell> cells;
  std::vector<std::pair<std::string, ImU32>> categories;  // name and colour, by category number
  std::vector<ChartSeries> series;
  std::vector<std::string> notes;  // lines of text under the legend
  // Charts that share their series' colours can leave the legend to one chart that is only a
  // legend (one column, no axes), so each plot keeps its room.
  enum class Legend { under, none, only } legend = Legend::under;
};

void draw_chart(ImDrawList* draw, ImVec2 corner, ImVec2 size, const Chart& chart, const Theme& theme, const Fonts& fonts);

// The charts in a grid of `columns`, on one picture, drawn headless (EGL). Throws
// HeadlessUnavailable where EGL cannot start.
Image render_charts(const std::vector<Chart>& charts, int columns, int width, int height);

}  // namespace frictionlab::ui
