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

// Parts the lesson plots (ui/plots.cpp) draw with too.

// Where a legend of `legend_size` goes inside the data area [area_min, area_max], `inset` from
// its edge: the corner whose rectangle meets the fewest `points` (each a square `radius` each
// side of it). `clear` when that corner meets none; otherwise the caller puts it outside.
struct LegendPlace {
  ImVec2 min, max;
  bool clear = false;
};
LegendPlace legend_corner(ImVec2 area_min, ImVec2 area_max, ImVec2 legend_size, float inset,
                          const std::vector<ImVec2>& points, float radius);

// A curve made of pieces (a nil in a theory function splits it), in screen points.
using CurvePieces = std::vector<std::vector<ImVec2>>;
// The curve passing nearest `point`; -1 when no curve has a point.
int nearest_curve(const std::vector<CurvePieces>& curves, ImVec2 point);
// A polyline drawn in dashes of `dash` pixels with `gap` between them.
void draw_dashed(ImDrawList* draw, const std::vector<ImVec2>& points, ImU32 colour, float thickness, float dash, float gap);

// The charts in a grid of `columns`, on one picture, drawn headless (EGL). Throws
// HeadlessUnavailable where EGL cannot start.
Image render_charts(const std::vector<Chart>& charts, int columns, int width, int height);

}  // namespace frictionlab::ui
