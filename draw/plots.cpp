#include "draw/plots.h"

#include <box2d/b2_common.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <list>
#include <map>
#include <numbers>
#include <optional>
#include <span>

#include "draw/overlays.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {
namespace {

struct Range {
  double low = 0.0, high = 1.0;
};

// What the values reach, with the zero line in it (forces are read against zero), noise and all.
Range reach_of(const std::vector<const std::vector<double>*>& series, std::size_t count) {
  double low = 0.0, high = 0.0;
  for (const auto* values : series) {
    for (std::size_t i = 0; i < count && i < values->size(); ++i) {
      if (!std::isfinite((*values)[i])) continue;
      low = std::min(low, (*values)[i]);
      high = std::max(high, (*values)[i]);
    }
  }
  return {low, high};
}

// A reach as an axis shows it: rounding noise is not drawn as a signal.
Range beyond_noise(Range reach) {
  double low = reach.low, high = reach.high;
  // Rounding noise (a resting block's speed of 1e-9 m/s) is not drawn as a signal: the axis
  // reaches at least a thousandth of a unit from zero, or a millionth of the values' size.
  // (Spans in halves: values near ±1.7e308 are finite, but their span is not.)
  const double least = std::max(1e-3, 1e-6 * std::max(-low, high));
  if (0.5 * high - 0.5 * low < 0.5 * least) {
    if (high >= -low) high = low + least;
    else low = high - least;
  }
  return {low, high};
}

Range extent_of(const std::vector<const std::vector<double>*>& series, std::size_t count) {
  if (count == 0) return {};  // nothing recorded yet: 0 to 1
  return beyond_noise(reach_of(series, count));
}

// The next of 1, 2, 5, 10, 20, ... times a power of ten at or above `size` (> 0), at most the
// largest double; `fine`: the next of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, ... times one (the
// axis' ends then need not fall on a tick; round_ends says which the axis takes).
double round_bound(double size, bool fine) {
  constexpr double largest = std::numeric_limits<double>::max();
  const double power = std::pow(10.0, std::floor(std::log10(size)));
  static constexpr double coarse_steps[] = {1.0, 2.0, 5.0, 10.0};
  static constexpr double fine_steps[] = {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0};
  for (const double whole : fine ? std::span<const double>(fine_steps) : std::span<const double>(coarse_steps)) {
    // (Within a rounding of the end: 3 × 10 is no more than 30.)
    if (whole * power >= size * (1.0 - 1e-12)) return std::min(whole * power, largest);
  }
  return largest;
}

// An axis' ends: each side of zero a round value beyond what the values reach and a margin of 3 %
// of it (so no curve runs along the frame's line). Before and after the reveal alike (issue 31:
// push's x axis read 0–10 N before it, 0–6.3 N after), and from the theory's values too, shown
// or not (push's friction axis reads −5 to 0 N from the opening). `fixed`: the range is the
// whole run's from the opening (planned_reach), so the scale holds still, and its ends are the
// finer round values (fine in round_bound): with only 1, 2 and 5 times a power of ten,
// stacked_blocks' pull of 21 N had an axis to 50 N, its data in the lower 45 % of the plot (a
// teacher's trial); now 25 N. An axis that grows with the record (a mystery's, whose run ahead
// would tell its values) keeps to 1, 2 and 5: it steps fewer times, and each step tells a class
// less of where the values are. The margin is each side's own: a span's (6 % of 9.4 N) took
// spring_pull's ±4.7 N to −5 and 10 N.
Range round_ends(Range range, bool fixed) {
  constexpr double margin = 1.03;
  constexpr double largest = std::numeric_limits<double>::max();
  // Values near ±1.7e308 are finite, but 1.03 times them is not: their end is the largest double.
  const auto side = [&](double reach) { return reach > largest / margin ? largest : round_bound(reach * margin, fixed); };
  return {range.low < 0.0 ? -side(-range.low) : 0.0, range.high > 0.0 ? side(range.high) : 0.0};
}

// The narrowest span an axis of a length or an angle shows: Box2D's own tolerances, within which
// the world's lengths and turns are its solver's, not the lesson's (contacts may overlap by
// b2_linearSlop, 5 mm; b2_angularSlop, 2°, is its angle's). Fitted to the record alone, a box
// that had not tipped drew its tilt's solver noise, −0.0015°, on an axis from −0.002 to 0 (a
// teacher's trial). 0: no floor (a force, a speed: the solver gives them exactly enough).
double resolution_of(const std::string& unit) {
  const double slop = b2_linearSlop, turn = b2_angularSlop;
  if (unit == "m") return slop;
  if (unit == "cm") return 100.0 * slop;
  if (unit == "mm") return 1000.0 * slop;
  if (unit == "\u00b0") return turn * 180.0 / std::numbers::pi;
  if (unit == "rad") return turn;
  return 0.0;
}

// `range` at least `span` wide, widened upwards: values that narrow are noise about zero, whose
// sign says nothing of where the quantity goes (tipping_box's tilt read −0.0015° before the box
// tipped forwards; widened downwards its axis read −5° to 0° and then had to turn over).
Range at_least(Range range, double span) {
  if (!(span > 0.0) || range.high - range.low >= span) return range;
  range.high = std::max(range.high, range.low + span);
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

// The key of an X–Y plot's frames with no contact touching.
constexpr const char* no_contact_key = "no contact";

// What one plot of the lesson reads: its record's x and y values, probe by probe.
struct PlotRecord {
  const lessons::Plot& plot;
  bool over_time;
  std::vector<const std::vector<double>*> xs, ys;
  std::size_t count;
};

PlotRecord record_of(lessons::Lesson& lesson, std::size_t plot_index) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  const Scene& scene = lesson.scene();
  PlotRecord record{plot, plot.kind == lessons::PlotKind::time, {}, {}, scene.times().size()};
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    record.xs.push_back(record.over_time ? &scene.times() : &scene.probe(plot.x_of(k)).history);
    record.ys.push_back(&scene.probe(plot.y[k]).history);
  }
  return record;
}

