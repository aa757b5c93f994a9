#include "ui/plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frictionlab::ui {

std::vector<double> axis_ticks(double low, double high, int count) {
  std::vector<double> ticks;
  if (!(high > low) || count < 1) return ticks;
  const double rough = (high - low) / count;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double fraction = rough / power;
  const double step = (fraction < 1.5 ? 1.0 : fraction < 3.5 ? 2.0 : fraction < 7.5 ? 5.0 : 10.0) * power;
  for (double tick = std::ceil(low / step - 1e-9) * step; tick <= high + 1e-9 * step; tick += step) {
    ticks.push_back(std::abs(tick) < 1e-12 * step ? 0.0 : tick);
  }
  return ticks;
}

std::string tick_text(double value, double step) {
  char text[32];
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(text, sizeof text, "%.*f", std::min(decimals, 6), value);
  std::string shown = text;
  if (!shown.empty() && shown[0] == '-') shown.replace(0, 1, "\u2212");
  return shown;
}

namespace {

struct Range {
  double low = 0.0, high = 1.0;
};

// Data range with the zero line in it (forces are read against zero) and a margin.
Range range_of(const std::vector<const std::vector<double>*>& series, std::size_t count, bool include_zero) {
  if (count == 0) return {};  // nothing recorded yet: 0 to 1
  double low = include_zero ? 0.0 : 1e300, high = include_zero ? 0.0 : -1e300;
  for (const auto* values : series) {
    for (std::size_t i = 0; i < count && i < values->size(); ++i) {
      if (!std::isfinite((*values)[i])) continue;
      low = std::min(low, (*values)[i]);
      high = std::max(high, (*values)[i]);
    }
  }
  if (low > high) return {};
  // Rounding noise (a resting block's speed of 1e-9 m/s) is not drawn as a signal: the axis
  // spans at least a thousandth of a unit, or a millionth of the values' size.
  const double least = std::max(1e-3, 1e-6 * std::max(std::abs(low), std::abs(high)));
  if (high - low < least) {
    const double middle = 0.5 * (low + high);
    low = std::min(low, middle - 0.5 * least);
    high = std::max(high, middle + 0.5 * least);
    if (include_zero && low < 0.0 && middle >= 0.0 && std::abs(middle) < least) low = std::min(low, 0.0);
  }
  const double margin = 0.06 * (high - low);
  return {low < 0.0 || !include_zero ? low - margin : low, high + margin};
}


std::string axis_title(const lessons::Lesson& lesson, const std::string& quantity) {
  if (quantity == "time") return "time (s)";
  const std::string& unit = lesson.probe_unit(quantity);
  return unit.empty() ? quantity : quantity + " (" + unit + ")";
}

}  // namespace

