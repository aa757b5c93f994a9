// Drawing a chart where layout_chart (chart_layout.cpp) put its parts: the map, the grid and the
// zero lines, the shaded spans, the levels' lines, the series, the theory curves in their dash
// patterns, the levels' texts, the present, the axes with their tick labels and names, then the
// legend (chart_legend.cpp).
#include <algorithm>
#include <cmath>

#include "draw/chart.h"
#include "draw/chart_parts.h"

namespace frictionlab::draw {

using namespace chart_parts;

namespace {

using Kind = ChartLayout::Line::Kind;

// What each part of a chart's drawing needs: where it draws, the chart, the layout it draws by
// (and notes its lines and texts in, for the tests), and the look.
struct Painter {
  ImDrawList* draw;
  const Chart& chart;
  ChartLayout& layout;
  const Theme& theme;
  const Fonts& fonts;
  float s = fonts.scale;
  ImFont* font = fonts.small;
  float text = font->FontSize;
  // The ticks' labels and the levels' texts (number_font).
  ImFont* numbers = number_font(chart, fonts);
  float number_text = numbers->FontSize;

  // Values already in axis space (log10 of the value on a log axis) to the screen.
  ImVec2 at_axis_value(double x, double y) const {
    return ImVec2(layout.low_left.x + static_cast<float>(share(x, layout.x_low, layout.x_high)) * (layout.high_right.x - layout.low_left.x),
                  layout.low_left.y - static_cast<float>(share(y, layout.y_low, layout.y_high)) * (layout.low_left.y - layout.high_right.y));
  }
  void line(Kind kind, ImVec2 from, ImVec2 to, ImU32 colour, float thickness) {
    draw->AddLine(from, to, colour, thickness);
    layout.lines.push_back({kind, from, to, colour});
  }
};

// A chart that is only a legend: its keys in one column, then its notes.
void draw_legend_only(ImDrawList* draw, ImVec2 corner, const Chart& chart, const Theme& theme, const Fonts& fonts) {
  const float s = fonts.scale;
  ImFont* font = fonts.small;
  const float text = font->FontSize;
  const float line = text + 3.0f * s;
  float y = corner.y + fonts.body->FontSize + text + 16.0f * s;
  for (const Key& key : keys_of(chart)) {
    draw->AddRectFilled(ImVec2(corner.x + 12.0f * s, y + 2.0f * s), ImVec2(corner.x + 24.0f * s, y + text - 2.0f * s), key.colour);
    draw->AddText(font, text, ImVec2(corner.x + 30.0f * s, y), theme.text, key.name.c_str());
    y += line;
  }
  for (const std::string& note : chart.notes) {
    draw->AddText(font, text, ImVec2(corner.x + 12.0f * s, y + 6.0f * s), theme.faint_text, note.c_str());
    y += line;
  }
}

// A map's cells, each filling the space half-way to its neighbours.
void draw_map(const Painter& p, const ChartAxes& axes) {
  for (const ChartCell& cell : p.chart.cells) {
    if (!axes.x.shows(cell.x) || !axes.y.shows(cell.y) || cell.category < 0 ||
        cell.category >= static_cast<int>(p.chart.categories.size())) {
      continue;
    }
    const double x = axes.x.map(cell.x), y = axes.y.map(cell.y);
    const auto edge = [](const std::vector<std::pair<double, double>>& edges, double value) {
      for (const auto& e : edges) {
        if (value >= e.first && value <= e.second) return e;
      }
      return std::make_pair(value, value);
    };
    const auto [x0, x1] = edge(axes.x_edges, x);
    const auto [y0, y1] = edge(axes.y_edges, y);
    p.draw->AddRectFilled(p.at_axis_value(x0, y1), p.at_axis_value(x1, y0),
                          p.chart.categories[static_cast<std::size_t>(cell.category)].second);
  }
}

// The grid at the ticks. The zero lines of a plain chart are darker: forces are read against zero.
void draw_grid(Painter& p) {
  const ChartLayout& layout = p.layout;
  for (const double tick : layout.x_ticks) {
    const float x = p.at_axis_value(tick, layout.y_low).x;
    const bool zero = p.chart.plain && tick == 0.0;
    p.line(zero ? Kind::axis : Kind::grid, ImVec2(x, layout.high_right.y), ImVec2(x, layout.low_left.y),
           zero ? p.theme.axis : p.theme.grid, 1.0f);
  }
  for (const double tick : layout.y_ticks) {
    const float y = p.at_axis_value(layout.x_low, tick).y;
    const bool zero = p.chart.plain && tick == 0.0;
    p.line(zero ? Kind::axis : Kind::grid, ImVec2(layout.low_left.x, y), ImVec2(layout.high_right.x, y),
           zero ? p.theme.axis : p.theme.grid, 1.0f);
  }
}

// The shaded spans of x, across the data's height.
void draw_bands(const Painter& p) {
  for (const auto& [x0, x1] : p.chart.bands) {
    const float left = p.layout.to_screen(x0, 1.0).x, right = p.layout.to_screen(x1, 1.0).x;
    p.draw->AddRectFilled(ImVec2(left, p.layout.high_right.y), ImVec2(std::max(right, left + 1.0f), p.layout.low_left.y),
                          p.chart.band_colour);
  }
}

// The theory over the measurements, each curve in its own pattern, the branch that applies now
// bold: each dash on a dash a point wider in the panel's colour, so that a curve lying on the
// data or on a level still shows, and the data shows in its gaps. (Drawn under them, push's
// dashed "sticking: f = −F" vanished under the measured line it agrees with, and its dotted
// "sliding" line on the −μk·N level: a teacher's trial.)
void draw_theory_curves(const Painter& p) {
  const ImU32 edge = p.theme.panel;
  for (std::size_t c = 0; c < p.layout.theory.size(); ++c) {
    const ChartCurve& curve = p.chart.theory[c];
    const float thickness = (static_cast<int>(c) == p.layout.active ? 3.5f : 1.8f) * p.s;
    for (const std::vector<ImVec2>& piece : p.layout.theory[c]) {
      draw_dashed(p.draw, piece, edge, thickness + 2.0f * p.s, curve.dash * p.s, curve.gap * p.s);
      draw_dashed(p.draw, piece, curve.colour, thickness, curve.dash * p.s, curve.gap * p.s);
    }
  }
}

// Each series: the labels beside its points, its line (each segment in its regime's colour,
// where it has them), its markers, and the present's dot on its last point.
void draw_series(const Painter& p) {
  const Chart& chart = p.chart;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& series = chart.series[k];
    const std::vector<ImVec2>& points = p.layout.series_points[k];
    const std::vector<std::size_t>& indices = p.layout.series_indices[k];
    const std::vector<ImU32>* colours = k < chart.segment_colours.size() && !chart.segment_colours[k].empty() ? &chart.segment_colours[k] : nullptr;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (indices[i] < series.labels.size()) {
        p.draw->AddText(p.font, 0.85f * p.text, ImVec2(points[i].x + 4.0f * p.s, points[i].y - 0.9f * p.text),
                        readable_ink(series.colour, p.theme.panel), series.labels[indices[i]].c_str());
      }
    }
    if (series.line && colours != nullptr) {
      for (std::size_t i = 1; i < points.size(); ++i) {
        const ImU32 colour = indices[i] < colours->size() ? (*colours)[indices[i]] : series.colour;
        p.draw->AddLine(points[i - 1], points[i], colour, 2.5f * p.s);
      }
    } else if (series.line && points.size() > 1 && series.dash > 0.0f) {
      draw_dashed(p.draw, points, series.colour, 2.5f * p.s, series.dash * p.s, series.gap * p.s);
    } else if (series.line && points.size() > 1) {
      p.draw->AddPolyline(points.data(), static_cast<int>(points.size()), series.colour, ImDrawFlags_None, 2.0f * p.s);
    }
    for (const ImVec2& at : points) {
      const float r = 3.5f * p.s;
      if (series.marker == Marker::dot) p.draw->AddCircleFilled(at, r, series.colour);
      if (series.marker == Marker::cross) {
        p.draw->AddLine(ImVec2(at.x - r, at.y - r), ImVec2(at.x + r, at.y + r), series.colour, 2.0f * p.s);
        p.draw->AddLine(ImVec2(at.x - r, at.y + r), ImVec2(at.x + r, at.y - r), series.colour, 2.0f * p.s);
      }
    }
  }
  if (chart.mark_now && std::isfinite(chart.now_x)) {
    const float x = p.layout.to_screen(chart.now_x, 1.0).x;
    p.draw->AddLine(ImVec2(x, p.layout.high_right.y), ImVec2(x, p.layout.low_left.y), chart.now_colour, 1.5f * p.s);
  }
}

