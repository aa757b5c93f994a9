#include "draw/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>


namespace frictionlab::ui {

// Where `value` lies from `low` (0) to `high` (1). In halves: values near ±1.7e308 are finite,
// but their differences may not be.
double share(double value, double low, double high) { return (0.5 * value - 0.5 * low) / (0.5 * high - 0.5 * low); }

namespace {

// The multiples of `step` from `low` to `high`, at most `most` of them: a step lost in the
// rounding of large values must not loop for ever.
std::vector<double> multiples_of(double step, double low, double high, std::size_t most) {
  std::vector<double> ticks;
  for (double tick = std::ceil(low / step - 1e-9) * step; tick <= high + 1e-9 * step && ticks.size() < most; tick += step) {
    ticks.push_back(std::abs(tick) < 1e-12 * step ? 0.0 : tick);
  }
  return ticks;
}

}  // namespace

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

struct Axis {
  bool log = false;
  double low = 0.0, high = 1.0;  // in the axis' own space: log10 of the value on a log axis

  bool shows(double value) const { return std::isfinite(value) && (!log || value > 0.0); }
  double map(double value) const { return log ? std::log10(value) : value; }
  // 0 at low, 1 at high.
  double fraction(double value) const { return share(map(value), low, high); }
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

namespace {

// The axes of a chart before its data area is known: ranges, and a map's cell edges.
struct ChartAxes {
  Axis x, y;
  std::vector<std::pair<double, double>> x_edges, y_edges;
};

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

// One line of a legend: a colour swatch (a square under the chart; inside it, a line, a band
// or a dashed theory line) and its text.
struct Key {
  std::string name;
  ImU32 colour;
  enum class Look { line, band, theory } look;
  float dash = 0.0f, gap = 0.0f;  // a theory curve's pattern
};

std::vector<Key> keys_of(const Chart& chart) {
  std::vector<Key> keys;
  // A map's categories that no cell has are left out of the legend.
  for (std::size_t category = 0; category < chart.categories.size(); ++category) {
    const bool present = std::any_of(chart.cells.begin(), chart.cells.end(), [&](const ChartCell& cell) {
      return cell.category == static_cast<int>(category);
    });
    if (present) keys.push_back({chart.categories[category].first, chart.categories[category].second, Key::Look::band});
  }
  for (const auto& [name, colour] : chart.colour_keys) keys.push_back({name, colour, Key::Look::line});
  for (const ChartSeries& series : chart.series) {
    if (!series.name.empty()) keys.push_back({series.name, series.colour, Key::Look::line});
  }
  if (!chart.band_name.empty()) keys.push_back({chart.band_name, chart.band_colour, Key::Look::band});
  for (const ChartCurve& curve : chart.theory) keys.push_back({curve.name, curve.colour, Key::Look::theory, curve.dash, curve.gap});
  return keys;
}

float width_of(ImFont* font, const std::string& text) { return font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str()).x; }

// Where each key goes when the legend runs in rows from `left` to `right`, starting at `top`:
// a key that would cross `right` starts the next row.
std::vector<ImVec2> wrap_keys(const std::vector<Key>& keys, float left, float right, float top, float row_height,
                              ImFont* font, float s) {
  std::vector<ImVec2> at;
  float x = left, y = top;
  for (const Key& key : keys) {
    const float w = width_of(font, key.name) + 32.0f * s;
    if (x > left && x + w > right) {
      x = left;
      y += row_height;
    }
    at.push_back(ImVec2(x, y));
    x += w;
  }
  return at;
}

std::vector<Tick> ticks_every(const Axis& axis, int count) {
  if (axis.log) return ticks_of(axis);
  std::vector<Tick> ticks;
  const std::vector<double> values = axis_ticks(axis.low, axis.high, count);
  const double step = values.size() > 1 ? values[1] - values[0] : 1.0;
  for (const double value : values) ticks.push_back({value, tick_text(value, step)});
  return ticks;
}

}  // namespace

ImVec2 ChartLayout::to_screen(double x, double y) const {
  const double ax = log_x ? std::log10(x) : x, ay = log_y ? std::log10(y) : y;
  return ImVec2(low_left.x + static_cast<float>(share(ax, x_low, x_high)) * (high_right.x - low_left.x),
                low_left.y - static_cast<float>(share(ay, y_low, y_high)) * (low_left.y - high_right.y));
}

ChartLayout layout_chart(const Chart& chart, ImVec2 corner, ImVec2 size, const Fonts& fonts) {
  const float s = fonts.scale;
  ImFont* font = fonts.small;
  const float text = font->FontSize;
  ChartLayout layout;
  const ChartAxes axes = axes_of(chart);
  layout.log_x = axes.x.log, layout.log_y = axes.y.log;
  layout.x_low = axes.x.low, layout.x_high = axes.x.high, layout.y_low = axes.y.low, layout.y_high = axes.y.high;
  for (const Tick& tick : ticks_every(axes.y, chart.y_tick_count)) {
    layout.y_ticks.push_back(tick.value);
    layout.y_tick_labels.push_back(tick.label);
  }
  float label_width = 0.0f;
  for (const std::string& label : layout.y_tick_labels) label_width = std::max(label_width, width_of(font, label));
  const std::vector<Key> keys = keys_of(chart);
  if (chart.legend == Chart::Legend::only) return layout;

  const float line = text + 3.0f * s;
  if (chart.plain) {
    if (chart.steady) label_width = std::max(label_width, width_of(font, chart.tick_room));
    layout.low_left = ImVec2(corner.x + label_width + 10.0f * s, corner.y + size.y - 2.0f * text - 8.0f * s);
    layout.high_right = ImVec2(corner.x + size.x - 8.0f * s, corner.y + text + 10.0f * s);
    if (chart.steady) {
      // The y label heads the legend's column and the x label ends the x ticks' line: the data
      // has the two lines of text they took (a plot on a page of its own, made tall).
      layout.low_left.y = corner.y + size.y - text - 4.0f * s;  // the tick marks' 4 pt, then the labels
      layout.high_right.y = corner.y + 0.5f * text + 1.0f * s;  // room for half the top tick's label
    }
  } else {
    // The legend goes under the chart, in two columns, so it hides none of it.
    const std::size_t rows = chart.legend == Chart::Legend::under ? (keys.size() + 1) / 2 : 0;
    const float legend_height =
        line * static_cast<float>(rows + chart.notes.size()) + (rows == 0 ? 0.0f : 6.0f * s);
    const float top = corner.y + fonts.body->FontSize + text + 16.0f * s;
    layout.low_left = ImVec2(corner.x + label_width + 16.0f * s, corner.y + size.y - 2.0f * text - 14.0f * s - legend_height);
    // Room on the right for the labels beside the last points (a step rate, say).
    const bool labelled = std::any_of(chart.series.begin(), chart.series.end(), [](const ChartSeries& series) { return !series.labels.empty(); });
    layout.high_right = ImVec2(corner.x + size.x - (labelled ? 60.0f : 10.0f) * s, top);
  }
  const float width = layout.high_right.x - layout.low_left.x, height = layout.low_left.y - layout.high_right.y;
  layout.drawable = width >= 20.0f && height >= 20.0f;
  if (!layout.drawable) return layout;
  // As many x ticks as the data area's width holds, unless the chart says how many.
  const auto set_x_ticks = [&](float data_width) {
    const int count = chart.x_tick_count > 0 ? chart.x_tick_count : std::max(2, static_cast<int>(data_width / (70.0f * s)));
    layout.x_ticks.clear(), layout.x_tick_labels.clear();
    for (const Tick& tick : ticks_every(axes.x, count)) {
      layout.x_ticks.push_back(tick.value);
      layout.x_tick_labels.push_back(tick.label);
    }
  };
  set_x_ticks(width);

  // The points where they land; at most about two a pixel, the rest would be drawn over each other.
  const auto place = [&] {
    const float w = layout.high_right.x - layout.low_left.x;
    layout.points.clear();
    layout.series_points.assign(chart.series.size(), {});
    layout.series_indices.assign(chart.series.size(), {});
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      const auto& points = chart.series[k].points;
      const std::size_t stride = std::max<std::size_t>(1, points.size() / static_cast<std::size_t>(std::max(1.0f, 2.0f * w)));
      const auto add = [&](std::size_t i) {
        const auto [x, y] = points[i];
        if (!axes.x.shows(x) || !axes.y.shows(y)) return;
        layout.series_points[k].push_back(layout.to_screen(x, y));
        layout.series_indices[k].push_back(i);
        layout.points.push_back(layout.series_points[k].back());
      };
      for (std::size_t i = 0; i < points.size(); i += stride) add(i);
      if (!points.empty() && (points.size() - 1) % stride != 0) add(points.size() - 1);  // the latest point always
    }
    layout.theory.clear();
    for (const ChartCurve& curve : chart.theory) {
      layout.theory.emplace_back();
      for (const auto& piece : curve.pieces) {
        layout.theory.back().emplace_back();
        for (const auto& [x, y] : piece) layout.theory.back().back().push_back(layout.to_screen(x, y));
      }
    }
  };
  place();