// What each plot's record reaches over a whole run of the lesson from t = 0 to its end, at the
// values it has now: the axes' ends from the opening, so that no plot rescales as the run goes
// past a round end (stacked_blocks' friction axis stepped 1, 2, 5, 10, 20, 50 N through its run,
// the last at 3.9 s of 4.2 s; its accelerations 5 to 10 m/s² there). Worked out on a copy of the
// lesson, once for each script text, setting and set of values (a slider moved runs it again).
struct PlannedReach {
  std::vector<Range> x, y;  // plot by plot; x for an X–Y plot only
  // Plot by plot, each series' points over the whole run, a (NaN, NaN) after each: where the
  // levels' texts must not go (Chart::planned_points).
  std::vector<std::vector<std::pair<double, double>>> points;
  // The force the arrows are scaled for (run_force_for_scale).
  std::optional<float> force_for_scale;
};

std::string values_key(const lessons::Lesson& lesson) {
  const lessons::ScriptText text = lesson.script();
  std::string key = text.path + '\n' + text.source + '\n';
  char number[64];
  const StepSettings& settings = lesson.settings();
  std::snprintf(number, sizeof number, "%.17g %d %d %d %d %.17g\n", settings.hz, settings.substeps, settings.velocity_iterations,
                settings.position_iterations, static_cast<int>(settings.treatment), settings.threshold_speed);
  key += number;
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    std::snprintf(number, sizeof number, "=%.17g\n", parameter.value);
    key += parameter.name + number;
  }
  return key;
}

// The most world steps a rehearsal takes: 47 447 for push at 10 kg pushed at 0.2 N/s, 0.19 s
// here; a run longer than that (a step rate of 100 000 Hz, a thousand sub-steps) is not run
// ahead, lest the window freeze on a slider's move, and its axes follow its record.
constexpr double rehearsal_steps = 60000.0;

