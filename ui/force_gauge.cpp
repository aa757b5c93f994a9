#include "ui/force_gauge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/overlays.h"

namespace frictionlab::ui {

void GaugeRecord::after_step(const Scene& scene) {
  if (scene.grabbed() == nullptr || scene.forces_applied().empty()) return;
  // The hand is always the scene's last applied force.
  const b2Vec2 force = scene.forces_applied().back();
  samples_.push_back({scene.frame(), scene.time(), static_cast<double>(force.Length()),
                      !scene.slipping().empty() && scene.slipping().back() != 0});
}

std::vector<HandStretch> GaugeRecord::stretches(double frame_step) const {
  std::vector<HandStretch> found;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const bool continues = i > 0 && samples_[i].frame == samples_[i - 1].frame + 1;
    if (!continues) found.push_back({samples_[i].t - frame_step, samples_[i].t});
    found.back().to = samples_[i].t;
  }
  return found;
}

std::optional<GaugeFigures> GaugeRecord::figures(double frame_step) const {
  if (samples_.empty()) return std::nullopt;
  // The latest stretch: back from the last sample while the frames run on without a gap.
  std::size_t first = samples_.size() - 1;
  while (first > 0 && samples_[first].frame == samples_[first - 1].frame + 1) --first;
  GaugeFigures figures;
  figures.peak = -1.0;
  for (std::size_t i = first; i < samples_.size(); ++i) {
    if (samples_[i].force > figures.peak) {
      figures.peak = samples_[i].force;
      figures.peak_time = samples_[i].t;
    }
  }
  double sum = 0.0;
  long count = 0;
  for (std::size_t i = first; i < samples_.size(); ++i) {
    const GaugeSample& sample = samples_[i];
    if (sample.t < figures.peak_time + settle_time - 0.5 * frame_step || !sample.slipping) continue;
    if (count == 0) figures.plateau_from = sample.t;
    figures.plateau_to = sample.t;
    sum += sample.force;
    ++count;
  }
  // A tenth of a second of sliding at least, or there is no plateau to speak of yet.
  if (count > 0 && figures.plateau_to - figures.plateau_from >= 0.1 - 0.5 * frame_step) {
    figures.plateau = sum / static_cast<double>(count);
  }
  return figures;
}

std::string stretches_text(const std::vector<HandStretch>& stretches) {
  std::string text;
  for (const HandStretch& stretch : stretches) {
    char line[64];
    std::snprintf(line, sizeof line, "%.2f\u2013%.2f s", std::max(0.0, stretch.from), stretch.to);
    text += (text.empty() ? "hand-pulled " : ", ") + std::string(line);
  }
  return text;
}

namespace {

// Where the gauge lies on the screen: its hook on the body, the hand's end of the coil, and its
// case beyond the hand, along the pull.
struct GaugeShape {
  ImVec2 hook, hand, case_end, along;
  float half_width;
};

GaugeShape gauge_shape(const Scene& scene, const Camera& camera, float scale) {
  const b2Body* body = scene.grabbed();
  GaugeShape shape{};
  shape.hook = camera.to_screen(body->GetWorldPoint(scene.applied_forces().back().local_point));
  shape.hand = camera.to_screen(scene.grab_hand());
  ImVec2 along = sub(shape.hand, shape.hook);
  if (length(along) < 2.0f) {
    // Slack: along the force it applies, or level when it applies none.
    const b2Vec2 force = scene.forces_applied().back();
    along = ImVec2(force.x, -force.y);
    if (length(along) < 1e-6f) along = ImVec2(1.0f, 0.0f);
  }
  shape.along = mul(along, 1.0f / length(along));
  shape.case_end = add(shape.hand, mul(shape.along, 56.0f * scale));
  shape.half_width = 7.0f * scale;
  return shape;
}

std::string reading_text(const Scene& scene) {
  return "gauge " + format_quantity(static_cast<double>(scene.forces_applied().back().Length()), "N");
}

}  // namespace

void avoid_gauge(const Scene& scene, const Camera& camera, float scale, LabelPlacer& labels) {
  if (scene.grabbed() == nullptr || scene.applied_forces().empty()) return;
  const GaugeShape shape = gauge_shape(scene, camera, scale);
  labels.avoid(DrawnSegment{shape.hook, shape.hand, shape.half_width});
  labels.avoid(DrawnSegment{shape.hand, shape.case_end, shape.half_width + 2.0f * scale});
}