  if (chart.plain && chart.steady && chart.legend == Chart::Legend::inside) {
    // A line above the data, the y label first and the keys after it in rows as wide as the
    // chart (a column beside the data took up to 40 % of its width). The rows are laid out for
    // every key that may ever be in them (`legend_room`: theory curves not shown before the
    // reveal), each in its place from the start, the theory's last as keys_of gives them: what
    // the run or the reveal adds moves neither a key nor the data.
    std::vector<std::string> names;
    for (const Key& key : keys) names.push_back(key.name);
    for (const std::string& name : chart.legend_room) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    const float left = corner.x + 2.0f * s, right = corner.x + size.x - 8.0f * s;
    // A key longer than a row (pulley's laws written out) wraps in it.
    layout.legend_wrap = right - left - 32.0f * s;
    const float top = corner.y;
    float x = left + (chart.y_label.empty() ? 0.0f : width_of(font, chart.y_label) + 24.0f * s), y = top, row = text;
    std::vector<ImVec2> at;
    for (const std::string& name : names) {
      const ImVec2 wrapped = font->CalcTextSizeA(text, INFINITY, layout.legend_wrap, name.c_str());
      const float w = wrapped.x + 32.0f * s;
      if (x > left && x + w > right + 12.0f * s) {
        x = left;
        y += row + 1.0f * s;
        row = text;
      }
      at.push_back(ImVec2(x, y));
      row = std::max(row, wrapped.y);
      x += w;
    }
    if (!names.empty() || !chart.y_label.empty()) {
      layout.y_label_at = ImVec2(left, top);
      layout.legend_outside = true;
      layout.legend_at.assign(at.begin(), at.begin() + static_cast<long>(keys.size()));
      // The data under the rows, with room for half the top tick's label.
      layout.high_right.y = y + row + 1.0f * s + 0.5f * text;
      if (layout.low_left.y - layout.high_right.y < 20.0f) {
        layout.drawable = false;
        return layout;
      }
      place();
      layout.legend_min = ImVec2(INFINITY, INFINITY), layout.legend_max = ImVec2(-INFINITY, -INFINITY);
      for (std::size_t i = 0; i < keys.size(); ++i) {
        const ImVec2 key_at = layout.legend_at[i];
        layout.legend_min = ImVec2(std::min(layout.legend_min.x, key_at.x), std::min(layout.legend_min.y, key_at.y));
        const ImVec2 wrapped = font->CalcTextSizeA(text, INFINITY, layout.legend_wrap, keys[i].name.c_str());
        layout.legend_max = ImVec2(std::max(layout.legend_max.x, key_at.x + wrapped.x + 22.0f * s),
                                   std::max(layout.legend_max.y, key_at.y + wrapped.y));
      }
    }
  } else if (!chart.plain && chart.legend != Chart::Legend::inside) {
    const std::size_t shown = chart.legend == Chart::Legend::under ? keys.size() : 0;
    layout.legend_min = ImVec2(corner.x + 12.0f * s, layout.low_left.y + 2.0f * text + 14.0f * s);
    layout.legend_max = ImVec2(corner.x + size.x - 12.0f * s, layout.legend_min.y + line * static_cast<float>((shown + 1) / 2));
  } else if (chart.legend == Chart::Legend::inside && !keys.empty()) {
    float legend_width = 0.0f, row_width = 0.0f;
    for (const Key& key : keys) {
      legend_width = std::max(legend_width, width_of(font, key.name));
      row_width += width_of(font, key.name) + 32.0f * s;
    }
    const ImVec2 legend_size(legend_width + 24.0f * s, static_cast<float>(keys.size()) * (text + 2.0f * s));
    std::vector<ImVec2> avoid = layout.points;
    for (const auto& curve : layout.theory) {
      for (const auto& piece : curve) avoid.insert(avoid.end(), piece.begin(), piece.end());
    }
    const LegendPlace inside = legend_corner(ImVec2(layout.low_left.x, layout.high_right.y), ImVec2(layout.high_right.x, layout.low_left.y),
                                             legend_size, 5.0f * s, avoid, 3.0f * s);
    // In the chosen corner, a key a line.
    const auto in_corner = [&] {
      layout.legend_min = inside.min, layout.legend_max = inside.max;
      float y = inside.min.y;
      for (std::size_t i = 0; i < keys.size(); ++i, y += text + 2.0f * s) layout.legend_at.push_back(ImVec2(inside.min.x, y));
    };
    // A corner clear of the data holds the legend only if the legend fits in the data area:
    // a tall one would run out over the axis and its labels.
    const bool fits = legend_size.y + 10.0f * s <= layout.low_left.y - layout.high_right.y &&
                      legend_size.x + 10.0f * s <= layout.high_right.x - layout.low_left.x;
    if (inside.clear && fits) {
      in_corner();
    } else {
      // No corner is free of the data: the legend goes above the data area, in one row beside
      // the y label when it fits there, else in as many rows as it needs under the label,
      // the data area giving up their height.
      layout.legend_outside = true;
      const float row_height = text + 4.0f * s;
      const float room = layout.high_right.x - corner.x - width_of(font, chart.y_label) - 12.0f * s;
      if (row_width <= room) {
        float x = layout.high_right.x - row_width;
        for (const Key& key : keys) {
          layout.legend_at.push_back(ImVec2(x, layout.high_right.y - text - 6.0f * s));
          x += width_of(font, key.name) + 32.0f * s;
        }
      } else if (const std::vector<ImVec2> rows = wrap_keys(keys, layout.low_left.x, layout.high_right.x,
                                                            layout.high_right.y - 4.0f * s, row_height, font, s);
                 rows.back().y - rows.front().y + row_height > 0.45f * (layout.low_left.y - layout.high_right.y)) {
        // Rows above the data would leave it little height (large text in a small plot, as on
        // a projector). Beside it, on the right, a key a line, if the data keeps at least half
        // the width; else the rows above all the same while the data keeps 30 px of height
        // (a short plot beats one with its data under the keys); else, rather than the plot
        // losing its data, in the corner it covers least of.
        const float column = legend_size.x + 8.0f * s;
        const float data_width = layout.high_right.x - layout.low_left.x;
        // A legend too tall for one column beside the data, in two or more: each column's
        // width, or none when the data would keep less than 30 % of the width.
        const auto beside_columns = [&](float full_width, float data_height) {
          const float key_height = text + 2.0f * s;
          for (std::size_t columns = 2; columns <= keys.size(); ++columns) {
            const std::size_t per_column = (keys.size() + columns - 1) / columns;
            if (static_cast<float>(per_column) * key_height > data_height) continue;
            std::vector<float> widths((keys.size() + per_column - 1) / per_column, 0.0f);
            float total = 0.0f;
            for (std::size_t i = 0; i < keys.size(); ++i) {
              widths[i / per_column] = std::max(widths[i / per_column], width_of(font, keys[i].name) + 24.0f * s);
            }
            for (const float w : widths) total += w + 8.0f * s;
            if (full_width - total >= 0.3f * full_width) return widths;
            break;  // more columns are wider still
          }
          return std::vector<float>();
        };
        const float rows_height = rows.back().y - rows.front().y + row_height + 4.0f * s;
        if (data_width - column >= 0.5f * data_width && legend_size.y <= layout.low_left.y - layout.high_right.y) {
          layout.high_right.x -= column;
          float y = layout.high_right.y;
          for (std::size_t i = 0; i < keys.size(); ++i, y += text + 2.0f * s) {
            layout.legend_at.push_back(ImVec2(layout.high_right.x + 8.0f * s, y));
          }
          set_x_ticks(data_width - column);  // fewer for the narrower data
          place();
        } else if (layout.low_left.y - (layout.high_right.y + rows_height) >= 30.0f * s) {
          layout.legend_at = rows;
          layout.high_right.y = rows.back().y + row_height + 4.0f * s;
          place();
        } else if (const std::vector<float> widths = beside_columns(data_width, layout.low_left.y - layout.high_right.y);
                   !widths.empty()) {
          // Beside the data in columns, as few as its height allows, keys in order down each.
          const std::size_t per_column = (keys.size() + widths.size() - 1) / widths.size();
          float total = 0.0f;
          for (const float w : widths) total += w + 8.0f * s;
          layout.high_right.x -= total;
          float x = layout.high_right.x + 8.0f * s;
          for (std::size_t i = 0; i < keys.size(); ++i) {
            if (i > 0 && i % per_column == 0) x += widths[i / per_column - 1] + 8.0f * s;
            layout.legend_at.push_back(ImVec2(x, layout.high_right.y + static_cast<float>(i % per_column) * (text + 2.0f * s)));
          }
          set_x_ticks(data_width - total);
          place();
        } else {
          layout.legend_outside = false;
          layout.legend_on_data = true;
          in_corner();
        }
      } else {
        layout.legend_at = rows;
        layout.high_right.y = rows.back().y + row_height + 4.0f * s;
        if (layout.low_left.y - layout.high_right.y < 20.0f) {
          layout.drawable = false;
          return layout;
        }
        place();
      }
      layout.legend_min = ImVec2(INFINITY, INFINITY), layout.legend_max = ImVec2(-INFINITY, -INFINITY);
      for (std::size_t i = 0; i < keys.size(); ++i) {
        const ImVec2 at = layout.legend_at[i];
        layout.legend_min = ImVec2(std::min(layout.legend_min.x, at.x), std::min(layout.legend_min.y, at.y));
        layout.legend_max = ImVec2(std::max(layout.legend_max.x, at.x + width_of(font, keys[i].name) + 22.0f * s),
                                   std::max(layout.legend_max.y, at.y + text));
      }
    }
  }
  const float data_height = layout.low_left.y - layout.high_right.y;
  const auto spacing = [&](const std::vector<double>& ticks) {
    return ticks.size() < 2 ? INFINITY
                            : static_cast<float>((0.5 * ticks[1] - 0.5 * ticks[0]) / (0.5 * layout.y_high - 0.5 * layout.y_low)) *
                                  data_height;
  };
  // The finest round step whose ticks keep the spacing asked for: a tall plot's levels read off
  // its axis (1 N apart where 2 or 5 N were, at push's defaults on a projector).
  if (chart.y_tick_spacing > 0.0f && !axes.y.log) {
    for (int count = 2; count <= 40; ++count) {
      const std::vector<Tick> finer = ticks_every(axes.y, count);
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
  if (!axes.y.log && spacing(layout.y_ticks) < 1.35f * text) {
    for (int count = chart.y_tick_count - 1; count >= 1; --count) {
      const std::vector<Tick> fewer = ticks_every(axes.y, count);
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
  // Each level's text at the data's right end, above its line, or under it when the line is
  // near the top; none for a level off the axis.
  for (std::size_t i = 0; i < chart.levels.size(); ++i) {
    const ChartLevel& level = chart.levels[i];
    if (!axes.y.shows(level.y)) continue;
    const float y = layout.to_screen(layout.log_x ? std::pow(10.0, layout.x_low) : layout.x_low, level.y).y;
    if (y < layout.high_right.y - 0.5f || y > layout.low_left.y + 0.5f) continue;
    const float w = width_of(font, level.text);
    // At either end of the line, above it or under it: where it covers the fewest points and
    // the fewest texts placed before it (the first of equals: right, above), in the data area.
    ImVec4 best;
    std::size_t fewest = static_cast<std::size_t>(-1);
    for (const float left : {layout.high_right.x - w - 4.0f * s, layout.low_left.x + 4.0f * s}) {
      for (const float top : {y - text - 2.0f * s, y + 2.0f * s}) {
        if (top < layout.high_right.y || top + text > layout.low_left.y) continue;
        const ImVec4 box(left - 3.0f * s, top - 1.0f, left + w + 3.0f * s, top + text + 1.0f);
        std::size_t met = 0;
        for (const ImVec2& p : layout.points) met += p.x >= box.x && p.x <= box.z && p.y >= box.y && p.y <= box.w;
        for (const auto& curve : layout.theory) {
          for (const auto& piece : curve) {
            for (const ImVec2& p : piece) met += p.x >= box.x && p.x <= box.z && p.y >= box.y && p.y <= box.w;
          }
        }
        for (const ChartLayout::Level& other : layout.levels) {
          met += 1000 * (other.at.x < box.z && other.at.z > box.x && other.at.y < box.w && other.at.w > box.y);
        }
        if (met < fewest) fewest = met, best = ImVec4(left, top, left + w, top + text);
      }
    }
    if (fewest == static_cast<std::size_t>(-1)) continue;  // a data area shorter than a line
    layout.levels.push_back({i, level.text, best, y});
  }
  layout.active = chart.active_theory;
  if (layout.active == Chart::nearest) {
    layout.active = -1;
    if (!layout.series_points.empty() && !layout.series_points.front().empty()) {
      layout.active = nearest_curve(layout.theory, layout.series_points.front().back());
    }
  }
  return layout;
}

ChartLayout draw_chart(ImDrawList* draw, ImVec2 corner, ImVec2 size, const Chart& chart, const Theme& theme,
                       const Fonts& fonts) {
  const float s = fonts.scale;
  ImFont* font = fonts.small;
  const float text = font->FontSize;
  if (!chart.plain) {
    draw->AddRectFilled(corner, ImVec2(corner.x + size.x, corner.y + size.y), theme.panel);
    draw->AddText(fonts.body, fonts.body->FontSize, ImVec2(corner.x + 8.0f * s, corner.y + 4.0f * s), theme.text,
                  chart.title.c_str());
  }
  const std::vector<Key> keys = keys_of(chart);
  const float line = text + 3.0f * s;
  if (chart.legend == Chart::Legend::only) {
    float y = corner.y + fonts.body->FontSize + text + 16.0f * s;
    for (const Key& key : keys) {
      draw->AddRectFilled(ImVec2(corner.x + 12.0f * s, y + 2.0f * s), ImVec2(corner.x + 24.0f * s, y + text - 2.0f * s), key.colour);
      draw->AddText(font, text, ImVec2(corner.x + 30.0f * s, y), theme.text, key.name.c_str());
      y += line;
    }
    for (const std::string& note : chart.notes) {
      draw->AddText(font, text, ImVec2(corner.x + 12.0f * s, y + 6.0f * s), theme.faint_text, note.c_str());
      y += line;
    }
    return {};
  }
  ChartLayout layout = layout_chart(chart, corner, size, fonts);
  if (!layout.drawable) return layout;
  const ImVec2 low_left = layout.low_left, high_right = layout.high_right;
  const auto line_of = [&](ChartLayout::Line::Kind kind, ImVec2 from, ImVec2 to, ImU32 colour, float thickness) {
    draw->AddLine(from, to, colour, thickness);
    layout.lines.push_back({kind, from, to, colour});
  };
  using Kind = ChartLayout::Line::Kind;
  const float width = high_right.x - low_left.x;
  const ChartAxes axes = axes_of(chart);
  const auto at_axis_value = [&](double x, double y) {  // values already in axis space
    return ImVec2(low_left.x + static_cast<float>(share(x, layout.x_low, layout.x_high)) * width,
                  low_left.y - static_cast<float>(share(y, layout.y_low, layout.y_high)) * (low_left.y - high_right.y));
  };

  draw->PushClipRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x + 1.0f, low_left.y + 1.0f), true);
  for (const ChartCell& cell : chart.cells) {
    if (!axes.x.shows(cell.x) || !axes.y.shows(cell.y) || cell.category < 0 ||
        cell.category >= static_cast<int>(chart.categories.size())) {
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
    draw->AddRectFilled(at_axis_value(x0, y1), at_axis_value(x1, y0), chart.categories[static_cast<std::size_t>(cell.category)].second);
  }
  // The zero lines of a plain chart are darker: forces are read against zero.
  for (const double tick : layout.x_ticks) {
    const float x = at_axis_value(tick, layout.y_low).x;
    const bool zero = chart.plain && tick == 0.0;
    line_of(zero ? Kind::axis : Kind::grid, ImVec2(x, high_right.y), ImVec2(x, low_left.y), zero ? theme.axis : theme.grid, 1.0f);
  }
  for (const double tick : layout.y_ticks) {
    const float y = at_axis_value(layout.x_low, tick).y;
    const bool zero = chart.plain && tick == 0.0;
    line_of(zero ? Kind::axis : Kind::grid, ImVec2(low_left.x, y), ImVec2(high_right.x, y), zero ? theme.axis : theme.grid, 1.0f);
  }
  for (const auto& [x0, x1] : chart.bands) {
    const float left = layout.to_screen(x0, 1.0).x, right = layout.to_screen(x1, 1.0).x;
    draw->AddRectFilled(ImVec2(left, high_right.y), ImVec2(std::max(right, left + 1.0f), low_left.y), chart.band_colour);
  }
  // The theory under the measurements, each curve in its own pattern: the branch that applies
  // now bold.
  for (std::size_t c = 0; c < layout.theory.size(); ++c) {
    const ChartCurve& curve = chart.theory[c];
    const float thickness = (static_cast<int>(c) == layout.active ? 3.5f : 1.8f) * s;
    for (const std::vector<ImVec2>& piece : layout.theory[c]) draw_dashed(draw, piece, curve.colour, thickness, curve.dash * s, curve.gap * s);
  }
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& series = chart.series[k];
    const std::vector<ImVec2>& points = layout.series_points[k];
    const std::vector<std::size_t>& indices = layout.series_indices[k];
    const std::vector<ImU32>* colours = k < chart.segment_colours.size() && !chart.segment_colours[k].empty() ? &chart.segment_colours[k] : nullptr;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (indices[i] < series.labels.size()) {
        draw->AddText(font, 0.85f * text, ImVec2(points[i].x + 4.0f * s, points[i].y - 0.9f * text),
                      readable_ink(series.colour, theme.panel), series.labels[indices[i]].c_str());
      }
    }
    if (series.line && colours != nullptr) {
      for (std::size_t i = 1; i < points.size(); ++i) {
        const ImU32 colour = indices[i] < colours->size() ? (*colours)[indices[i]] : series.colour;
        draw->AddLine(points[i - 1], points[i], colour, 2.5f * s);
      }
    } else if (series.line && points.size() > 1) {
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
    if (chart.mark_now && !points.empty()) draw->AddCircleFilled(points.back(), 4.0f * s, chart.now_colour, 12);
  }
  if (chart.mark_now && std::isfinite(chart.now_x)) {
    const float x = layout.to_screen(chart.now_x, 1.0).x;
    draw->AddLine(ImVec2(x, high_right.y), ImVec2(x, low_left.y), chart.now_colour, 1.5f * s);
  }
  // The levels over the series: the values the class reads off the plot.
  for (const ChartLayout::Level& placed : layout.levels) {
    const ChartLevel& level = chart.levels[placed.index];
    // Solid: every dash pattern is a theory curve's (a teacher's trial read push's dashed
    // −μs·N level for its dashed "sticking: f = −F" key, both grey). Thin and labelled, it is no
    // series either (those are 2 points and more, in the series' colours).
    draw->AddLine(ImVec2(low_left.x, placed.y), ImVec2(high_right.x, placed.y), level.colour, 1.5f * s);
    draw->AddRectFilled(ImVec2(placed.at.x - 2.0f * s, placed.at.y - 1.0f), ImVec2(placed.at.z + 2.0f * s, placed.at.w + 1.0f),
                        (theme.panel & 0x00FFFFFFu) | (220u << IM_COL32_A_SHIFT));
    draw->AddText(font, text, ImVec2(placed.at.x, placed.at.y), readable_ink(level.colour, theme.panel), level.text.c_str());
  }
  if (!chart.message.empty()) {
    draw->AddText(font, text, ImVec2(low_left.x + 4.0f * s, high_right.y + 4.0f * s), theme.bad, chart.message.c_str(), nullptr,
                  width - 8.0f * s);
  }
  draw->PopClipRect();

  // Axes, tick labels and titles.
  draw->AddRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x, low_left.y), theme.axis, 0.0f, 0, 1.0f);
  for (const auto& [from, to] : {std::pair{low_left, ImVec2(high_right.x, low_left.y)}, std::pair{low_left, ImVec2(low_left.x, high_right.y)},
                                 std::pair{high_right, ImVec2(high_right.x, low_left.y)}, std::pair{high_right, ImVec2(low_left.x, high_right.y)}}) {
    layout.lines.push_back({Kind::axis, from, to, theme.axis});
  }
  const float gap = (chart.plain ? 5.0f : 4.0f) * s;
  if (chart.steady) {
    // Tick marks outside the data in the axes' colour, between the edge and the tick labels:
    // on a projector the faint grid (1.3:1 on the panel) fades, and the ticks are what the
    // levels are read against (WCAG 2.1 1.4.11 asks 3:1 of them).
    const float length = 4.0f * s, thickness = 1.5f * s;
    for (const double tick : layout.y_ticks) {
      const float y = at_axis_value(layout.x_low, tick).y;
      line_of(Kind::tick, ImVec2(low_left.x - length, y), ImVec2(low_left.x, y), theme.axis, thickness);
    }
    for (const double tick : layout.x_ticks) {
      const float x = at_axis_value(tick, layout.y_low).x;
      line_of(Kind::tick, ImVec2(x, low_left.y), ImVec2(x, low_left.y + length), theme.axis, thickness);
    }
  }
  const float x_labels_below = (chart.steady ? 4.0f : 3.0f) * s;  // under the tick marks
  // A steady chart's x label at the right end of the ticks' line, the ticks it would cover left out.
  const float x_label_left = high_right.x - width_of(font, chart.x_label);
  for (std::size_t i = 0; i < layout.x_ticks.size(); ++i) {
    const float x = at_axis_value(layout.x_ticks[i], layout.y_low).x;
    const std::string& label = layout.x_tick_labels[i];
    if (chart.steady && !chart.x_label.empty() && x + 0.5f * width_of(font, label) + 8.0f * s > x_label_left) continue;
    draw->AddText(font, text, ImVec2(x - 0.5f * width_of(font, label), low_left.y + x_labels_below), theme.text, label.c_str());
  }
  for (std::size_t i = 0; i < layout.y_ticks.size(); ++i) {
    const float y = at_axis_value(layout.x_low, layout.y_ticks[i]).y;
    const std::string& label = layout.y_tick_labels[i];
    draw->AddText(font, text, ImVec2(low_left.x - width_of(font, label) - gap, y - 0.5f * text), theme.text, label.c_str());
  }
  const ImVec2 x_label_at = chart.steady ? ImVec2(x_label_left, low_left.y + x_labels_below)
                                         : ImVec2(low_left.x + 0.5f * (width - width_of(font, chart.x_label)),
                                                  low_left.y + text + (chart.plain ? 5.0f : 6.0f) * s);
  draw->AddText(font, text, x_label_at, chart.plain ? theme.faint_text : theme.text, chart.x_label.c_str());
  const ImVec2 y_label_at = chart.steady && std::isfinite(layout.y_label_at.x) ? layout.y_label_at
                            : chart.plain ? ImVec2(corner.x + 2.0f * s, corner.y + 2.0f * s)
                                          : ImVec2(corner.x + 8.0f * s, high_right.y - text - 4.0f * s);
  draw->AddText(font, text, y_label_at, theme.faint_text, chart.y_label.c_str());

