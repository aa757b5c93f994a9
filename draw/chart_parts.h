// What the chart engine's files share and no caller needs: an axis in its own space (log10 of
// the value on a log axis), its ticks, a legend's keys, and the steps layout_chart takes that
// live in files of their own (the y ticks fitted to the data area's height, the legend's place
// and its drawing). Only draw/chart*.cpp include it; the interface is draw/chart.h.
#pragma once

#include <imgui.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "draw/chart.h"

namespace frictionlab::draw::chart_parts {

// The multiples of `step` from `low` to `high`, at most `most` of them: a step lost in the
// rounding of large values must not loop for ever.
std::vector<double> multiples_of(double step, double low, double high, std::size_t most);

struct Axis {
  bool log = false;
  double low = 0.0, high = 1.0;  // in the axis' own space: log10 of the value on a log axis

  bool shows(double value) const { return std::isfinite(value) && (!log || value > 0.0); }
  double map(double value) const { return log ? std::log10(value) : value; }
  // 0 at low, 1 at high.
  double fraction(double value) const { return share(map(value), low, high); }
};

struct Tick {
  double value;  // in the axis' own space
  std::string label;
};

// About `count` ticks on a linear axis (1, 2 or 5 times a power of ten apart), the decades
// (or 1, 2, 5 times them) on a log axis.
std::vector<Tick> ticks_every(const Axis& axis, int count);

// The axes of a chart before its data area is known: ranges, and a map's cell edges.
struct ChartAxes {
  Axis x, y;
  std::vector<std::pair<double, double>> x_edges, y_edges;
};
ChartAxes axes_of(const Chart& chart);

// One line of a legend: a colour swatch (a square under the chart; inside it, a line, a band
// or a dashed theory line) and its text.
struct Key {
  std::string name;
  ImU32 colour;
  enum class Look { line, band, theory } look;
  float dash = 0.0f, gap = 0.0f;  // a theory curve's pattern, or a dashed series' (0: solid)
};
std::vector<Key> keys_of(const Chart& chart);

float width_of(ImFont* font, const std::string& text);

// The font of a chart's numbers, its y tick labels and its levels' texts: on a plot on a page of
// its own (Chart::steady, a projector's key plot) the body text's, which the back row reads the
// levels against (issue 31: the small text's digits were 18 px high on a 1080-line projector);
// elsewhere, and for every other text (the legend, the axes' names), the small text's. Levels'
// texts too wide for their column in it keep the small text's (ChartLayout::level_font).
ImFont* number_font(const Chart& chart, const Fonts& fonts);

// The marks between a steady chart's labelled ticks (`ticks`, 2 or more, a round step apart) on
// an axis from `low` to `high` (`pixels_per_unit` along it), as a ruler's: the finest of a
// fifth, a quarter or a half of their step that is still a round step (1 N marks between 5 N
// ticks, 5 N between 20) and leaves the marks 4 points apart or more (a ruler's millimetres, a
// projector's 8 px); none where no such step fits.
std::vector<double> minor_ticks(const std::vector<double>& ticks, double low, double high, float pixels_per_unit, float s);

// The y ticks fitted to the data area's height, once it is known: as fine as
// `chart.y_tick_spacing` allows, and never closer than a line and a third of text.
void fit_y_ticks(const Chart& chart, const Axis& y_axis, float text, float s, ChartLayout& layout);

// Where the legend goes, and the data area it leaves (layout.low_left, layout.high_right),
// once the points have a first place: `place` places them again in a changed data area,
// `set_x_ticks` chooses the x ticks again for a changed width. False when the data area left
// is too small to draw.
bool place_legend(const Chart& chart, const std::vector<Key>& keys, ImVec2 corner, ImVec2 size, const Fonts& fonts,
                  ChartLayout& layout, const std::function<void()>& place, const std::function<void(float)>& set_x_ticks);

// The legend where place_legend put it (under the chart in two columns, or inside/above the
// data), and a chart's notes.
void draw_legend(ImDrawList* draw, const Chart& chart, const std::vector<Key>& keys, const ChartLayout& layout, ImVec2 size,
                 const Theme& theme, const Fonts& fonts);

}  // namespace frictionlab::draw::chart_parts