std::optional<PlannedReach> rehearse(const lessons::Lesson& lesson) {
  const StepSettings& settings = lesson.settings();
  if (!(lesson.duration() * settings.hz * settings.substeps <= rehearsal_steps)) return std::nullopt;
  std::map<std::string, std::string> values;
  for (const lessons::Parameter& parameter : lesson.parameters()) values[parameter.name] = lessons::parameter_text(parameter);
  try {
    lessons::Lesson copy(lesson.script(), values, lesson.settings());
    // Frame by frame, as step_to would: the largest force on a moving body in each.
    std::vector<float> largest;
    while (!copy.reached(copy.duration())) {
      copy.step();
      float frame = 0.0f;
      for (const auto& [name, body] : copy.scene().bodies()) {
        if (body->GetType() != b2_dynamicBody) continue;
        for (const ForceOnBody& force : forces_on(copy.scene(), body)) frame = std::max(frame, force.force.Length());
      }
      largest.push_back(frame);
    }
    PlannedReach reach;
    if (!largest.empty()) {
      const auto ninth = largest.begin() + static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(largest.size() - 1));
      std::nth_element(largest.begin(), ninth, largest.end());
      if (*ninth > 0.0f) reach.force_for_scale = *ninth;
    }
    const Scene& scene = copy.scene();
    const std::size_t count = scene.times().size();
    for (const lessons::Plot& plot : copy.plots()) {
      std::vector<const std::vector<double>*> xs, ys;
      std::vector<std::pair<double, double>> points;
      for (std::size_t k = 0; k < plot.y.size(); ++k) {
        const std::vector<double>& x = plot.kind != lessons::PlotKind::time ? scene.probe(plot.x_of(k)).history : scene.times();
        if (plot.kind != lessons::PlotKind::time) xs.push_back(&x);
        ys.push_back(&scene.probe(plot.y[k]).history);
        for (std::size_t i = 0; i < count && i < x.size() && i < ys.back()->size(); ++i) points.emplace_back(x[i], (*ys.back())[i]);
        points.emplace_back(NAN, NAN);
      }
      reach.x.push_back(xs.empty() ? Range{} : reach_of(xs, count));
      reach.y.push_back(reach_of(ys, count));
      reach.points.push_back(std::move(points));
    }
    return reach;
  } catch (const std::exception&) {
    return std::nullopt;  // the lesson itself says what went wrong; its axes follow its record
  }
}

// How many times planned_reach looked a lesson's reach up by its text and values (tests).
std::size_t reach_lookups = 0;

// The reach of the lesson's plots, from the last few rehearsals kept (the window draws a plot
// every frame, and each plot asks). A lesson's revision finds its answer again at the cost of
// comparing two numbers: values_key holds the whole script's text, and building it for every
// plot of every frame cost more than drawing the plot. Only a revision not seen lately builds
// the key, which finds a rehearsal of the same text, values and settings (a slider moved back,
// the lesson opened again) among those kept. Revisions are never reused (Lesson::revision), so
// several lessons' answers are kept side by side: two lessons drawing their plots in turn (the
// web page's, the tests') each find their own, where one slot had them build the key every time.
const PlannedReach* planned_reach(const lessons::Lesson& lesson) {
  struct Kept {
    std::string key;
    std::optional<PlannedReach> reach;
  };
  // A list: the answers handed out stay where they are while others come and go.
  static std::list<Kept> kept;
  static std::vector<std::pair<std::uint64_t, const Kept*>> by_revision;  // the latest last
  constexpr std::size_t most_kept = 8, most_revisions = 16;
  const auto answer = [](const Kept& entry) { return entry.reach ? &*entry.reach : nullptr; };
  const auto seen = std::find_if(by_revision.begin(), by_revision.end(), [&](const auto& entry) { return entry.first == lesson.revision(); });
  if (seen != by_revision.end()) return answer(*seen->second);
  ++reach_lookups;
  const std::string key = values_key(lesson);
  auto known = std::find_if(kept.begin(), kept.end(), [&](const Kept& entry) { return entry.key == key; });
  if (known == kept.end()) {
    // Rehearsed before the oldest is let go, so that nothing kept moves until its answer is in.
    std::optional<PlannedReach> rehearsed = rehearse(lesson);
    if (kept.size() >= most_kept) {
      const Kept* oldest = &kept.front();
      std::erase_if(by_revision, [&](const auto& entry) { return entry.second == oldest; });
      kept.pop_front();
    }
    kept.push_back({key, std::move(rehearsed)});
    known = std::prev(kept.end());
  }
  if (by_revision.size() >= most_revisions) by_revision.erase(by_revision.begin());
  by_revision.emplace_back(lesson.revision(), &*known);
  return answer(*known);
}

}  // namespace

