#include "ui/chart.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ui/headless.h"
#include "ui/imgui_host.h"
#include "ui/plots.h"

namespace frictionlab::ui {
namespace {

struct Axis {
  bool log = false;
  double low = 0.0, high = 1.0;  // in the axis' own space: log10 of the value on a log axis

  bool shows(double value) const { return std::isfinite(value) && (!log || value > 0.0); }
  double map(double value) const { return log ? std::log10(value) : value; }
  // 0 at low, 1 at high.
  double fraction(double value) const { return (map(value) - low) / (high - low); }
};

// 10⁻³: the exponent in superscript digits, which the loaded font has.
std::string power_of_ten(int exponent) {
  static const char* const digits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                       "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string text = "10";
  if (exponent < 0) text += "\u207b";
  for (const char c : std::to_string(std::abs(exponent))) text += digits[c - '0'];
  return text;
}

Axis axis_of(bool log, const std::vector<double>& values) {
  Axis axis;
  axis.log = log;
  double low = INFINITY, high = -INFINITY;
  for (const double value : values) {
    if (!axis.shows(value)) continue;
    low = std::min(low, axis.map(value));
    high = std::max(high, axis.map(value));
  }
  if (!(low <= high)) return axis;
  if (high - low < 1e-12) {
    low -= 0.5;
    high += 0.5;
  }
  const double margin = 0.04 * (high - low);
  axis.low = low - margin;
  axis.high = high + margin;
  return axis;
}

struct Tick {
  double value;  // in the axis' own space
  std::string label;
};

std::vector<Tick> ticks_of(const Axis& axis) {
  std::vector<Tick> ticks;
  if (axis.log) {
    const int first = static_cast<int>(std::ceil(axis.low - 1e-9)), last = static_cast<int>(std::floor(axis.high + 1e-9));
    const int every = std::max(1, (last - first + 1) / 7 + 1);
    for (int exponent = first; exponent <= last; ++exponent) {
      if ((exponent - first) % every == 0) ticks.push_back({static_cast<double>(exponent), power_of_ten(exponent)});
    }
    if (ticks.size() >= 2) return ticks;
    // Less than two decades in view: 1, 2 and 5 times each power of ten, so the axis still reads.
    ticks.clear();
    for (int exponent = first - 1; exponent <= last; ++exponent) {
      for (const int mantissa : {1, 2, 5}) {
        const double at = exponent + std::log10(static_cast<double>(mantissa));
        if (at < axis.low - 1e-9 || at > axis.high + 1e-9) continue;
        ticks.push_back({at, mantissa == 1 ? power_of_ten(exponent) : std::to_string(mantissa) + "\u00d7" + power_of_ten(exponent)});
      }
    }
    return ticks;
  }
  const std::vector<double> values = axis_ticks(axis.low, axis.high, 5);
  const double step = values.size() > 1 ? values[1] - values[0] : 1.0;
  for (const double value : values) ticks.push_back({value, tick_text(value, step)});
  return ticks;
}

// Where each grid value's cell begins and ends, half-way to its neighbours (in axis space).
std::vector<std::pair<double, double>> cell_edges(const Axis& axis, std::vector<double> values) {
  for (double& value : values) value = axis.map(value);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<std::pair<double, double>> edges;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double before = i > 0 ? 0.5 * (values[i] - values[i - 1]) : (values.size() > 1 ? 0.5 * (values[1] - values[0]) : 0.5);
    const double after = i + 1 < values.size() ? 0.5 * (values[i + 1] - values[i]) : before;
    edges.push_back({values[i] - before, values[i] + after});
  }
  return edges;
}

}  // namespace

