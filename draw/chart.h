// The one chart engine: the benchmark's charts (error against cost, stability maps) and the
// lessons' plots (draw/plots.cpp builds a Chart from the probes' record). Linear or logarithmic
// axes with ticks and units, series as lines or markers, maps, shaded spans, theory curves and
// a legend placed off the data; rendered headless to a picture for the benchmark's output.
#pragma once

#include <imgui.h>

#include <cmath>

#include <string>
#include <utility>
#include <vector>

#include "draw/image.h"
#include "draw/theme.h"

namespace frictionlab::draw {

// Where `value` lies from `low` (0) to `high` (1), without overflow for any finite values.
double share(double value, double low, double high);
// Tick positions for an axis from low to high: 1, 2 or 5 times a power of ten apart, about
// `count` of them.
std::vector<double> axis_ticks(double low, double high, int count);
// A tick's label with as many decimals as the step needs, and a true minus sign.
std::string tick_text(double value, double step);

enum class Marker { none, dot, cross };

struct ChartSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y); points not finite, or not > 0 on a log axis, are left out
  ImU32 colour = IM_COL32(0, 0, 0, 255);
  bool line = true;
  Marker marker = Marker::none;
  std::vector<std::string> labels;  // beside each point, when given (a step rate, say)
  // A line drawn in dashes of `dash` points with `gap` between them (0: solid), here and in the
  // legend: a plot with more curves than colours tells the later ones apart so.
  float dash = 0.0f, gap = 0.0f;
};

// One cell of a map: the point of a grid it stands for, and the category that colours it.
struct ChartCell {
  double x, y;
  int category;
};

// A law drawn beside the measurements: pieces of polyline in the chart's own numbers.
struct ChartCurve {
  std::string name;
  std::vector<std::vector<std::pair<double, double>>> pieces;
  // Its own colour and dash pattern (in points at text scale 1), on the plot and in the legend
  // alike: two laws on one plot (the right one and an article's as written) are told apart.
  ImU32 colour = 0;
  float dash = 6.0f, gap = 4.0f;
};

// The look of a plot's theory curve number `index`: dashes, dots and long dashes in turn, in
// the theme's theory colours in turn, so that the curves of one plot (up to six) each have
// one of their own.
void give_theory_look(ChartCurve& curve, const Theme& theme, std::size_t index);

// A level marked across the data area: a thin solid line at y (the dash patterns are the theory
// curves') with its text beside it (μs·N = 3.92 N).
struct ChartLevel {
  std::string text;
  double y = 0.0;
  ImU32 colour = 0;
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
  // legend (one column, no axes), so each plot keeps its room. `inside`: in the corner of the
  // data area that no point or curve reaches, else in a row above it (lesson plots).
  enum class Legend { under, none, only, inside } legend = Legend::under;

