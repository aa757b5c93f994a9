#include "ui/plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/chart.h"

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

// A legend line: a series, a regime's colour, the slip band or a theory curve.
struct Entry {
  ImU32 colour;
  std::string text;
  enum class Look { line, band, theory } look;
};

std::vector<Entry> legend_entries(const lessons::Lesson& lesson, const lessons::Plot& plot, const Theme& theme) {
  const bool over_time = plot.kind == lessons::PlotKind::time;
  const bool regimes = !over_time && plot.y.size() == 1;
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  bool one_unit = true;
  for (const std::string& name : plot.y) one_unit = one_unit && lesson.probe_unit(name) == y_unit;
  std::vector<Entry> entries;
  if (regimes) {
    entries.push_back({theme.sticking, "sticking", Entry::Look::line});
    entries.push_back({theme.slipping, "slipping", Entry::Look::line});
  } else {
    for (std::size_t k = 0; k < plot.y.size(); ++k) {
      const std::string& unit = lesson.probe_unit(plot.y[k]);
      std::string text = plot.y[k];
      if (!one_unit && !unit.empty()) text += " (" + unit + ")";
      if (plot.y.size() > 1 || over_time) entries.push_back({theme.series[k % 4], text, Entry::Look::line});
    }
    if (over_time) entries.push_back({theme.slip_band, "slipping", Entry::Look::band});
  }
  for (const lessons::TheoryCurve& curve : plot.theory) entries.push_back({theme.theory, curve.label, Entry::Look::theory});
  return entries;
}

float text_width(ImFont* font, float height, const std::string& text) {
  return font->CalcTextSizeA(height, 1e6f, 0.0f, text.c_str()).x;
}

// The y axis' title: the probe and its unit, or the unit the probes share.
std::string y_title_of(const lessons::Lesson& lesson, const lessons::Plot& plot) {
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  bool one_unit = true;
  for (const std::string& name : plot.y) one_unit = one_unit && lesson.probe_unit(name) == y_unit;
  return plot.y.size() == 1 ? axis_title(lesson, plot.y.front()) : one_unit && !y_unit.empty() ? "(" + y_unit + ")" : "";
}

// Theory curves are sampled over the x range widened to whole tick steps, so that a range
// growing with the data asks the script again only when it passes a tick.
std::pair<double, double> sampling_range(double low, double high) {
  const std::vector<double> ticks = axis_ticks(low, high, 5);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : high - low;
  return {std::floor(low / step) * step, std::ceil(high / step) * step};
}

constexpr int theory_sample_count = 256;

}  // namespace