void draw_chart(ImDrawList* draw, ImVec2 corner, ImVec2 size, const Chart& chart, const Theme& theme, const Fonts& fonts) {
  const float s = fonts.scale;
  ImFont* font = fonts.small;
  const float text = font->FontSize;
  draw->AddRectFilled(corner, ImVec2(corner.x + size.x, corner.y + size.y), theme.panel);
  draw->AddText(fonts.body, fonts.body->FontSize, ImVec2(corner.x + 8.0f * s, corner.y + 4.0f * s), theme.text,
                chart.title.c_str());

  std::vector<double> xs, ys;
  for (const ChartCell& cell : chart.cells) {
    xs.push_back(cell.x);
    ys.push_back(cell.y);
  }
  for (const ChartSeries& series : chart.series) {
    for (const auto& [x, y] : series.points) {
      xs.push_back(x);
      ys.push_back(y);
    }
  }
  Axis x_axis = axis_of(chart.log_x, xs), y_axis = axis_of(chart.log_y, ys);
  // A map fills its axes to the cells' edges.
  std::vector<std::pair<double, double>> x_edges, y_edges;
  if (!chart.cells.empty()) {
    x_edges = cell_edges(x_axis, xs.size() > chart.cells.size() ? std::vector<double>(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(chart.cells.size())) : xs);
    y_edges = cell_edges(y_axis, ys.size() > chart.cells.size() ? std::vector<double>(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(chart.cells.size())) : ys);
    x_axis.low = x_edges.front().first;
    x_axis.high = x_edges.back().second;
    y_axis.low = y_edges.front().first;
    y_axis.high = y_edges.back().second;
  }
  const std::vector<Tick> x_ticks = ticks_of(x_axis), y_ticks = ticks_of(y_axis);
  float label_width = 0.0f;
  for (const Tick& tick : y_ticks) label_width = std::max(label_width, font->CalcTextSizeA(text, 1e6f, 0.0f, tick.label.c_str()).x);
  // The legend goes under the chart, in two columns, so it hides none of it.
  // A map's categories that no cell has are left out of the legend.
  std::vector<std::pair<std::string, ImU32>> entries;
  for (std::size_t category = 0; category < chart.categories.size(); ++category) {
    const bool present = std::any_of(chart.cells.begin(), chart.cells.end(), [&](const ChartCell& cell) {
      return cell.category == static_cast<int>(category);
    });
    if (present) entries.push_back(chart.categories[category]);
  }
  for (const ChartSeries& series : chart.series) {
    if (!series.name.empty()) entries.push_back({series.name, series.colour});
  }
  const float line = text + 3.0f * s;
  if (chart.legend == Chart::Legend::only) {
    float y = corner.y + fonts.body->FontSize + text + 16.0f * s;
    for (const auto& [name, colour] : entries) {
      draw->AddRectFilled(ImVec2(corner.x + 12.0f * s, y + 2.0f * s), ImVec2(corner.x + 24.0f * s, y + text - 2.0f * s), colour);
      draw->AddText(font, text, ImVec2(corner.x + 30.0f * s, y), theme.text, name.c_str());
      y += line;
    }
    for (const std::string& note : chart.notes) {
      draw->AddText(font, text, ImVec2(corner.x + 12.0f * s, y + 6.0f * s), theme.faint_text, note.c_str());
      y += line;
    }
    return;
  }
  if (chart.legend == Chart::Legend::none) entries.clear();
  const std::size_t entry_rows = (entries.size() + 1) / 2;
  const float legend_height = line * static_cast<float>(entry_rows + chart.notes.size()) + (entries.empty() ? 0.0f : 6.0f * s);
  const float top = corner.y + fonts.body->FontSize + text + 16.0f * s;
  const ImVec2 low_left(corner.x + label_width + 16.0f * s, corner.y + size.y - 2.0f * text - 14.0f * s - legend_height);
  // Room on the right for the labels beside the last points (a step rate, say).
  const bool labelled = std::any_of(chart.series.begin(), chart.series.end(), [](const ChartSeries& series) { return !series.labels.empty(); });
  const ImVec2 high_right(corner.x + size.x - (labelled ? 60.0f : 10.0f) * s, top);
  const float width = high_right.x - low_left.x, height = low_left.y - high_right.y;
  if (width < 20.0f || height < 20.0f) return;
  const auto to_screen = [&](double x, double y) {
    return ImVec2(low_left.x + static_cast<float>(x_axis.fraction(x)) * width,
                  low_left.y - static_cast<float>(y_axis.fraction(y)) * height);
  };
  const auto at_axis_value = [&](double x, double y) {  // values already in axis space
    return ImVec2(low_left.x + static_cast<float>((x - x_axis.low) / (x_axis.high - x_axis.low)) * width,
                  low_left.y - static_cast<float>((y - y_axis.low) / (y_axis.high - y_axis.low)) * height);
  };

  draw->PushClipRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x, low_left.y), true);
  for (const ChartCell& cell : chart.cells) {
    if (!x_axis.shows(cell.x) || !y_axis.shows(cell.y) || cell.category < 0 ||
        cell.category >= static_cast<int>(chart.categories.size())) {
      continue;
    }
    const double x = x_axis.map(cell.x), y = y_axis.map(cell.y);
    const auto edge = [](const std::vector<std::pair<double, double>>& edges, double value) {
      for (const auto& e : edges) {
        if (value >= e.first && value <= e.second) return e;
      }
      return std::make_pair(value, value);
    };
    const auto [x0, x1] = edge(x_edges, x);
    const auto [y0, y1] = edge(y_edges, y);
    draw->AddRectFilled(at_axis_value(x0, y1), at_axis_value(x1, y0), chart.categories[static_cast<std::size_t>(cell.category)].second);
  }
  for (const Tick& tick : x_ticks) {
    const float x = at_axis_value(tick.value, y_axis.low).x;
    draw->AddLine(ImVec2(x, high_right.y), ImVec2(x, low_left.y), theme.grid, 1.0f);
  }
  for (const Tick& tick : y_ticks) {
    const float y = at_axis_value(x_axis.low, tick.value).y;
    draw->AddLine(ImVec2(low_left.x, y), ImVec2(high_right.x, y), theme.grid, 1.0f);
  }
  for (const ChartSeries& series : chart.series) {
    std::vector<ImVec2> points;
    for (std::size_t i = 0; i < series.points.size(); ++i) {
      const auto [x, y] = series.points[i];
      if (!x_axis.shows(x) || !y_axis.shows(y)) continue;
      points.push_back(to_screen(x, y));
      if (i < series.labels.size()) {
        draw->AddText(font, 0.85f * text, ImVec2(points.back().x + 4.0f * s, points.back().y - 0.9f * text), series.colour,
                      series.labels[i].c_str());
      }
    }
    if (series.line && points.size() > 1) {
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), series.colour, ImDrawFlags_None, 2.0f * s);
    }
    for (const ImVec2& p : points) {
      const float r = 3.5f * s;
      if (series.marker == Marker::dot) draw->AddCircleFilled(p, r, series.colour);
      if (series.marker == Marker::cross) {
        draw->AddLine(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), series.colour, 2.0f * s);
        draw->AddLine(ImVec2(p.x - r, p.y + r), ImVec2(p.x + r, p.y - r), series.colour, 2.0f * s);
      }
    }
  }
  draw->PopClipRect();

  // Axes, tick labels and titles.
  draw->AddRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x, low_left.y), theme.axis, 0.0f, 0, 1.0f);
  for (const Tick& tick : x_ticks) {
    const float x = at_axis_value(tick.value, y_axis.low).x;
    const float w = font->CalcTextSizeA(text, 1e6f, 0.0f, tick.label.c_str()).x;
    draw->AddText(font, text, ImVec2(x - 0.5f * w, low_left.y + 3.0f * s), theme.text, tick.label.c_str());
  }
  for (const Tick& tick : y_ticks) {
    const float y = at_axis_value(x_axis.low, tick.value).y;
    const float w = font->CalcTextSizeA(text, 1e6f, 0.0f, tick.label.c_str()).x;
    draw->AddText(font, text, ImVec2(low_left.x - w - 4.0f * s, y - 0.5f * text), theme.text, tick.label.c_str());
  }
  const float x_title = font->CalcTextSizeA(text, 1e6f, 0.0f, chart.x_label.c_str()).x;
  draw->AddText(font, text, ImVec2(low_left.x + 0.5f * (width - x_title), low_left.y + text + 6.0f * s), theme.text,
                chart.x_label.c_str());
  draw->AddText(font, text, ImVec2(corner.x + 8.0f * s, top - text - 4.0f * s), theme.faint_text, chart.y_label.c_str());

  // The legend: categories, then series, in two columns; then the notes.
  const ImVec2 legend(corner.x + 12.0f * s, low_left.y + 2.0f * text + 14.0f * s);
  const float column = 0.5f * (size.x - 24.0f * s);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const ImVec2 at(legend.x + column * static_cast<float>(i % 2), legend.y + line * static_cast<float>(i / 2));
    draw->AddRectFilled(ImVec2(at.x, at.y + 2.0f * s), ImVec2(at.x + 12.0f * s, at.y + text - 2.0f * s), entries[i].second);
    draw->AddText(font, text, ImVec2(at.x + 18.0f * s, at.y), theme.text, entries[i].first.c_str());
  }
  float y = legend.y + line * static_cast<float>(entry_rows);
  for (const std::string& note : chart.notes) {
    draw->AddText(font, text, ImVec2(legend.x, y), theme.faint_text, note.c_str());
    y += line;
  }
}