void draw_plot(ImDrawList* draw, const lessons::Lesson& lesson, const lessons::Plot& plot, double time_span,
               ImVec2 corner, ImVec2 size, const Theme& theme, const Fonts& fonts) {
  const Scene& scene = lesson.scene();
  ImFont* font = fonts.small;
  const float s = fonts.scale, text_height = font->FontSize;
  const bool over_time = plot.x == "time";
  const std::vector<double>& times = scene.times();
  const std::vector<double>& xs = over_time ? times : scene.probe(plot.x).history;
  std::vector<const std::vector<double>*> ys;
  for (const std::string& name : plot.y) ys.push_back(&scene.probe(name).history);
  const std::size_t count = xs.size();

  // Axes' ranges and the plotting rectangle inside the tick labels.
  const Range x_range = over_time ? Range{0.0, std::max(time_span, count ? times.back() : 0.0)} : range_of({&xs}, count, true);
  const Range y_range = range_of(ys, count, true);
  const std::vector<double> y_ticks = axis_ticks(y_range.low, y_range.high, 4);
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  float label_width = 0.0f;
  for (double tick : y_ticks) {
    label_width = std::max(label_width, font->CalcTextSizeA(text_height, 1e6f, 0.0f, tick_text(tick, y_step).c_str()).x);
  }
  const ImVec2 low_left(corner.x + label_width + 10.0f * s, corner.y + size.y - 2.0f * text_height - 8.0f * s);
  const ImVec2 high_right(corner.x + size.x - 8.0f * s, corner.y + text_height + 10.0f * s);
  const float width = high_right.x - low_left.x, height = low_left.y - high_right.y;
  if (width < 20.0f || height < 20.0f) return;
  const auto to_screen = [&](double x, double y) {
    return ImVec2(low_left.x + static_cast<float>((x - x_range.low) / (x_range.high - x_range.low)) * width,
                  low_left.y - static_cast<float>((y - y_range.low) / (y_range.high - y_range.low)) * height);
  };

  // Grid and tick labels.
  for (double tick : y_ticks) {
    const float y = to_screen(x_range.low, tick).y;
    draw->AddLine(ImVec2(low_left.x, y), ImVec2(high_right.x, y), tick == 0.0 ? theme.axis : theme.grid, 1.0f);
    const std::string text = tick_text(tick, y_step);
    const float w = font->CalcTextSizeA(text_height, 1e6f, 0.0f, text.c_str()).x;
    draw->AddText(font, text_height, ImVec2(low_left.x - w - 5.0f * s, y - 0.5f * text_height), theme.text, text.c_str());
  }
  const std::vector<double> x_ticks = axis_ticks(x_range.low, x_range.high, std::max(2, static_cast<int>(width / (70.0f * s))));
  const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
  for (double tick : x_ticks) {
    const float x = to_screen(tick, y_range.low).x;
    draw->AddLine(ImVec2(x, low_left.y), ImVec2(x, high_right.y), tick == 0.0 ? theme.axis : theme.grid, 1.0f);
    const std::string text = tick_text(tick, x_step);
    const float w = font->CalcTextSizeA(text_height, 1e6f, 0.0f, text.c_str()).x;
    draw->AddText(font, text_height, ImVec2(x - 0.5f * w, low_left.y + 3.0f * s), theme.text, text.c_str());
  }
  draw->AddRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x, low_left.y), theme.axis);
  const std::string x_title = axis_title(lesson, plot.x);
  const float x_title_width = font->CalcTextSizeA(text_height, 1e6f, 0.0f, x_title.c_str()).x;
  draw->AddText(font, text_height, ImVec2(low_left.x + 0.5f * (width - x_title_width), low_left.y + text_height + 5.0f * s),
                theme.faint_text, x_title.c_str());
  std::string y_title;
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  bool one_unit = true;
  for (const std::string& name : plot.y) one_unit = one_unit && lesson.probe_unit(name) == y_unit;
  y_title = plot.y.size() == 1 ? axis_title(lesson, plot.y.front()) : one_unit && !y_unit.empty() ? "(" + y_unit + ")" : "";
  draw->AddText(font, text_height, ImVec2(corner.x + 2.0f * s, corner.y + 2.0f * s), theme.faint_text, y_title.c_str());

  draw->PushClipRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x + 1, low_left.y + 1), true);
  const std::vector<unsigned char>& slipping = scene.slipping();
  // At most about two points a pixel: the rest would be drawn over each other.
  const std::size_t stride = std::max<std::size_t>(1, count / static_cast<std::size_t>(2.0f * width));
  const bool regimes = !over_time && plot.y.size() == 1;
  if (over_time) {
    // The slip regime shaded behind the curves.
    std::size_t i = 0;
    while (i < count && i < slipping.size()) {
      if (!slipping[i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < count && j + 1 < slipping.size() && slipping[j + 1]) ++j;
      const float x0 = to_screen(i > 0 ? times[i - 1] : 0.0, 0.0).x, x1 = to_screen(times[j], 0.0).x;
      draw->AddRectFilled(ImVec2(x0, high_right.y), ImVec2(std::max(x1, x0 + 1.0f), low_left.y), theme.slip_band);
      i = j + 1;
    }
  }
  for (std::size_t k = 0; k < ys.size(); ++k) {
    const std::vector<double>& values = *ys[k];
    const ImU32 colour = theme.series[k % 4];
    if (regimes) {
      for (std::size_t i = stride; i < count; i += stride) {
        const bool slip = i < slipping.size() && slipping[i];
        draw->AddLine(to_screen(xs[i - stride], values[i - stride]), to_screen(xs[i], values[i]),
                      slip ? theme.slipping : theme.sticking, 2.5f * s);
      }
    } else {
      std::vector<ImVec2> points;
      points.reserve(count / stride + 2);
      for (std::size_t i = 0; i < count; i += stride) points.push_back(to_screen(xs[i], values[i]));
      if (count > 0 && (count - 1) % stride != 0) points.push_back(to_screen(xs[count - 1], values[count - 1]));
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, 2.0f * s);
    }
    if (count > 0) draw->AddCircleFilled(to_screen(xs[count - 1], values[count - 1]), 4.0f * s, theme.now_marker, 12);
  }
  if (over_time && count > 0) {
    const float x = to_screen(times.back(), 0.0).x;
    draw->AddLine(ImVec2(x, high_right.y), ImVec2(x, low_left.y), theme.now_marker, 1.5f * s);
  }
  draw->PopClipRect();

  // The legend: the series (with their units when they differ), then what the colours of
  // the regimes mean, in the corner of the plot the curves leave most free.
  struct Entry {
    ImU32 colour;
    std::string text;
    bool band;
  };
  std::vector<Entry> entries;
  if (regimes) {
    entries.push_back({theme.sticking, "sticking", false});
    entries.push_back({theme.slipping, "slipping", false});
  } else {
    for (std::size_t k = 0; k < plot.y.size(); ++k) {
      const std::string& unit = lesson.probe_unit(plot.y[k]);
      std::string text = plot.y[k];
      if (!one_unit && !unit.empty()) text += " (" + unit + ")";
      if (plot.y.size() > 1 || over_time) entries.push_back({theme.series[k % 4], text, false});
    }
    if (over_time) entries.push_back({theme.slip_band, "slipping", true});
  }
  float legend_width = 0.0f;
  for (const Entry& e : entries) legend_width = std::max(legend_width, font->CalcTextSizeA(text_height, 1e6f, 0.0f, e.text.c_str()).x);
  legend_width += 24.0f * s;
  const float legend_height = static_cast<float>(entries.size()) * (text_height + 2.0f * s);
  const float inner = 5.0f * s;
  const ImVec2 corners[] = {{low_left.x + inner, high_right.y + inner},
                            {high_right.x - inner - legend_width, high_right.y + inner},
                            {low_left.x + inner, low_left.y - inner - legend_height},
                            {high_right.x - inner - legend_width, low_left.y - inner - legend_height}};
  std::size_t best = 0, fewest = static_cast<std::size_t>(-1);
  for (std::size_t c = 0; c < 4; ++c) {
    std::size_t inside = 0;
    for (const auto* values : ys) {
      for (std::size_t i = 0; i < count; i += stride) {
        const ImVec2 p = to_screen(xs[i], (*values)[i]);
        inside += p.x >= corners[c].x && p.x <= corners[c].x + legend_width && p.y >= corners[c].y &&
                  p.y <= corners[c].y + legend_height;
      }
    }
    if (inside < fewest) fewest = inside, best = c;
  }
  ImVec2 at = corners[best];
  for (const Entry& e : entries) {
    const float w = font->CalcTextSizeA(text_height, 1e6f, 0.0f, e.text.c_str()).x;
    draw->AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + 22.0f * s + w + 2, at.y + text_height + 1),
                        (theme.panel & 0x00FFFFFFu) | (200u << IM_COL32_A_SHIFT));
    if (e.band) {
      draw->AddRectFilled(ImVec2(at.x, at.y + 2), ImVec2(at.x + 16.0f * s, at.y + text_height - 2), e.colour);
    } else {
      draw->AddLine(ImVec2(at.x, at.y + 0.5f * text_height), ImVec2(at.x + 16.0f * s, at.y + 0.5f * text_height), e.colour,
                    3.0f * s);
    }
    draw->AddText(font, text_height, ImVec2(at.x + 20.0f * s, at.y), theme.text, e.text.c_str());
    at.y += text_height + 2.0f * s;
  }
}

}  // namespace frictionlab::ui