std::optional<float> run_force_for_scale(const lessons::Lesson& lesson) {
  const PlannedReach* reach = planned_reach(lesson);
  return reach != nullptr ? reach->force_for_scale : std::nullopt;
}

namespace {

Range joined(Range a, Range b) { return {std::min(a.low, b.low), std::max(a.high, b.high)}; }

bool one_y_unit(const lessons::Lesson& lesson, const lessons::Plot& plot) {
  return std::all_of(plot.y.begin(), plot.y.end(),
                     [&](const std::string& name) { return lesson.probe_unit(name) == lesson.probe_unit(plot.y.front()); });
}

// The axes' names: several x probes share their unit, not their name, and so do several y
// probes of one unit.
void name_axes(Chart& chart, const lessons::Lesson& lesson, const lessons::Plot& plot) {
  chart.x_label = plot.xs.size() > 1 && !lesson.probe_unit(plot.x).empty() ? "(" + lesson.probe_unit(plot.x) + ")"
                                                                            : axis_title(lesson, plot.x);
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  chart.y_label = plot.y.size() == 1                      ? axis_title(lesson, plot.y.front())
                  : one_y_unit(lesson, plot) && !y_unit.empty() ? "(" + y_unit + ")"
                                                                : "";
}

// A series' look: its colour, and its dash pattern (0: a solid line).
struct SeriesLook {
  ImU32 colour = 0;
  float dash = 0.0f, gap = 0.0f;
  bool operator==(const SeriesLook&) const = default;
};

// The dashes of a series drawn dashed: longer than every theory curve's pattern (6/4, 2/3 and
// 11/4 points, give_theory_look) and on a thicker line in a series' colour, so that it is read
// as a measured curve.
constexpr float series_dash = 16.0f, series_gap = 6.0f;

// Each y probe's look: a force of a known kind (its read = { ... } says: a contact's friction,
// a normal force, an applied force, a spring, a rope) in its arrows' colour in the world, so
// that a class matches a curve to its arrow (issue 31: the world drew friction vermilion and
// spring_pull's plot drew it blue); the first probe of a kind takes it, a second its shade
// (Theme::second_force) dashed, told apart by its pattern where a projector washes the two
// colours toward one (stacked_blocks' two frictions, issue 31), a third the kind's colour
// dashed and a fourth the shade solid, so that a force's curve never takes another kind's
// colour (friction_models' third friction was the applied force's blue).
// The others (a speed) take the series colours in turn that no probe of the plot has yet,
// solid, then dashed: no two curves of one plot share a look.
std::vector<SeriesLook> series_looks(const lessons::Lesson& lesson, const lessons::Plot& plot, const Theme& theme) {
  std::vector<SeriesLook> looks(plot.y.size());
  std::vector<bool> given(plot.y.size(), false);
  const auto taken = [&](const SeriesLook& look) {
    for (std::size_t k = 0; k < looks.size(); ++k) {
      if (given[k] && looks[k] == look) return true;
    }
    return false;
  };
  // A probe drawn like a material (probe{ like = ... }): its colour as a line that stands out on
  // the plot; a second like the same material dashed.
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    const std::string& material = lesson.probe_like(plot.y[k]);
    if (material.empty()) continue;
    const ImU32 colour =
        line_like(material_colour(theme, material, lesson.scene().pairs().find_material(material)), theme.panel);
    looks[k] = taken(SeriesLook{colour}) ? SeriesLook{colour, series_dash, series_gap} : SeriesLook{colour};
    given[k] = true;
  }
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    if (given[k]) continue;
    const std::optional<ForceKind> kind = lesson.probe_force(plot.y[k]);
    if (!kind) continue;
    const ImU32 own = theme.force[static_cast<int>(*kind)], shade = theme.second_force[static_cast<int>(*kind)];
    for (const SeriesLook& look : {SeriesLook{own}, SeriesLook{shade, series_dash, series_gap},
                                   SeriesLook{own, series_dash, series_gap}, SeriesLook{shade}}) {
      if (taken(look)) continue;
      looks[k] = look;
      given[k] = true;
      break;
    }
  }
  std::vector<SeriesLook> others;
  for (const bool dashed : {false, true}) {
    for (const ImU32 colour : theme.series) others.push_back(dashed ? SeriesLook{colour, series_dash, series_gap} : SeriesLook{colour});
  }
  std::size_t next = 0;
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    if (given[k]) continue;
    // More curves than looks: they repeat (none of the lessons plots more than four).
    std::size_t tried = 0;
    while (tried < others.size() && taken(others[next % others.size()])) ++next, ++tried;
    looks[k] = others[next % others.size()];
    given[k] = true;
    ++next;
  }
  return looks;
}