  // What lesson plots add; a chart that leaves them alone draws as before.
  // `plain`: no title row or background (the panel around it has them), the y label over the
  // tick labels, the zero lines darker.
  bool plain = false;
  // Linear axes with their range given, instead of the data's with a margin.
  bool fixed_x = false, fixed_y = false;
  double x_low = 0.0, x_high = 1.0, y_low = 0.0, y_high = 1.0;
  int y_tick_count = 5;
  int x_tick_count = 5;  // 0: one every 70 points of width
  // Colour of the line leading to each point of series[k] (a regime's colour), for the series
  // that have them; named in the legend by `colour_keys`.
  std::vector<std::vector<ImU32>> segment_colours;
  std::vector<std::pair<std::string, ImU32>> colour_keys;
  // Shaded spans of x (when the block slipped) and their name in the legend.
  std::vector<std::pair<double, double>> bands;
  ImU32 band_colour = 0;
  std::string band_name;
  // The present: a dot on each series' last point, and a line at x = now_x when it is finite.
  bool mark_now = false;
  double now_x = NAN;
  ImU32 now_colour = 0;
  // Theory curves, each drawn in its own look over the series, each dash edged in the panel's
  // colour so that it shows where it lies on the data or on a level, the `active` one bold
  // (`nearest`: the one passing nearest the first series' last point).
  static constexpr int nearest = -2;
  std::vector<ChartCurve> theory;
  int active_theory = -1;
  std::string message;  // drawn in the data area in the theme's `bad` colour (a script error)
  // Levels across the data (their values count for a y range that is not fixed): the lines
  // under the series, each text where no point of the series comes (`planned_points` too), else
  // under the series, the data drawn over it.
  std::vector<ChartLevel> levels;
  // Points the series will reach later in the run (a lesson plot's rehearsal of the whole run,
  // plots.cpp): the levels' texts keep off them from the opening, so that none moves or covers
  // the latest data as the run goes on. In the chart's own numbers.
  std::vector<std::pair<double, double>> planned_points;
  // A steady chart's levels' texts go in a column beside the data's right end, as a textbook
  // labels a line at its end, where no data of any run passes (spring_pull's sawtooth crossed
  // both its texts all along: struck through by the data, a teacher's trial). The column is as
  // wide as the widest of these (the texts the theory will show, before the reveal too, so
  // that the reveal moves nothing); empty, or wider than a third of the chart: the texts go by
  // their lines in the data area, as place_level_texts says.
  std::vector<std::string> level_room;
  // The data area the same whatever the data and whatever the legend holds (a plot on a page of
  // its own, read from the back of a room): the inside legend goes in a column beside the data,
  // as wide as the longest of its keys and of `legend_room` (names that may join it, such as
  // theory curves not shown yet), and the y tick labels have the room of the widest of them,
  // which holds still as the axes do (a lesson plot's are fixed, the same at the reveal). Plain
  // charts only.
  bool steady = false;
  std::vector<std::string> legend_room;
  // The y ticks at least this many points of text scale 1 apart (0: as y_tick_count says):
  // as many as the data area's height holds.
  float y_tick_spacing = 0.0f;
};

// Where a chart's parts go on the screen, worked out before anything is drawn (and by tests).
struct ChartLayout {
  ImVec2 low_left, high_right;  // the data area
  // The chart's right end less its 8-point margin: where a plain chart's data ends, and the
  // levels' column beside a steady chart's data.
  float right_end = 0.0f;
  bool log_x = false, log_y = false;
  double x_low = 0.0, x_high = 1.0, y_low = 0.0, y_high = 1.0;  // axis space: log10 of the value on a log axis
  std::vector<double> x_ticks, y_ticks;  // axis space
  // A steady chart's unlabelled marks between its ticks (axis space), as a ruler's: the key
  // values read off to a tenth of the axis or finer where the labels, kept apart, tick coarser
  // (a teacher's trial: on a projector tipping_box's push axis was labelled every 20 N of 60,
  // spring_pull's forces every 2 N of 10).
  std::vector<double> x_minor_ticks, y_minor_ticks;
  std::vector<std::string> x_tick_labels, y_tick_labels;
  // The font the levels' texts are written in: the numbers' (chart_parts.h's number_font), but
  // the small text's on a steady chart whose column beside the data would take more than a
  // third of its width in it (incline's "θc = 30.96°: −μs·N" on a projector), where they fit.
  ImFont* level_font = nullptr;
  std::vector<ImVec2> points;  // every series' points as drawn (at most about two a pixel)
  std::vector<std::vector<ImVec2>> series_points;        // the same, series by series
  std::vector<std::vector<std::size_t>> series_indices;  // which of the series' points each is
  std::vector<std::vector<std::vector<ImVec2>>> theory;  // [curve][piece][point]
  int active = -1;
  ImVec2 legend_min, legend_max;
  std::vector<ImVec2> legend_at;  // an inside legend's keys, one by one
  bool legend_outside = false;  // an inside legend that found no free corner: in a row above
  // An inside legend with no room off the data (neither a free corner, beside nor above): in
  // the corner it covers least of.
  bool legend_on_data = false;
  bool drawable = false;        // room enough for a data area
  ImVec2 y_label_at{NAN, NAN};  // a steady chart's y label, over its legend beside the data
  ImVec2 x_label_at{NAN, NAN};  // a steady chart's x label, beyond the data's right end
  float legend_wrap = 0.0f;     // a steady chart's keys wrap at this width (0: they do not)
  // Each level's text, where it was written (x0, y0, x1, y1), and its line's y on the screen.
  struct Level {
    std::size_t index;  // in the chart's levels
    std::string text;  // empty: its line alone, with no room for its text
    ImVec4 at;
    float y;
    // No place by its line is clear of the data, the run's to come and the theory's curves
    // (spring_pull's sawtooth crosses both its levels all along): the text is drawn under the
    // series, which stay in sight over it.
    bool beneath = false;
    // In the column beside the data (Chart::level_room), in one line or two (in_two_lines): a
    // short line leads from its line's end to the text's middle, which may be moved up or down
    // off its line to keep clear of another level's text (incline's −μs·N and holding levels,
    // 0.8 N apart at its defaults).
    bool beside = false;
    // Beside the data, its label over its value (level_text_in_column); else on one line, where
    // the column is wide enough for it: incline's three levels' texts, two lines each, stood up
    // to 3 N above their lines on a projector, stacked over each other (a teacher's trial, issue 31).
    bool in_two_lines = false;
  };
  std::vector<Level> levels;
  // The lines draw_chart drew to read the data by, with their colours, for the contrast test:
  // the data area's edges and the zero lines (axis), the tick marks outside the edges (tick:
  // a steady chart's, which read 3:1 or more on the panel) and the grid across the data (grid:
  // kept faint, so that it does not compete with the curves and levels; the ticks are the
  // reading aid). Empty from layout_chart.
  struct Line {
    enum class Kind { axis, tick, grid } kind;
    ImVec2 from, to;
    ImU32 colour;
  };
  std::vector<Line> lines;
  // The texts draw_chart wrote round the data (the tick labels, the axes' names), each with its
  // box (x0, y0, x1, y1): placed by layout_chart, before the levels' texts, which keep clear of them.
  struct AxisText {
    enum class Kind { x_tick, y_tick, x_name, y_name } kind;
    std::string text;
    ImVec4 at;
  };
  std::vector<AxisText> axis_texts;