PlotLayout layout_plot(lessons::Lesson& lesson, std::size_t plot_index, double time_span, ImVec2 corner, ImVec2 size,
                       const Fonts& fonts) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  const Scene& scene = lesson.scene();
  ImFont* font = fonts.small;
  const float s = fonts.scale, text_height = font->FontSize;
  const bool over_time = plot.kind == lessons::PlotKind::time;
  const std::vector<double>& times = scene.times();
  const std::vector<double>& xs = over_time ? times : scene.probe(plot.x).history;
  std::vector<const std::vector<double>*> ys;
  for (const std::string& name : plot.y) ys.push_back(&scene.probe(name).history);
  const std::size_t count = xs.size();
  PlotLayout layout;

  // Axes' ranges: the data's, with the theory curves' values across it (a law is worth
  // seeing before the run reaches it).
  const Range x_range = over_time ? Range{0.0, std::max(time_span, count ? times.back() : 0.0)} : range_of({&xs}, count, true);
  const lessons::TheorySamples* samples = nullptr;
  std::vector<int> says_active;
  if (!plot.theory.empty()) {
    try {
      const auto [low, high] = sampling_range(x_range.low, x_range.high);
      samples = &lesson.theory_samples(plot_index, low, high, theory_sample_count);
      says_active = lesson.theory_active(plot_index);
    } catch (const lessons::ScriptError& error) {
      layout.theory_error = error.what();
      samples = nullptr;
    }
  }
  std::vector<double> theory_values;
  if (samples != nullptr) {
    for (const auto& curve : samples->curves) {
      for (const auto& piece : curve) {
        for (const lessons::TheoryPoint& p : piece) {
          if (p.x >= x_range.low && p.x <= x_range.high) theory_values.push_back(p.y);
        }
      }
    }
  }
  Range y_range = range_of(ys, count, true);
  if (!theory_values.empty()) {
    // range_of reads `count` values of each list; the theory's own count is its length.
    const Range theory_range = range_of({&theory_values}, theory_values.size(), true);
    y_range = count == 0 ? theory_range : Range{std::min(y_range.low, theory_range.low), std::max(y_range.high, theory_range.high)};
  }
  layout.x_low = x_range.low, layout.x_high = x_range.high, layout.y_low = y_range.low, layout.y_high = y_range.high;

  const std::vector<double> y_ticks = axis_ticks(y_range.low, y_range.high, 4);
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  float label_width = 0.0f;
  for (double tick : y_ticks) label_width = std::max(label_width, text_width(font, text_height, tick_text(tick, y_step)));
  layout.low_left = ImVec2(corner.x + label_width + 10.0f * s, corner.y + size.y - 2.0f * text_height - 8.0f * s);
  layout.high_right = ImVec2(corner.x + size.x - 8.0f * s, corner.y + text_height + 10.0f * s);
  if (layout.high_right.x - layout.low_left.x < 20.0f || layout.low_left.y - layout.high_right.y < 20.0f) return layout;

  // The legend's size, then the points it must not cover.
  const std::vector<Entry> entries = legend_entries(lesson, plot, theme(ThemeName::light));
  float legend_width = 0.0f, row_width = 0.0f;
  for (const Entry& e : entries) {
    legend_width = std::max(legend_width, text_width(font, text_height, e.text));
    row_width += text_width(font, text_height, e.text) + 32.0f * s;
  }
  legend_width += 24.0f * s;
  const float legend_height = static_cast<float>(entries.size()) * (text_height + 2.0f * s);

  const auto place = [&] {
    layout.points.clear();
    const float width = layout.high_right.x - layout.low_left.x;
    // At most about two points a pixel: the rest would be drawn over each other.
    const std::size_t stride = std::max<std::size_t>(1, count / static_cast<std::size_t>(std::max(1.0f, 2.0f * width)));
    for (const auto* values : ys) {
      for (std::size_t i = 0; i < count; i += stride) layout.points.push_back(layout.to_screen(xs[i], (*values)[i]));
      if (count > 0 && (count - 1) % stride != 0) layout.points.push_back(layout.to_screen(xs[count - 1], (*values)[count - 1]));
    }
    layout.theory.clear();
    if (samples == nullptr) return;
    for (const auto& curve : samples->curves) {
      layout.theory.emplace_back();
      for (const auto& piece : curve) {
        layout.theory.back().emplace_back();
        for (const lessons::TheoryPoint& p : piece) layout.theory.back().back().push_back(layout.to_screen(p.x, p.y));
      }
    }
  };
  place();
  std::vector<ImVec2> avoid = layout.points;
  for (const auto& curve : layout.theory) {
    for (const auto& piece : curve) avoid.insert(avoid.end(), piece.begin(), piece.end());
  }
  const float inset = 5.0f * s;
  const LegendPlace inside = legend_corner(ImVec2(layout.low_left.x, layout.high_right.y), ImVec2(layout.high_right.x, layout.low_left.y),
                                           ImVec2(legend_width, legend_height), inset, avoid, 3.0f * s);
  if (inside.clear || entries.empty()) {
    layout.legend_min = inside.min, layout.legend_max = inside.max;
  } else {
    // No corner is free of the data: the legend goes in one row above the data area, beside
    // the axis title, and the data area gives up a row when the title leaves no room.
    layout.legend_outside = true;
    const float title = text_width(font, text_height, y_title_of(lesson, plot)) + 12.0f * s;
    const float room = layout.high_right.x - corner.x - title;
    if (row_width > room) layout.high_right.y += text_height + 4.0f * s;
    layout.legend_min = ImVec2(layout.high_right.x - row_width, layout.high_right.y - text_height - 6.0f * s);
    layout.legend_max = ImVec2(layout.high_right.x, layout.high_right.y - 4.0f * s);
    place();
  }
  // The branch that applies now: the one that says so, else the one nearest the latest point.
  for (std::size_t c = 0; c < says_active.size(); ++c) {
    if (says_active[c] == 1 && layout.active < 0) layout.active = static_cast<int>(c);
  }
  const bool any_says = std::any_of(says_active.begin(), says_active.end(), [](int a) { return a >= 0; });
  if (!any_says && count > 0 && !layout.theory.empty()) {
    layout.active = nearest_curve(layout.theory, layout.to_screen(xs[count - 1], (*ys.front())[count - 1]));
  }
  return layout;
}