// The record: one series a probe. An X–Y plot of one probe is coloured by regime instead.
void add_record(Chart& chart, const lessons::Lesson& lesson, const PlotRecord& record, const Theme& theme) {
  const lessons::Plot& plot = record.plot;
  const bool one_unit = one_y_unit(lesson, plot);
  const std::vector<SeriesLook> looks = series_looks(lesson, plot, theme);
  for (std::size_t k = 0; k < plot.y.size(); ++k) {
    ChartSeries series;
    const std::string& unit = lesson.probe_unit(plot.y[k]);
    if (plot.y.size() > 1 || record.over_time) {
      series.name = probe_words(lesson, plot.y[k]) + (!one_unit && !unit.empty() ? " (" + unit + ")" : "");
    }
    series.colour = looks[k].colour;
    series.dash = looks[k].dash, series.gap = looks[k].gap;
    series.points.reserve(record.count);
    for (std::size_t i = 0; i < record.count; ++i) series.points.push_back({(*record.xs[k])[i], (*record.ys[k])[i]});
    chart.series.push_back(std::move(series));
  }
  const std::vector<unsigned char>& slipping = lesson.scene().slipping();
  const std::vector<unsigned char>& touching = lesson.scene().touching();
  if (!record.over_time && plot.y.size() == 1) {
    // A frame with nothing touching is neither: push's block in the air read as sticking.
    std::vector<ImU32> colours(record.count);
    bool in_the_air = false;
    for (std::size_t i = 0; i < record.count; ++i) {
      const bool touches = i >= touching.size() || touching[i];
      in_the_air = in_the_air || !touches;
      colours[i] = !touches ? theme.no_contact : i < slipping.size() && slipping[i] ? theme.slipping : theme.sticking;
    }
    chart.segment_colours.push_back(std::move(colours));
    chart.colour_keys = {{"sticking", theme.sticking}, {"slipping", theme.slipping}};
    // Keyed once it has happened; a steady plot keeps its key's room from the start.
    if (in_the_air) chart.colour_keys.push_back({no_contact_key, theme.no_contact});
  }
  chart.mark_now = true;
  chart.now_colour = theme.now_marker;
  if (record.over_time && record.count > 0) chart.now_x = lesson.scene().times().back();
}

// The slip regime shaded behind a time plot's curves, from the frame before it began: any
// contact's, or the steps where the plot's own shade probe reads other than 0.
void add_slip_bands(Chart& chart, const lessons::Lesson& lesson, const PlotRecord& record, const Theme& theme) {
  const Scene& scene = lesson.scene();
  const std::vector<double>& times = scene.times();
  const std::vector<unsigned char>& slipping = scene.slipping();
  const std::string& shade_probe = record.plot.shade;
  const std::vector<double>* shade = shade_probe.empty() ? nullptr : &scene.probe(shade_probe).history;
  const std::size_t shaded = shade ? shade->size() : slipping.size();
  // A shade probe that reads no number (NaN) shades nothing there.
  const auto on = [&](std::size_t i) { return shade ? std::isfinite((*shade)[i]) && (*shade)[i] != 0.0 : slipping[i] != 0; };
  for (std::size_t i = 0; i < record.count && i < shaded;) {
    if (!on(i)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < record.count && j + 1 < shaded && on(j + 1)) ++j;
    chart.bands.push_back({i > 0 ? times[i - 1] : 0.0, times[j]});
    i = j + 1;
  }
  chart.band_colour = theme.slip_band;
  chart.band_name = shade ? probe_words(lesson, shade_probe) : "slipping";
}

// The theory curves across the x range, each in its look, and which applies now. Returns the
// values they take in the range, which count for the y axis, so a law is seen before the run
// gets there.
std::vector<double> add_theory_curves(Chart& chart, lessons::Lesson& lesson, std::size_t plot_index, Range x_range,
                                      const Theme& theme) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  std::vector<double> values;
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
        if (p.x >= x_range.low && p.x <= x_range.high) values.push_back(p.y);
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
  return values;
}