// The present's dot on each series' last point, over everything in the data area: what the
// class watches.
void draw_present(const Painter& p) {
  if (!p.chart.mark_now) return;
  for (const std::vector<ImVec2>& points : p.layout.series_points) {
    if (!points.empty()) p.draw->AddCircleFilled(points.back(), 4.0f * p.s, p.chart.now_colour, 12);
  }
}

// The levels' lines, under the series: the values the class reads off the plot.
void draw_level_lines(const Painter& p) {
  for (const ChartLayout::Level& placed : p.layout.levels) {
    const ChartLevel& level = p.chart.levels[placed.index];
    // Solid: every dash pattern is a theory curve's (a teacher's trial read push's dashed
    // −μs·N level for its dashed "sticking: f = −F" key, both grey). Thin and labelled, it is no
    // series either (those are 2 points and more, in the series' colours).
    p.draw->AddLine(ImVec2(p.layout.low_left.x, placed.y), ImVec2(p.layout.high_right.x, placed.y), level.colour, 1.5f * p.s);
  }
}

// The levels' texts placed `beneath` the series (or not), each on a box of the panel's colour.
void draw_level_texts(const Painter& p, bool beneath) {
  for (const ChartLayout::Level& placed : p.layout.levels) {
    if (placed.beneath != beneath || placed.beside || placed.text.empty()) continue;
    const ChartLevel& level = p.chart.levels[placed.index];
    // Opaque: the text is read against the panel's colour it was chosen for (readable_ink),
    // not a slip band or a grid line showing through (incline's ochre text, as the second
    // theory colour was, on its pink band read 4.36:1).
    p.draw->AddRectFilled(ImVec2(placed.at.x - 2.0f * p.s, placed.at.y - 1.0f), ImVec2(placed.at.z + 2.0f * p.s, placed.at.w + 1.0f),
                          p.theme.panel);
    ImFont* font = p.layout.level_font != nullptr ? p.layout.level_font : p.numbers;
    p.draw->AddText(font, font->FontSize, ImVec2(placed.at.x, placed.at.y), readable_ink(level.colour, p.theme.panel), level.text.c_str());
  }
}