void draw_gauge(ImDrawList* draw, const Scene& scene, const Camera& camera, const Theme& theme, const Fonts& fonts,
                LabelPlacer& labels) {
  if (scene.grabbed() == nullptr || scene.applied_forces().empty()) return;
  const float s = fonts.scale;
  const GaugeShape shape = gauge_shape(scene, camera, s);
  const ImVec2 across(-shape.along.y, shape.along.x);
  // The coil: a zigzag from the hook to the hand's end, as many turns however far it stretches.
  const float stretch = length(sub(shape.hand, shape.hook));
  if (stretch >= 3.0f) {
    constexpr int turns = 10;
    std::vector<ImVec2> coil;
    coil.push_back(shape.hook);
    for (int i = 1; i < 2 * turns; ++i) {
      const float f = static_cast<float>(i) / (2.0f * turns);
      const float side = (i % 2 == 0 ? -1.0f : 1.0f) * 0.7f * shape.half_width;
      coil.push_back(add(add(shape.hook, mul(sub(shape.hand, shape.hook), f)), mul(across, side)));
    }
    coil.push_back(shape.hand);
    draw->AddPolyline(coil.data(), static_cast<int>(coil.size()), theme.spring, 0, 1.6f * s);
  }
  draw->AddCircleFilled(shape.hook, 3.5f * s, theme.hand);
  // The case the hand holds, with a scale of marks along it, and the ring at its far end.
  const ImVec2 corners[4] = {add(shape.hand, mul(across, shape.half_width)), add(shape.case_end, mul(across, shape.half_width)),
                             sub(shape.case_end, mul(across, shape.half_width)), sub(shape.hand, mul(across, shape.half_width))};
  draw->AddConvexPolyFilled(corners, 4, theme.panel);
  draw->AddPolyline(corners, 4, theme.hand, ImDrawFlags_Closed, 2.0f * s);
  for (int mark = 1; mark < 6; ++mark) {
    const ImVec2 at = add(shape.hand, mul(shape.along, 56.0f * s * static_cast<float>(mark) / 6.0f));
    draw->AddLine(add(at, mul(across, 0.5f * shape.half_width)), sub(at, mul(across, 0.5f * shape.half_width)),
                  theme.hand, 1.0f * s);
  }
  draw->AddCircle(add(shape.case_end, mul(shape.along, 5.0f * s)), 5.0f * s, theme.hand, 0, 2.0f * s);
  // Its reading on the case's upper side, as a scale's window shows it, or the nearest free place.
  const std::string text = reading_text(scene);
  const ImVec2 size = fonts.body->CalcTextSizeA(fonts.body->FontSize, 1e6f, 0.0f, text.c_str());
  const ImVec2 middle = mul(add(shape.hand, shape.case_end), 0.5f);
  const ImVec2 up = across.y <= 0.0f ? across : mul(across, -1.0f);
  const ImVec2 wanted = add(middle, mul(up, shape.half_width + 6.0f * s + 0.5f * std::abs(up.y) * size.y +
                                                0.5f * std::abs(up.x) * size.x));
  const ImVec2 at = labels.place(wanted, ImVec2(size.x + 6.0f, size.y + 2.0f));
  draw_label(draw, fonts.body, at, theme.text, theme.panel, text.c_str());
}

Chart gauge_chart(const GaugeRecord& record, double frame_step, const Theme& theme) {
  Chart chart;
  chart.title = "Force gauge";
  chart.plain = true;
  // One line and the slip's shading, as the lesson's plots shade it: no legend to cover them.
  chart.legend = Chart::Legend::none;
  chart.y_tick_count = 4;
  chart.x_tick_count = 0;
  chart.x_label = "time (s)";
  chart.y_label = "";  // the panel's title says it: "Force gauge (N)"
  ChartSeries reading;
  reading.name = "gauge";
  reading.colour = theme.hand;
  double highest = 0.0, latest = 0.0;
  for (std::size_t i = 0; i < record.samples().size(); ++i) {
    const GaugeSample& sample = record.samples()[i];
    // A stretch's line starts afresh: no line across the time the hand let go.
    if (i > 0 && sample.frame != record.samples()[i - 1].frame + 1) reading.points.push_back({sample.t, NAN});
    reading.points.push_back({sample.t, sample.force});
    highest = std::max(highest, sample.force);
    latest = sample.t;
  }
  chart.series.push_back(std::move(reading));
  // The slip shaded, as the lesson's plots shade it, where the hand was pulling.
  for (std::size_t i = 0; i < record.samples().size();) {
    if (!record.samples()[i].slipping) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < record.samples().size() && record.samples()[j + 1].slipping &&
           record.samples()[j + 1].frame == record.samples()[j].frame + 1) {
      ++j;
    }
    chart.bands.push_back({record.samples()[i].t - frame_step, record.samples()[j].t});
    i = j + 1;
  }
  chart.band_colour = theme.slip_band;
  chart.band_name = "slipping";
  chart.mark_now = true;
  chart.now_colour = theme.now_marker;
  chart.now_x = latest;
  // From a little before the hand took hold to now: a lesson that runs for minutes would squeeze
  // a pull of a few seconds into a line.
  const double first = record.empty() ? 0.0 : record.samples().front().t - frame_step;
  const double span = std::max(latest - first, 1.0);
  chart.fixed_x = true;
  chart.x_low = std::max(0.0, first - 0.1 * span);
  chart.x_high = std::max(latest, first + span) + 0.05 * span;
  chart.fixed_y = true;
  chart.y_low = 0.0;
  chart.y_high = std::max(1.0, 1.15 * highest);
  return chart;
}

}  // namespace frictionlab::ui