// The plot's levels, labelled "label = value" in the y probe's unit; their values, which count
// for the y axis too.
std::vector<double> add_levels(Chart& chart, lessons::Lesson& lesson, std::size_t plot_index, const Theme& theme) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  std::vector<double> values;
  const std::vector<double> levels = lesson.plot_levels(plot_index);
  for (std::size_t k = 0; k < levels.size(); ++k) {
    if (!std::isfinite(levels[k])) continue;  // nil: no such level now
    std::string value = format_quantity(levels[k], y_unit.c_str());
    if (y_unit.empty()) value.pop_back();  // the space before a unit there is not
    chart.levels.push_back({plot.levels[k].label + " = " + value, levels[k], theme.theory[k % 2]});
    values.push_back(levels[k]);
  }
  return values;
}

// The room a hidden level's text takes: its label beside each form its value may print in
// (format_quantity's three figures, from 0.001 to 9999, negative: "−0.00888" to "−8888"), so
// that the widest of them, not the value, sets the column. (Under 0.001 a value prints as a
// power of ten; no level of a lesson comes near it.)
std::vector<std::string> hidden_level_room(const lessons::Lesson& lesson, std::size_t plot_index) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  const std::string& y_unit = lesson.probe_unit(plot.y.front());
  std::vector<std::string> room;
  for (const lessons::PlotLevel& level : plot.levels) {
    for (const double widest : {-0.00888, -0.0888, -0.888, -8.88, -88.8, -888.0, -8888.0}) {
      std::string value = format_quantity(widest, y_unit.c_str());
      if (y_unit.empty()) value.pop_back();
      room.push_back(level.label + " = " + value);
    }
  }
  return room;
}

// The values the theory's curves and the plot's levels take, apart: a level counts for the y
// axis only where the run comes near it (level_in_reach).
struct TheoryValues {
  std::vector<double> curves, levels;
};

// The chart without the theory's curves and levels (kept back, or in error).
void clear_theory(Chart& chart) {
  chart.theory.clear();
  chart.levels.clear();
  chart.active_theory = -1;
}

// The theory's curves and levels (a script error in one becomes the chart's message, and the
// lesson itself runs on); the values they take, for the y axis.
TheoryValues add_theory(Chart& chart, lessons::Lesson& lesson, std::size_t plot_index, Range x_range, const Theme& theme) {
  const lessons::Plot& plot = lesson.plots().at(plot_index);
  TheoryValues values;
  try {
    if (!plot.theory.empty()) values.curves = add_theory_curves(chart, lesson, plot_index, x_range, theme);
    if (!plot.levels.empty()) values.levels = add_levels(chart, lesson, plot_index, theme);
  } catch (const lessons::ScriptError& error) {
    clear_theory(chart);
    values = {};
    chart.message = error.what();
  }
  return values;
}

// Whether a level lies near enough what the run and the theory's curves reach (`reach`, zero in
// it) for the y axis to run out to it: within half the reach's span beyond either end. A level
// further off is a threshold the run never comes near (tipping_box pushed 0.2 m up slides at
// 49 N, and its tipping push of 123 N took the friction axis to -140 N, the run's data in the
// top third; a teacher's trial): it is left off the axis, and the theory table still gives it.
bool level_in_reach(double level, Range reach) {
  const double slack = 0.5 * (reach.high - reach.low);
  return level >= reach.low - slack && level <= reach.high + slack;
}

}  // namespace

std::size_t planned_reach_lookups() { return reach_lookups; }

double time_axis_span(double duration, double now, bool secret) {
  if (secret) {
    double span = 1.0;
    for (int i = 0; span < now && i < 60; ++i) span *= (i % 3 == 1) ? 2.5 : 2.0;
    return span;
  }
  const double reach = std::max(duration, now);
  if (!(reach > 0.0) || !std::isfinite(reach)) return 1.0;
  // The power of ten as a divisor below 1 (0.3 s is 3 / 10, where 3 × 0.1 is 0.30000000000000004).
  const int exponent = static_cast<int>(std::floor(std::log10(reach)));
  const double power = std::pow(10.0, std::abs(exponent));
  for (const double whole : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0}) {
    const double end = exponent < 0 ? whole / power : whole * power;
    // (Within a rounding of the end: a duration of 2.5 s is no more than 2.5.)
    if (end >= reach * (1.0 - 1e-12)) return end;
  }
  return reach;
}