void draw_plot(ImDrawList* draw, lessons::Lesson& lesson, std::size_t plot_index, double time_span, ImVec2 corner, ImVec2 size,
               const Theme& theme, const Fonts& fonts) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  const PlotLayout layout = layout_plot(lesson, plot_index, time_span, corner, size, fonts);
  const Scene& scene = lesson.scene();
  ImFont* font = fonts.small;
  const float s = fonts.scale, text_height = font->FontSize;
  const bool over_time = plot.kind == lessons::PlotKind::time;
  const std::vector<double>& times = scene.times();
  const std::vector<double>& xs = over_time ? times : scene.probe(plot.x).history;
  std::vector<const std::vector<double>*> ys;
  for (const std::string& name : plot.y) ys.push_back(&scene.probe(name).history);
  const std::size_t count = xs.size();
  const ImVec2 low_left = layout.low_left, high_right = layout.high_right;
  const float width = high_right.x - low_left.x, height = low_left.y - high_right.y;
  if (width < 20.0f || height < 20.0f) return;
  const auto to_screen = [&](double x, double y) { return layout.to_screen(x, y); };

  // Grid and tick labels.
  const std::vector<double> y_ticks = axis_ticks(layout.y_low, layout.y_high, 4);
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  for (double tick : y_ticks) {
    const float y = to_screen(layout.x_low, tick).y;
    draw->AddLine(ImVec2(low_left.x, y), ImVec2(high_right.x, y), tick == 0.0 ? theme.axis : theme.grid, 1.0f);
    const std::string text = tick_text(tick, y_step);
    draw->AddText(font, text_height, ImVec2(low_left.x - text_width(font, text_height, text) - 5.0f * s, y - 0.5f * text_height),
                  theme.text, text.c_str());
  }
  const std::vector<double> x_ticks = axis_ticks(layout.x_low, layout.x_high, std::max(2, static_cast<int>(width / (70.0f * s))));
  const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
  for (double tick : x_ticks) {
    const float x = to_screen(tick, layout.y_low).x;
    draw->AddLine(ImVec2(x, low_left.y), ImVec2(x, high_right.y), tick == 0.0 ? theme.axis : theme.grid, 1.0f);
    const std::string text = tick_text(tick, x_step);
    draw->AddText(font, text_height, ImVec2(x - 0.5f * text_width(font, text_height, text), low_left.y + 3.0f * s), theme.text,
                  text.c_str());
  }
  draw->AddRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x, low_left.y), theme.axis);
  const std::string x_title = axis_title(lesson, plot.x);
  draw->AddText(font, text_height,
                ImVec2(low_left.x + 0.5f * (width - text_width(font, text_height, x_title)), low_left.y + text_height + 5.0f * s),
                theme.faint_text, x_title.c_str());
  const std::string y_title = y_title_of(lesson, plot);
  draw->AddText(font, text_height, ImVec2(corner.x + 2.0f * s, corner.y + 2.0f * s), theme.faint_text, y_title.c_str());

  draw->PushClipRect(ImVec2(low_left.x, high_right.y), ImVec2(high_right.x + 1, low_left.y + 1), true);
  const std::vector<unsigned char>& slipping = scene.slipping();
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
  // The theory under the measurements: the branch that applies now bold, the others dashed.
  for (std::size_t c = 0; c < layout.theory.size(); ++c) {
    for (const std::vector<ImVec2>& piece : layout.theory[c]) {
      if (static_cast<int>(c) == layout.active) {
        draw->AddPolyline(piece.data(), static_cast<int>(piece.size()), theme.theory, 0, 3.5f * s);
      } else {
        draw_dashed(draw, piece, theme.theory, 1.5f * s, 6.0f * s, 4.0f * s);
      }
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
  if (!layout.theory_error.empty()) {
    // The script's mistake where the curve would be; the lesson itself runs on.
    draw->AddText(font, text_height, ImVec2(low_left.x + 4.0f * s, high_right.y + 4.0f * s), theme.bad,
                  layout.theory_error.c_str(), nullptr, width - 8.0f * s);
  }
  draw->PopClipRect();

  // The legend where the layout put it: in a corner free of the data, or in a row above it.
  ImVec2 at = layout.legend_min;
  for (const Entry& e : legend_entries(lesson, plot, theme)) {
    const float w = text_width(font, text_height, e.text);
    draw->AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + 22.0f * s + w + 2, at.y + text_height + 1),
                        (theme.panel & 0x00FFFFFFu) | (200u << IM_COL32_A_SHIFT));
    const float middle = at.y + 0.5f * text_height;
    if (e.look == Entry::Look::band) {
      draw->AddRectFilled(ImVec2(at.x, at.y + 2), ImVec2(at.x + 16.0f * s, at.y + text_height - 2), e.colour);
    } else if (e.look == Entry::Look::theory) {
      draw_dashed(draw, {ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle)}, e.colour, 2.0f * s, 5.0f * s, 3.0f * s);
    } else {
      draw->AddLine(ImVec2(at.x, middle), ImVec2(at.x + 16.0f * s, middle), e.colour, 3.0f * s);
    }
    draw->AddText(font, text_height, ImVec2(at.x + 20.0f * s, at.y), theme.text, e.text.c_str());
    if (layout.legend_outside) {
      at.x += w + 32.0f * s;
    } else {
      at.y += text_height + 2.0f * s;
    }
  }
}

}  // namespace frictionlab::ui
