#include "draw/plots.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "draw/overlays.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {
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
  // Spans in halves: values near ±1.7e308 are finite, but their span is not.
  if (0.5 * high - 0.5 * low < 0.5 * least) {
    const double middle = 0.5 * low + 0.5 * high;
    low = std::min(low, middle - 0.5 * least);
    high = std::max(high, middle + 0.5 * least);
    if (include_zero && low < 0.0 && middle >= 0.0 && std::abs(middle) < least) low = std::min(low, 0.0);
  }
  const double margin = 0.12 * (0.5 * high - 0.5 * low);  // 6 % of the span
  constexpr double largest = std::numeric_limits<double>::max();
  return {low < 0.0 || !include_zero ? std::max(low - margin, -largest) : low, std::min(high + margin, largest)};
}

// The next of 1, 2, 5, 10, 20, ... times a power of ten at or above `size` (> 0), at most the
// largest double.
double round_bound(double size) {
  constexpr double largest = std::numeric_limits<double>::max();
  const double power = std::pow(10.0, std::floor(std::log10(size)));
  for (const double whole : {1.0, 2.0, 5.0, 10.0}) {
    if (whole * power >= size) return std::min(whole * power, largest);
  }
  return largest;
}

// A range from the record alone (the theory kept back while the class predicts) widened to
// round ends, as the time axis grows before the reveal: a range fitted to the data drawn so far
// rescaled the plot every frame of the run (a teacher's trial: push's friction axis moved under
// the class's eyes from 0 to −4.2 N). The data only add to it, so it only grows, and by a step of
// 2 or 2.5 times at once: the scale holds still between, three steps a decade.
Range round_ends(Range range) {
  if (range.low < 0.0) range.low = -round_bound(-range.low);
  if (range.high > 0.0) range.high = round_bound(range.high);
  return range;
}

// A probe as the class reads it: the script's label for it, else its name in words.
std::string probe_words(const lessons::Lesson& lesson, const std::string& probe) {
  const std::string& label = lesson.probe_label(probe);
  return label.empty() ? lessons::class_words(probe) : label;
}

std::string axis_title(const lessons::Lesson& lesson, const std::string& quantity) {
  if (quantity == "time") return "time (s)";
  const std::string& unit = lesson.probe_unit(quantity);
  return unit.empty() ? probe_words(lesson, quantity) : probe_words(lesson, quantity) + " (" + unit + ")";
}

// Theory curves are sampled over the x range widened to whole tick steps, so that a range
// growing with the data asks the script again only when it passes a tick.
std::pair<double, double> sampling_range(double low, double high) {
  const std::vector<double> ticks = axis_ticks(low, high, 5);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 0.5 * high - 0.5 * low;
  constexpr double largest = std::numeric_limits<double>::max();
  return {std::max(std::floor(low / step) * step, -largest), std::min(std::ceil(high / step) * step, largest)};
}

constexpr int theory_sample_count = 256;

}  // namespace