  ImVec2 to_screen(double x, double y) const;  // the chart's own numbers to screen points
};

ChartLayout layout_chart(const Chart& chart, ImVec2 corner, ImVec2 size, const Fonts& fonts);
// A level's text as written in the column beside the data where it is too wide for one line:
// its label over its value ("−μs·N" over "= −3.92 N"), so that the column stays narrow.
std::string level_text_in_column(const std::string& text);
// A placed level's text as written (in two lines or one).
std::string level_text_as_written(const ChartLayout::Level& placed, const std::string& text);
// Draws the chart and returns where its parts went.
ChartLayout draw_chart(ImDrawList* draw, ImVec2 corner, ImVec2 size, const Chart& chart, const Theme& theme,
                       const Fonts& fonts);

// Parts the lesson plots (draw/plots.cpp) draw with too.

// Where a legend of `legend_size` goes inside the data area [area_min, area_max], `inset` from
// its edge: the corner whose rectangle meets the fewest `points` (each a square `radius`
// each side of it), the first of equals in the order top left, top right, bottom left,
// bottom right. `clear` when that corner meets none; otherwise the caller puts it outside.
struct LegendPlace {
  ImVec2 min, max;
  bool clear = false;
};
LegendPlace legend_corner(ImVec2 area_min, ImVec2 area_max, ImVec2 legend_size, float inset,
                          const std::vector<ImVec2>& points, float radius);

// Whether a chart of this size has room for its legend off its data however the data fill the
// data area (beside or above it), or needs more room: for choosing how many plots go side by
// side, once, without the choice changing as the data come in.
bool legend_has_room(const Chart& chart, ImVec2 size, const Fonts& fonts);

// A curve made of pieces (a nil in a theory function splits it), in screen points.
using CurvePieces = std::vector<std::vector<ImVec2>>;
// The curve passing nearest `point`; -1 when no curve has a point.
int nearest_curve(const std::vector<CurvePieces>& curves, ImVec2 point);
// A polyline drawn in dashes of `dash` pixels with `gap` between them.
void draw_dashed(ImDrawList* draw, const std::vector<ImVec2>& points, ImU32 colour, float thickness, float dash, float gap);

}  // namespace frictionlab::draw