// The levels' texts in the column beside the data, each led to from its line's end by a line
// of its colour, on a box of the panel's colour.
void draw_level_texts_beside(const Painter& p) {
  for (const ChartLayout::Level& placed : p.layout.levels) {
    if (!placed.beside || placed.text.empty()) continue;
    const ChartLevel& level = p.chart.levels[placed.index];
    const float middle = 0.5f * (placed.at.y + placed.at.w);
    p.draw->AddLine(ImVec2(p.layout.high_right.x, placed.y), ImVec2(placed.at.x - 3.0f * p.s, middle), level.colour, 1.5f * p.s);
    p.draw->AddRectFilled(ImVec2(placed.at.x - 2.0f * p.s, placed.at.y - 1.0f), ImVec2(placed.at.z + 2.0f * p.s, placed.at.w + 1.0f),
                          p.theme.panel);
    ImFont* font = p.layout.level_font != nullptr ? p.layout.level_font : p.numbers;
    p.draw->AddText(font, font->FontSize, ImVec2(placed.at.x, placed.at.y), readable_ink(level.colour, p.theme.panel),
                    level_text_as_written(placed, level.text).c_str());
  }
}

// The data area's edges, a steady chart's tick marks, the tick labels and the axes' names.
void draw_axes(Painter& p) {
  const Chart& chart = p.chart;
  ChartLayout& layout = p.layout;
  const ImVec2 low_left = layout.low_left, high_right = layout.high_right;
  p.draw->AddRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x, low_left.y), p.theme.axis, 0.0f, 0, 1.0f);
  for (const auto& [from, to] : {std::pair{low_left, ImVec2(high_right.x, low_left.y)}, std::pair{low_left, ImVec2(low_left.x, high_right.y)},
                                 std::pair{high_right, ImVec2(high_right.x, low_left.y)}, std::pair{high_right, ImVec2(low_left.x, high_right.y)}}) {
    layout.lines.push_back({Kind::axis, from, to, p.theme.axis});
  }
  const float s = p.s;
  if (chart.steady) {
    // Tick marks outside the data in the axes' colour, between the edge and the tick labels:
    // on a projector the faint grid (1.3:1 on the panel) fades, and the ticks are what the
    // levels are read against (WCAG 2.1 1.4.11 asks 3:1 of them).
    const float length = 4.0f * s, thickness = 1.5f * s;
    for (const double tick : layout.y_ticks) {
      const float y = p.at_axis_value(layout.x_low, tick).y;
      p.line(Kind::tick, ImVec2(low_left.x - length, y), ImVec2(low_left.x, y), p.theme.axis, thickness);
    }
    // The marks between them, shorter and thinner, as a ruler's.
    for (const double tick : layout.y_minor_ticks) {
      const float y = p.at_axis_value(layout.x_low, tick).y;
      p.line(Kind::tick, ImVec2(low_left.x - 0.6f * length, y), ImVec2(low_left.x, y), p.theme.axis, 0.7f * thickness);
    }
    for (const double tick : layout.x_ticks) {
      const float x = p.at_axis_value(tick, layout.y_low).x;
      p.line(Kind::tick, ImVec2(x, low_left.y), ImVec2(x, low_left.y + length), p.theme.axis, thickness);
    }
    for (const double tick : layout.x_minor_ticks) {
      const float x = p.at_axis_value(tick, layout.y_low).x;
      p.line(Kind::tick, ImVec2(x, low_left.y), ImVec2(x, low_left.y + 0.6f * length), p.theme.axis, 0.7f * thickness);
    }
  }
  // The tick labels and the axes' names where layout_chart put them (place_axis_texts): the
  // ticks' labels in the numbers' font, the axes' names in the small text's.
  using TextKind = ChartLayout::AxisText::Kind;
  for (const ChartLayout::AxisText& label : layout.axis_texts) {
    ImFont* font = label.kind == TextKind::y_tick ? p.numbers : p.font;
    const ImU32 colour = label.kind == TextKind::y_name                       ? p.theme.faint_text
                         : label.kind == TextKind::x_name && chart.plain ? p.theme.faint_text
                                                                         : p.theme.text;
    p.draw->AddText(font, font->FontSize, ImVec2(label.at.x, label.at.y), colour, label.text.c_str());
  }
}

}  // namespace