namespace {

// A chart of the plot before anything is plotted in it: its title, its axes' names and ticks.
Chart empty_chart(const lessons::Lesson& lesson, const lessons::Plot& plot, bool steady) {
  Chart chart;
  chart.title = plot.title;
  chart.plain = true;
  chart.legend = Chart::Legend::inside;
  chart.y_tick_count = 4;
  chart.x_tick_count = 0;
  // The y ticks as fine as the data area's height reads, a line and a half of their labels' text
  // apart (the body text's on a page of its own, number_font): the levels read off the axis (1 N
  // steps at push's defaults, where 2 or 5 N were).
  chart.y_tick_spacing = plot_tick_spacing_points(steady);
  name_axes(chart, lesson, plot);
  return chart;
}

// What the axes reach for besides the record: the run's plan, and how much of the record is the
// run's.
struct RunReach {
  const PlannedReach* planned;  // none for a mystery before its reveal
  bool planned_here;            // the plan covers this plot
  std::size_t reach_count;      // the record's steps that are the run's
};

RunReach run_reach(lessons::Lesson& lesson, const PlotRecord& record, std::size_t plot_index, bool secret) {
  const std::vector<double>& times = lesson.scene().times();
  // A mystery's values are hidden: a run to the end would tell them (push's breakaway on its x
  // axis), so its axes follow the record alone until the reveal.
  const PlannedReach* planned = secret ? nullptr : planned_reach(lesson);
  const bool planned_here = planned != nullptr && plot_index < planned->y.size();
  // Past the run's end the window plays on, and the axes stay the run's (teachers.md: no plot
  // rescales as the run goes on): what follows the run (tipping_box's box falling over onto a
  // −1900 N impact, push's push growing to 25 N) would squash the run into a sliver. It runs
  // on past the data area's edge, clipped there. The run's record ends at its first step at or
  // after its duration.
  std::size_t reach_count = record.count;
  if (planned_here) {
    const double end = lesson.duration() * (1.0 - 1e-12);
    const auto first_past = std::lower_bound(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(std::min(record.count, times.size())), end);
    reach_count = std::min(record.count, static_cast<std::size_t>(first_past - times.begin()) + 1);
  }
  return {planned, planned_here, reach_count};
}

// The x axis: the time span (fixed by the lesson's duration from the opening), or what the
// record reaches, with round ends.
Range x_axis_range(const lessons::Lesson& lesson, const PlotRecord& record, const RunReach& run, std::size_t plot_index,
                   double time_span) {
  const auto& [planned, planned_here, reach_count] = run;
  const std::vector<double>& times = lesson.scene().times();
  // (The noise floor on the whole: a partial record's noise, widened alone, took contact_area's
  // speeds to −0.002 m/s early in the run and −1e-7 at its end.)
  const Range x_reach = planned_here && !record.over_time
                            ? beyond_noise(joined(reach_of(record.xs, reach_count), planned->x[plot_index]))
                            : extent_of(record.xs, record.count);
  return record.over_time ? Range{0.0, std::max(time_span, record.count ? times.back() : 0.0)}
                          : record.count == 0 && !planned_here ? Range{}  // nothing recorded yet: 0 to 1
                                              : round_ends(at_least(x_reach,
                                                                    resolution_of(lesson.probe_unit(record.plot.x))),
                                                           planned_here);
}

// A plot on a page of its own keeps its levels' texts' room beside its data from the opening,
// shown or not, so that the reveal moves nothing (Chart::level_room). A mystery's levels are
// worked out from its hidden values: their texts' widths would tell them (incline's θc, push's
// μs·N) and move the column as a slider moved them, so the room is every declared level's
// label beside the widest value text it could have, whatever its value.
std::vector<std::string> level_texts_room(const Chart& chart, const lessons::Lesson& lesson, std::size_t plot_index,
                                          bool secret) {
  std::vector<std::string> level_texts;
  if (secret) {
    level_texts = hidden_level_room(lesson, plot_index);
  } else {
    for (const ChartLevel& level : chart.levels) level_texts.push_back(level.text);
  }
  return level_texts;
}

// A plot on a page of its own holds still as the run goes on and the theory is revealed.
void keep_room_from_the_start(Chart& chart, const lessons::Plot& plot, std::vector<std::string> level_texts) {
  chart.steady = true;
  chart.level_room = std::move(level_texts);
  // Room beside the data for the theory's keys from the start, before the reveal shows them.
  // An X–Y plot coloured by regime keys its three regimes first, "no contact" once it has
  // happened, in a place of its own from the start.
  if (!chart.segment_colours.empty()) chart.legend_room = {"sticking", "slipping", no_contact_key};
  for (const lessons::TheoryCurve& curve : plot.theory) chart.legend_room.push_back(curve.label);
}

// The y axis: what the run and the theory's curves reach, and the levels near that, with round
// ends.
Range y_axis_range(const lessons::Lesson& lesson, const PlotRecord& record, const RunReach& run, std::size_t plot_index,
                   const TheoryValues& theory_values) {
  const auto& [planned, planned_here, reach_count] = run;
  Range y_range = planned_here ? beyond_noise(joined(reach_of(record.ys, reach_count), planned->y[plot_index]))
                               : extent_of(record.ys, record.count);
  const bool reached = record.count > 0 || planned_here;
  if (!theory_values.curves.empty()) {
    const Range curves = extent_of({&theory_values.curves}, theory_values.curves.size());
    y_range = !reached ? curves : joined(y_range, curves);
  }
  // Levels near what the run and the curves reach (all of them where nothing is reached yet).
  const bool reach_known = reached || !theory_values.curves.empty();
  const Range reach = joined(y_range, Range{0.0, 0.0});
  std::vector<double> levels_shown;
  for (const double level : theory_values.levels) {
    if (!reach_known || level_in_reach(level, reach)) levels_shown.push_back(level);
  }
  if (!levels_shown.empty()) {
    const Range levels = extent_of({&levels_shown}, levels_shown.size());
    y_range = !reach_known ? levels : joined(y_range, levels);
  }
  if (reached || !theory_values.curves.empty() || !theory_values.levels.empty()) {
    y_range = round_ends(at_least(y_range, resolution_of(record.plot.y.empty() ? std::string() : lesson.probe_unit(record.plot.y.front()))),
                         planned_here);
  }
  return y_range;
}

}  // namespace

