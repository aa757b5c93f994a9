// The chart's axes: where a value lies on an axis, round tick positions and their labels (a
// true minus, superscript powers of ten on a log axis), the axes' ranges from the data or a
// map's cells, and the y ticks fitted to the data area's height.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "draw/chart.h"
#include "draw/chart_parts.h"

namespace frictionlab::draw {

// Where `value` lies from `low` (0) to `high` (1). In halves: values near ±1.7e308 are finite,
// but their differences may not be.
double share(double value, double low, double high) { return (0.5 * value - 0.5 * low) / (0.5 * high - 0.5 * low); }

namespace chart_parts {

std::vector<double> multiples_of(double step, double low, double high, std::size_t most) {
  std::vector<double> ticks;
  for (double tick = std::ceil(low / step - 1e-9) * step; tick <= high + 1e-9 * step && ticks.size() < most; tick += step) {
    ticks.push_back(std::abs(tick) < 1e-12 * step ? 0.0 : tick);
  }
  return ticks;
}

}  // namespace chart_parts

using chart_parts::Axis;
using chart_parts::ChartAxes;
using chart_parts::multiples_of;
using chart_parts::Tick;

std::vector<double> axis_ticks(double low, double high, int count) {
  if (!(high > low) || count < 1) return {};
  // In halves: the span of values near ±1.7e308 would overflow to infinity, and so may a step
  // of ten times a power of ten up there; such a step is made the largest that fits.
  const double half_rough = (0.5 * high - 0.5 * low) / count;
  const double power = std::pow(10.0, std::floor(std::log10(half_rough) + std::log10(2.0)));
  const double fraction = 2.0 * (half_rough / power);
  double step = (fraction < 1.5 ? 1.0 : fraction < 3.5 ? 2.0 : fraction < 7.5 ? 5.0 : 10.0) * power;
  for (const double smaller : {5.0, 2.0, 1.0}) {
    if (!std::isfinite(step)) step = smaller * power;
  }
  // At most a few more ticks than asked for.
  return multiples_of(step, low, high, 4u * static_cast<std::size_t>(count) + 4u);
}

std::string tick_text(double value, double step) {
  char text[32];
  if (std::abs(value) >= 1e7 || step >= 1e7) {
    // Too many digits to write out (1e308 would take 309): three significant ones, 1.5e+12.
    std::snprintf(text, sizeof text, "%.3g", value);
    std::string shown = text;
    if (!shown.empty() && shown[0] == '-') shown.replace(0, 1, "\u2212");
    return shown;
  }
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(text, sizeof text, "%.*f", std::min(decimals, 6), value);
  std::string shown = text;
  // A value that rounds to zero is zero, not "−0" or "−0.000" (a tick a rounding away from 0).
  if (shown.find_first_not_of("-0.") == std::string::npos) shown.erase(0, shown[0] == '-' ? 1 : 0);
  if (!shown.empty() && shown[0] == '-') shown.replace(0, 1, "\u2212");
  return shown;
}

namespace {

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
  // In halves, and kept within what a double holds: values near ±1.7e308 are finite, but
  // their span is not.
  if (0.5 * high - 0.5 * low < 0.5e-12) {
    low -= 0.5;
    high += 0.5;
  }
  const double margin = 0.08 * (0.5 * high - 0.5 * low);  // 4 % of the span
  constexpr double largest = std::numeric_limits<double>::max();
  axis.low = std::max(low - margin, -largest);
  axis.high = std::min(high + margin, largest);
  return axis;
}

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

namespace chart_parts {

ChartAxes axes_of(const Chart& chart) {
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
  ChartAxes axes;
  axes.x = chart.fixed_x ? Axis{false, chart.x_low, chart.x_high} : axis_of(chart.log_x, xs);
  axes.y = chart.fixed_y ? Axis{false, chart.y_low, chart.y_high} : axis_of(chart.log_y, ys);
  // A map fills its axes to the cells' edges.
  if (!chart.cells.empty()) {
    const auto first_cells = [&](const std::vector<double>& values) {
      return values.size() > chart.cells.size()
                 ? std::vector<double>(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(chart.cells.size()))
                 : values;
    };
    axes.x_edges = cell_edges(axes.x, first_cells(xs));
    axes.y_edges = cell_edges(axes.y, first_cells(ys));
    axes.x.low = axes.x_edges.front().first;
    axes.x.high = axes.x_edges.back().second;
    axes.y.low = axes.y_edges.front().first;
    axes.y.high = axes.y_edges.back().second;
  }
  return axes;
}

std::vector<Tick> ticks_every(const Axis& axis, int count) {
  if (axis.log) return ticks_of(axis);
  std::vector<Tick> ticks;
  const std::vector<double> values = axis_ticks(axis.low, axis.high, count);
  const double step = values.size() > 1 ? values[1] - values[0] : 1.0;
  for (const double value : values) ticks.push_back({value, tick_text(value, step)});
  return ticks;
}

std::vector<double> minor_ticks(const std::vector<double>& ticks, double low, double high, float pixels_per_unit, float s) {
  std::vector<double> marks;
  if (ticks.size() < 2 || !(high > low) || !(pixels_per_unit > 0.0f)) return marks;
  const double step = ticks[1] - ticks[0];
  const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const long whole = std::lround(step / power);
  for (const int parts : {5, 4, 2}) {
    // A part that is no round step (a fifth of 2, a quarter of 1 or 5) is passed over.
    if ((whole == 2 && parts == 5) || (whole != 2 && parts == 4)) continue;
    const double minor = step / parts;
    if (static_cast<float>(minor) * pixels_per_unit < 4.0f * s) continue;
    for (const double value : multiples_of(minor, low, high, 400)) {
      // Not where a labelled tick is.
      if (std::abs(std::remainder(value, step)) > 1e-6 * step) marks.push_back(value);
    }
    break;
  }
  return marks;
}

void fit_y_ticks(const Chart& chart, const Axis& y_axis, float text, float s, ChartLayout& layout) {
  const float data_height = layout.low_left.y - layout.high_right.y;
  const auto spacing = [&](const std::vector<double>& ticks) {
    return ticks.size() < 2 ? INFINITY
                            : static_cast<float>((0.5 * ticks[1] - 0.5 * ticks[0]) / (0.5 * layout.y_high - 0.5 * layout.y_low)) *
                                  data_height;
  };
  // The finest round step whose ticks keep the spacing asked for: a tall plot's levels read off
  // its axis (1 N apart where 2 or 5 N were, at push's defaults on a projector).
  if (chart.y_tick_spacing > 0.0f && !y_axis.log) {
    for (int count = 2; count <= 40; ++count) {
      const std::vector<Tick> finer = ticks_every(y_axis, count);
      std::vector<double> values;
      for (const Tick& tick : finer) values.push_back(tick.value);
      if (values.size() >= 2 && spacing(values) < chart.y_tick_spacing * s) break;
      layout.y_ticks = values;
      layout.y_tick_labels.clear();
      for (const Tick& tick : finer) layout.y_tick_labels.push_back(tick.label);
    }
  }
  // Fewer y ticks where the data area is short for its text (large text in a small plot): the
  // labels at least a line and a third apart, so none is printed on another.
  if (!y_axis.log && spacing(layout.y_ticks) < 1.35f * text) {
    for (int count = chart.y_tick_count - 1; count >= 1; --count) {
      const std::vector<Tick> fewer = ticks_every(y_axis, count);
      std::vector<double> values;
      for (const Tick& tick : fewer) values.push_back(tick.value);
      if (spacing(values) >= 1.35f * text || count == 1) {
        layout.y_ticks = values;
        layout.y_tick_labels.clear();
        for (const Tick& tick : fewer) layout.y_tick_labels.push_back(tick.label);
        break;
      }
    }
    // Down to one tick (often just "0"), the axis could not be read. Round values a little
    // closer together than the 1, 2, 5 steps allow come first (−4, 0, 4 on pulley's −4.4 to 4.8
    // N, where the steps of 5 left "0" alone and the ends read "−4.4" and "4.8"); else its two
    // ends are labelled, where the data area is tall enough to hold two labels apart.
    if (layout.y_ticks.size() < 2 && layout.y_high > layout.y_low) {
      const double span = layout.y_high - layout.y_low;
      const double power = std::pow(10.0, std::floor(std::log10(span)));
      for (const double decade : {power, 0.1 * power}) {
        for (const double whole : {5.0, 4.0, 3.0, 2.0, 1.0}) {
          const double step = whole * decade;
          const std::vector<double> values = multiples_of(step, layout.y_low, layout.y_high, 12);
          if (values.size() < 2 || spacing(values) < 1.35f * text) continue;
          layout.y_ticks = values;
          layout.y_tick_labels.clear();
          for (const double value : values) layout.y_tick_labels.push_back(tick_text(value, step));
          break;
        }
        if (layout.y_ticks.size() >= 2) break;
      }
    }
    if (layout.y_ticks.size() < 2 && data_height >= 1.35f * text && layout.y_high > layout.y_low) {
      const double span = layout.y_high - layout.y_low;
      layout.y_ticks = {layout.y_low, layout.y_high};
      layout.y_tick_labels = {tick_text(layout.y_low, 0.1 * span), tick_text(layout.y_high, 0.1 * span)};
    }
  }
  layout.y_minor_ticks.clear();
  if (chart.plain && chart.steady && !y_axis.log) {
    layout.y_minor_ticks = minor_ticks(layout.y_ticks, layout.y_low, layout.y_high,
                                       (layout.low_left.y - layout.high_right.y) / static_cast<float>(layout.y_high - layout.y_low), s);
  }
}

}  // namespace chart_parts

ImVec2 ChartLayout::to_screen(double x, double y) const {
  const double ax = log_x ? std::log10(x) : x, ay = log_y ? std::log10(y) : y;
  return ImVec2(low_left.x + static_cast<float>(share(ax, x_low, x_high)) * (high_right.x - low_left.x),
                low_left.y - static_cast<float>(share(ay, y_low, y_high)) * (low_left.y - high_right.y));
}

}  // namespace frictionlab::draw