ChartLayout draw_chart(ImDrawList* draw, ImVec2 corner, ImVec2 size, const Chart& chart, const Theme& theme,
                       const Fonts& fonts) {
  const float s = fonts.scale;
  if (!chart.plain) {
    draw->AddRectFilled(corner, ImVec2(corner.x + size.x, corner.y + size.y), theme.panel);
    draw->AddText(fonts.body, fonts.body->FontSize, ImVec2(corner.x + 8.0f * s, corner.y + 4.0f * s), theme.text,
                  chart.title.c_str());
  }
  if (chart.legend == Chart::Legend::only) {
    draw_legend_only(draw, corner, chart, theme, fonts);
    return {};
  }
  ChartLayout layout = layout_chart(chart, corner, size, fonts);
  if (!layout.drawable) return layout;
  Painter painter{draw, chart, layout, theme, fonts};
  // What lies in the data area, clipped to it, from the bottom layer up.
  draw->PushClipRect(ImVec2(layout.low_left.x, layout.high_right.y), ImVec2(layout.high_right.x + 1.0f, layout.low_left.y + 1.0f), true);
  draw_map(painter, axes_of(chart));
  draw_grid(painter);
  draw_bands(painter);
  // The levels' lines and the texts that found no place off the data under the series; the
  // theory over them; the other texts, off the data, and the present's dots on top.
  draw_level_lines(painter);
  draw_level_texts(painter, true);
  draw_series(painter);
  draw_theory_curves(painter);
  draw_level_texts(painter, false);
  draw_present(painter);
  if (!chart.message.empty()) {
    draw->AddText(painter.font, painter.text, ImVec2(layout.low_left.x + 4.0f * s, layout.high_right.y + 4.0f * s), theme.bad,
                  chart.message.c_str(), nullptr, layout.high_right.x - layout.low_left.x - 8.0f * s);
  }
  draw->PopClipRect();
  draw_level_texts_beside(painter);
  draw_axes(painter);
  draw_legend(draw, chart, keys_of(chart), layout, size, theme, fonts);
  return layout;
}