Chart plot_chart(lessons::Lesson& lesson, std::size_t plot_index, double time_span, const Theme& theme,
                 bool with_theory, bool steady) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  const Scene& scene = lesson.scene();
  const bool over_time = plot.kind == lessons::PlotKind::time;
  const std::vector<double>& times = scene.times();
  std::vector<const std::vector<double>*> xs, ys;
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    xs.push_back(over_time ? &times : &scene.probe(plot.x_of(k)).history);
    ys.push_back(&scene.probe(plot.y[k]).history);
  }
  const std::size_t count = times.size();
  const std::vector<unsigned char>& slipping = scene.slipping();

  Chart chart;
  chart.title = plot.title;
  chart.plain = true;
  chart.legend = Chart::Legend::inside;
  chart.y_tick_count = 4;
  chart.x_tick_count = 0;
  // Several x probes share their unit, not their name.
  chart.x_label = plot.xs.size() > 1 && !lesson.probe_unit(plot.x).empty() ? "(" + lesson.probe_unit(plot.x) + ")"
                                                                            : axis_title(lesson, plot.x);
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  bool one_unit = true;
  for (const std::string& name : plot.y) one_unit = one_unit && lesson.probe_unit(name) == y_unit;
  chart.y_label = plot.y.size() == 1 ? axis_title(lesson, plot.y.front()) : one_unit && !y_unit.empty() ? "(" + y_unit + ")" : "";

  // The x axis: the lesson's time span, or the data's range with zero in it.
  // Before the reveal a range from the record alone, with round ends (round_ends); once the
  // theory is shown its levels and curves hold the range from the opening (push's friction
  // axis), and the ends fit what is drawn.
  const auto grown = [&](Range range) { return with_theory ? range : round_ends(range); };
  const Range x_range =
      over_time ? Range{0.0, std::max(time_span, count ? times.back() : 0.0)} : grown(range_of(xs, count, true));
  chart.fixed_x = true;
  chart.x_low = x_range.low, chart.x_high = x_range.high;

  // The record: one series a probe. An X–Y plot of one probe is coloured by regime instead.
  const bool regimes = !over_time && plot.y.size() == 1;
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    ChartSeries series;
    const std::string& unit = lesson.probe_unit(plot.y[k]);
    if (plot.y.size() > 1 || over_time) series.name = probe_words(lesson, plot.y[k]) + (!one_unit && !unit.empty() ? " (" + unit + ")" : "");
    series.colour = theme.series[k % 4];
    series.points.reserve(count);
    for (std::size_t i = 0; i < count; ++i) series.points.push_back({(*xs[k])[i], (*ys[k])[i]});
    chart.series.push_back(std::move(series));
  }
  if (regimes) {
    std::vector<ImU32> colours(count);
    for (std::size_t i = 0; i < count; ++i) colours[i] = i < slipping.size() && slipping[i] ? theme.slipping : theme.sticking;
    chart.segment_colours.push_back(std::move(colours));
    chart.colour_keys = {{"sticking", theme.sticking}, {"slipping", theme.slipping}};
  }
  if (over_time) {
    // The slip regime shaded behind the curves, from the frame before it began: any contact's,
    // or the steps where the plot's own shade probe reads other than 0.
    const std::vector<double>* shade = plot.shade.empty() ? nullptr : &scene.probe(plot.shade).history;
    const std::size_t shaded = shade ? shade->size() : slipping.size();
    // A shade probe that reads no number (NaN) shades nothing there.
    const auto on = [&](std::size_t i) { return shade ? std::isfinite((*shade)[i]) && (*shade)[i] != 0.0 : slipping[i] != 0; };
    for (std::size_t i = 0; i < count && i < shaded;) {
      if (!on(i)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < count && j + 1 < shaded && on(j + 1)) ++j;
      chart.bands.push_back({i > 0 ? times[i - 1] : 0.0, times[j]});
      i = j + 1;
    }
    chart.band_colour = theme.slip_band;
    chart.band_name = shade ? probe_words(lesson, plot.shade) : "slipping";
  }
  chart.mark_now = true;
  chart.now_colour = theme.now_marker;
  if (over_time && count > 0) chart.now_x = times.back();

  // The theory across the x range; its values count for the y axis, so a law is seen before
  // the run gets there.
  std::vector<double> theory_values;
  if (with_theory && !plot.theory.empty()) {
    try {
      const auto [low, high] = sampling_range(x_range.low, x_range.high);
      const lessons::TheorySamples& samples = lesson.theory_samples(plot_index, low, high, theory_sample_count);
      const std::vector<int> says_active = lesson.theory_active(plot_index);
      for (std::size_t c = 0; c < samples.curves.size(); ++c) {
        ChartCurve curve;
        curve.name = plot.theory[c].label;
        give_theory_look(curve, theme, c);
        for (const auto& piece : samples.curves[c]) {
          curve.pieces.emplace_back();
          for (const lessons::TheoryPoint& p : piece) {
            curve.pieces.back().push_back({p.x, p.y});
            if (p.x >= x_range.low && p.x <= x_range.high) theory_values.push_back(p.y);
          }
        }
        chart.theory.push_back(std::move(curve));
      }
      // The branch that applies now: the one that says so, else the one nearest the latest point.
      const bool any_says = std::any_of(says_active.begin(), says_active.end(), [](int a) { return a >= 0; });
      chart.active_theory = any_says ? -1 : Chart::nearest;
      for (std::size_t c = 0; c < says_active.size(); ++c) {
        if (says_active[c] == 1 && chart.active_theory < 0) chart.active_theory = static_cast<int>(c);
      }
    } catch (const lessons::ScriptError& error) {
      chart.theory.clear();
      theory_values.clear();
      chart.message = error.what();  // the lesson itself runs on
    }
  }
  // The levels, labelled with their values in the y probe's unit; theirs count for the y axis too.
  if (with_theory && !plot.levels.empty() && chart.message.empty()) {
    try {
      const std::vector<double> values = lesson.plot_levels(plot_index);
      for (std::size_t k = 0; k < values.size(); ++k) {
        if (!std::isfinite(values[k])) continue;  // nil: no such level now
        std::string value = format_quantity(values[k], y_unit.c_str());
        if (y_unit.empty()) value.pop_back();  // the space before a unit there is not
        chart.levels.push_back({plot.levels[k].label + " = " + value, values[k],
                                theme.theory[k % 2]});
        theory_values.push_back(values[k]);
      }
    } catch (const lessons::ScriptError& error) {
      chart.theory.clear();
      chart.levels.clear();
      theory_values.clear();
      chart.message = error.what();
    }
  }
  if (steady) {
    chart.steady = true;
    // Room beside the data for the theory's keys from the start, before the reveal shows them.
    for (const lessons::TheoryCurve& curve : plot.theory) chart.legend_room.push_back(curve.label);
    chart.y_tick_spacing = 22.0f;
  }
  Range y_range = range_of(ys, count, true);
  if (!theory_values.empty()) {
    const Range theory_range = range_of({&theory_values}, theory_values.size(), true);
    y_range = count == 0 ? theory_range : Range{std::min(y_range.low, theory_range.low), std::max(y_range.high, theory_range.high)};
  }
  y_range = grown(y_range);
  chart.fixed_y = true;
  chart.y_low = y_range.low, chart.y_high = y_range.high;
  return chart;
}

ChartLayout layout_plot(lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner, ImVec2 size,
                        const Fonts& fonts, bool with_theory, bool steady) {
  return layout_chart(plot_chart(lesson, plot, time_span, theme(ThemeName::light), with_theory, steady), corner, size, fonts);
}

ChartLayout draw_plot(ImDrawList* draw, lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner,
                      ImVec2 size, const Theme& theme, const Fonts& fonts, bool with_theory,
                      const std::function<std::string(const std::string&)>& script_words, bool steady) {
  Chart chart = plot_chart(lesson, plot, time_span, theme, with_theory, steady);
  if (script_words && !chart.message.empty()) chart.message = script_words(chart.message);
  return draw_chart(draw, corner, size, chart, theme, fonts);
}

}  // namespace frictionlab::draw