  if (chart.legend == Chart::Legend::under || (chart.legend == Chart::Legend::none && !chart.plain)) {
    // Categories, then series, in two columns; then the notes.
    const float column = 0.5f * (size.x - 24.0f * s);
    const std::size_t shown = chart.legend == Chart::Legend::under ? keys.size() : 0;
    for (std::size_t i = 0; i < shown; ++i) {
      const ImVec2 at(layout.legend_min.x + column * static_cast<float>(i % 2), layout.legend_min.y + line * static_cast<float>(i / 2));
      draw->AddRectFilled(ImVec2(at.x, at.y + 2.0f * s), ImVec2(at.x + 12.0f * s, at.y + text - 2.0f * s), keys[i].colour);
      draw->AddText(font, text, ImVec2(at.x + 18.0f * s, at.y), theme.text, keys[i].name.c_str());
    }
    float y = layout.legend_min.y + line * static_cast<float>((shown + 1) / 2);
    for (const std::string& note : chart.notes) {
      draw->AddText(font, text, ImVec2(layout.legend_min.x, y), theme.faint_text, note.c_str());
      y += line;
    }
  } else if (chart.legend == Chart::Legend::inside) {
    for (std::size_t i = 0; i < keys.size() && i < layout.legend_at.size(); ++i) {
      const Key& key = keys[i];
      const ImVec2 at = layout.legend_at[i];
      const ImVec2 wrapped = font->CalcTextSizeA(text, INFINITY, layout.legend_wrap, key.name.c_str());
      const float w = wrapped.x;
      draw->AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + 22.0f * s + w + 2, at.y + wrapped.y + 1),
                          (theme.panel & 0x00FFFFFFu) | (200u << IM_COL32_A_SHIFT));
      const float middle = at.y + 0.5f * text;
      if (key.look == Key::Look::band) {
        draw->AddRectFilled(ImVec2(at.x, at.y + 2), ImVec2(at.x + 16.0f * s, at.y + text - 2), key.colour);
      } else if (key.look == Key::Look::theory) {
        draw_dashed(draw, {ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle)}, key.colour, 2.0f * s, key.dash * s, key.gap * s);
      } else {
        draw->AddLine(ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle), key.colour, 3.0f * s);
      }
      draw->AddText(font, text, ImVec2(at.x + 20.0f * s, at.y), theme.text, key.name.c_str(), nullptr, layout.legend_wrap);
    }
  }
  return layout;
}