LegendPlace legend_corner(ImVec2 area_min, ImVec2 area_max, ImVec2 legend_size, float inset,
                          const std::vector<ImVec2>& points, float radius) {
  const ImVec2 corners[] = {{area_max.x - inset - legend_size.x, area_min.y + inset},
                            {area_min.x + inset, area_min.y + inset},
                            {area_max.x - inset - legend_size.x, area_max.y - inset - legend_size.y},
                            {area_min.x + inset, area_max.y - inset - legend_size.y}};
  LegendPlace best;
  std::size_t fewest = static_cast<std::size_t>(-1);
  for (const ImVec2& corner : corners) {
    std::size_t met = 0;
    for (const ImVec2& p : points) {
      met += p.x + radius >= corner.x && p.x - radius <= corner.x + legend_size.x && p.y + radius >= corner.y &&
             p.y - radius <= corner.y + legend_size.y;
    }
    if (met < fewest) {
      fewest = met;
      best = {corner, ImVec2(corner.x + legend_size.x, corner.y + legend_size.y), met == 0};
    }
  }
  return best;
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

Image render_charts(const std::vector<Chart>& charts, int columns, int width, int height) {
  HeadlessContext gl;
  ImGuiHost host(nullptr);
  const float scale = frame_scale(width, height) < 1.0f ? 1.0f : frame_scale(width, height);
  const Fonts& fonts = host.prepare(scale, ThemeName::light);
  const Theme& colours = theme(ThemeName::light);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 60.0f;
  gl.bind_framebuffer(width, height);
  host.begin_frame();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  columns = std::max(columns, 1);
  const int rows = (static_cast<int>(charts.size()) + columns - 1) / columns;
  const float cell_width = static_cast<float>(width) / static_cast<float>(columns);
  const float cell_height = static_cast<float>(height) / static_cast<float>(std::max(rows, 1));
  const float gap = 6.0f * scale;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const float x = cell_width * static_cast<float>(static_cast<int>(i) % columns);
    const float y = cell_height * static_cast<float>(static_cast<int>(i) / columns);
    draw_chart(draw, ImVec2(x + gap, y + gap), ImVec2(cell_width - 2.0f * gap, cell_height - 2.0f * gap), charts[i],
               colours, fonts);
  }
  const ImVec4 clear = ImGui::ColorConvertU32ToFloat4(colours.background);
  glClearColor(clear.x, clear.y, clear.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  host.end_frame();
  return gl.read_pixels();
}

}  // namespace frictionlab::ui