Chart plot_chart(lessons::Lesson& lesson, std::size_t plot_index, double time_span, const Theme& theme,
                 bool with_theory, bool steady, bool secret) {
  const PlotRecord record = record_of(lesson, plot_index);
  Chart chart = empty_chart(lesson, record.plot, steady);
  const RunReach run = run_reach(lesson, record, plot_index, secret);
  const Range x_range = x_axis_range(lesson, record, run, plot_index, time_span);
  chart.fixed_x = true;
  chart.x_low = x_range.low, chart.x_high = x_range.high;
  if (run.planned_here) chart.planned_points = run.planned->points[plot_index];

  add_record(chart, lesson, record, theme);
  if (record.over_time) add_slip_bands(chart, lesson, record, theme);
  // The theory is worked out whether it is shown or not, so that the y axis is the same before
  // and after the reveal (round_ends); kept back, it is not drawn, nor its error said. A
  // mystery's theory counts for nothing until its reveal.
  TheoryValues theory_values = add_theory(chart, lesson, plot_index, x_range, theme);
  if (secret) theory_values = {};
  std::vector<std::string> level_texts = level_texts_room(chart, lesson, plot_index, secret);
  if (!with_theory) {
    clear_theory(chart);
    chart.message.clear();
  }
  if (steady) keep_room_from_the_start(chart, record.plot, std::move(level_texts));
  const Range y_range = y_axis_range(lesson, record, run, plot_index, theory_values);
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
                      const std::function<std::string(const std::string&)>& script_words, bool steady, bool secret) {
  Chart chart = plot_chart(lesson, plot, time_span, theme, with_theory, steady, secret);
  if (script_words && !chart.message.empty()) chart.message = script_words(chart.message);
  return draw_chart(draw, corner, size, chart, theme, fonts);
}

}  // namespace frictionlab::draw