bool legend_has_room(const Chart& chart, ImVec2 size, const Fonts& fonts) {
  if (chart.legend != Chart::Legend::inside || chart.log_x || chart.log_y) return true;
  const ChartLayout plain = layout_chart(chart, ImVec2(0.0f, 0.0f), size, fonts);
  if (!plain.drawable) return false;
  // Data everywhere: a nameless series on a grid over the axes' whole range, so that no corner
  // is free. The axes keep their range (fixed by the chart, or its data's with a margin).
  Chart filled = chart;
  filled.fixed_x = filled.fixed_y = true;
  filled.x_low = plain.x_low, filled.x_high = plain.x_high, filled.y_low = plain.y_low, filled.y_high = plain.y_high;
  ChartSeries everywhere;
  everywhere.line = false;
  constexpr int grid = 24;
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; j <= grid; ++j) {
      everywhere.points.push_back({plain.x_low + (plain.x_high - plain.x_low) * i / grid,
                                   plain.y_low + (plain.y_high - plain.y_low) * j / grid});
    }
  }
  filled.series.push_back(std::move(everywhere));
  const ChartLayout layout = layout_chart(filled, ImVec2(0.0f, 0.0f), size, fonts);
  return layout.drawable && !layout.legend_on_data;
}

LegendPlace legend_corner(ImVec2 area_min, ImVec2 area_max, ImVec2 legend_size, float inset,
                          const std::vector<ImVec2>& points, float radius) {
  const ImVec2 corners[] = {{area_min.x + inset, area_min.y + inset},
                            {area_max.x - inset - legend_size.x, area_min.y + inset},
                            {area_min.x + inset, area_max.y - inset - legend_size.y},
                            {area_max.x - inset - legend_size.x, area_max.y - inset - legend_size.y}};
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


}  // namespace frictionlab::ui