void give_theory_look(ChartCurve& curve, const Theme& theme, std::size_t index) {
  // Dots short enough to read as dots beside the dashes, long dashes long enough to read as
  // longer, even in a legend's 16-point swatch.
  constexpr float patterns[3][2] = {{6.0f, 4.0f}, {2.0f, 3.0f}, {11.0f, 4.0f}};
  curve.dash = patterns[index % 3][0];
  curve.gap = patterns[index % 3][1];
  curve.colour = theme.theory[index % 2];
}

int nearest_curve(const std::vector<CurvePieces>& curves, ImVec2 point) {
  int nearest = -1;
  double least = INFINITY;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    for (const std::vector<ImVec2>& piece : curves[c]) {
      for (std::size_t i = 0; i < piece.size(); ++i) {
        // Distance to the segment from this point to the next (or to the point, when alone).
        const ImVec2 a = piece[i], b = i + 1 < piece.size() ? piece[i + 1] : piece[i];
        const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
        const double along = length2 > 0.0 ? std::clamp(((point.x - a.x) * dx + (point.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
        const double ex = a.x + along * dx - point.x, ey = a.y + along * dy - point.y;
        const double distance = ex * ex + ey * ey;
        if (distance < least) least = distance, nearest = static_cast<int>(c);
      }
    }
  }
  return nearest;
}

void draw_dashed(ImDrawList* draw, const std::vector<ImVec2>& points, ImU32 colour, float thickness, float dash, float gap) {
  float phase = 0.0f;  // how far into the dash-and-gap pattern the next segment starts
  const float period = dash + gap;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const ImVec2 a = points[i - 1], b = points[i];
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    float done = 0.0f;
    while (done < length) {
      const float in_period = std::fmod(phase + done, period);
      const float step = std::min(length - done, in_period < dash ? dash - in_period : period - in_period);
      if (in_period < dash && length > 0.0f) {
        const float t0 = done / length, t1 = (done + step) / length;
        draw->AddLine(ImVec2(a.x + (b.x - a.x) * t0, a.y + (b.y - a.y) * t0), ImVec2(a.x + (b.x - a.x) * t1, a.y + (b.y - a.y) * t1),
                      colour, thickness);
      }
      done += std::max(step, 1e-3f);
    }
    phase = std::fmod(phase + length, period);
  }
}

}  // namespace frictionlab::draw
