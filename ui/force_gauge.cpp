#include "ui/force_gauge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/measuring_tools.h"
#include "ui/overlays.h"

namespace frictionlab::ui {

void GaugeRecord::after_step(const Scene& scene) {
  const b2Body* body = scene.grabbed();
  if (body == nullptr || scene.forces_applied().empty()) return;
  // The hand is always the scene's last applied force.
  const b2Vec2 hand = scene.forces_applied().back();
  bool lesson_pulls = false;
  const auto name_pull = [&](const std::string& name, b2Vec2 force) {
    if (force.LengthSquared() == 0.0f) return;
    lesson_pulls = true;
    if (lesson_pulls_.find(name) != std::string::npos) return;
    lesson_pulls_ += (lesson_pulls_.empty() ? "" : " and ") + name;
  };
  for (std::size_t i = 0; i + 1 < scene.applied_forces().size(); ++i) {
    if (scene.applied_forces()[i].body == body) name_pull(scene.applied_forces()[i].name, scene.forces_applied()[i]);
  }
  for (std::size_t i = 0; i < scene.springs().size(); ++i) {
    const Spring& spring = scene.springs()[i];
    if (spring.body == body || spring.other == body) name_pull(spring.name, scene.spring_forces_applied()[i]);
  }
  // Every pull on the body as the step applied it, the hand's among them: what friction answers
  // while the body sticks.
  b2Vec2 total{0.0f, 0.0f};
  for (const ForceOnBody& force : forces_on(scene, body)) {
    if (force.kind == ForceKind::tension) name_pull("rope", force.force);
    if (force.kind == ForceKind::applied || force.kind == ForceKind::spring || force.kind == ForceKind::tension) {
      total += force.force;
    }
  }
  // Along the surface it stands on; off any, along the hand's pull.
  b2Vec2 along = hand;
  if (const std::optional<Surface> surface = surface_under(scene, body)) along = surface->along;
  const float size = along.Normalize();
  const double pull = size > 0.0f ? static_cast<double>(b2Dot(total, along)) : static_cast<double>(total.Length());
  samples_.push_back({scene.frame(), scene.time(), static_cast<double>(hand.Length()), pull, lesson_pulls,
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

std::size_t GaugeRecord::latest_stretch_start() const {
  // Back from the last sample while the frames run on without a gap.
  std::size_t first = samples_.empty() ? 0 : samples_.size() - 1;
  while (first > 0 && samples_[first].frame == samples_[first - 1].frame + 1) --first;
  return first;
}

std::optional<GaugeFigures> GaugeRecord::figures(double frame_step) const {
  if (samples_.empty()) return std::nullopt;
  const std::size_t first = latest_stretch_start();
  GaugeFigures figures;
  bool lesson_pulled = false;
  for (std::size_t i = first; i < samples_.size(); ++i) lesson_pulled = lesson_pulled || samples_[i].lesson_pulls;
  // The gauge alone when the hand pulled alone: the pull along the surface then differs from it
  // only by a slant the hand gave it.
  const auto pull = [&](const GaugeSample& sample) { return lesson_pulled ? std::abs(sample.pull) : sample.force; };
  if (lesson_pulled) figures.lesson_pulls = lesson_pulls_;
  // The first step that held (a body taken while sliding may come to rest and break away
  // later), and the step it broke away in: the first after that one to end slipping.
  std::size_t held = first;
  while (held < samples_.size() && samples_[held].slipping) ++held;
  std::size_t end = samples_.size();
  for (std::size_t i = held; i < samples_.size(); ++i) {
    if (samples_[i].slipping) {
      end = i + 1;
      figures.broke_away = true;
      break;
    }
  }
  if (held < samples_.size()) {
    for (std::size_t i = held; i < end; ++i) {
      if (!figures.peak || pull(samples_[i]) > *figures.peak) {
        figures.peak = pull(samples_[i]);
        figures.peak_time = samples_[i].t;
      }
    }
  }
  // Sliding from the start of the stretch: the plateau counts from there.
  const double slid_from = figures.peak ? figures.peak_time : samples_[first].t;
  double sum = 0.0;
  long count = 0;
  for (std::size_t i = first; i < samples_.size(); ++i) {
    const GaugeSample& sample = samples_[i];
    if (sample.t < slid_from + settle_time - 0.5 * frame_step || !sample.slipping) continue;
    if (count == 0) figures.plateau_from = sample.t;
    figures.plateau_to = sample.t;
    sum += pull(sample);
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

GaugeShape gauge_shape(const Scene& scene, const Camera& camera, float scale) {
  const b2Body* body = scene.grabbed();
  GaugeShape shape{};
  shape.hook = camera.to_screen(body->GetWorldPoint(scene.applied_forces().back().local_point));
  shape.hand = camera.to_screen(scene.grab_hand());
  // The ring is where the hand is: under the pointer, as the mouse moved it last.
  shape.ring = camera.to_screen(scene.grab_target());
  shape.half_width = 7.0f * scale;
  shape.ring_radius = 5.0f * scale;
  ImVec2 along = sub(shape.ring, shape.hook);
  if (length(along) < 2.0f) {
    // Slack: along the force it applies, or level when it applies none.
    const b2Vec2 force = scene.forces_applied().back();
    along = ImVec2(force.x, -force.y);
    if (length(along) < 1e-6f) along = ImVec2(1.0f, 0.0f);
  }
  shape.along = mul(along, 1.0f / length(along));
  // The case ends at the ring and reaches back towards the hook, leaving the coil a little room.
  const float room = length(sub(shape.ring, shape.hook)) - shape.ring_radius - 12.0f * scale;
  const float case_length = std::clamp(room, 0.0f, 56.0f * scale);
  const ImVec2 case_end = sub(shape.ring, mul(shape.along, shape.ring_radius));
  shape.case_start = sub(case_end, mul(shape.along, case_length));
  return shape;
}

namespace {

std::string reading_text(const Scene& scene) {
  return "gauge " + format_quantity(static_cast<double>(scene.forces_applied().back().Length()), "N");
}

}  // namespace

void avoid_gauge(const Scene& scene, const Camera& camera, float scale, LabelPlacer& labels) {
  if (scene.grabbed() == nullptr || scene.applied_forces().empty()) return;
  const GaugeShape shape = gauge_shape(scene, camera, scale);
  // The scale's spring, from the point held to the hand's end of it, and the case with its ring.
  labels.avoid(DrawnSegment{shape.hook, shape.hand, shape.half_width});
  labels.avoid(DrawnSegment{shape.case_start, add(shape.ring, mul(shape.along, shape.ring_radius)),
                            shape.half_width + 2.0f * scale});
}

void draw_gauge(ImDrawList* draw, const Scene& scene, const Camera& camera, const Theme& theme, const Fonts& fonts,
                LabelPlacer& labels) {
  if (scene.grabbed() == nullptr || scene.applied_forces().empty()) return;
  const float s = fonts.scale;
  const GaugeShape shape = gauge_shape(scene, camera, s);
  const ImVec2 across(-shape.along.y, shape.along.x);
  // The coil: a zigzag from the hook into the case, as many turns however far it stretches.
  const float stretch = length(sub(shape.case_start, shape.hook));
  if (stretch >= 3.0f) {
    constexpr int turns = 10;
    std::vector<ImVec2> coil;
    coil.push_back(shape.hook);
    for (int i = 1; i < 2 * turns; ++i) {
      const float f = static_cast<float>(i) / (2.0f * turns);
      const float side = (i % 2 == 0 ? -1.0f : 1.0f) * 0.7f * shape.half_width;
      coil.push_back(add(add(shape.hook, mul(sub(shape.case_start, shape.hook), f)), mul(across, side)));
    }
    coil.push_back(shape.case_start);
    draw->AddPolyline(coil.data(), static_cast<int>(coil.size()), theme.spring, 0, 1.6f * s);
  }
  draw->AddCircleFilled(shape.hook, 3.5f * s, theme.hand);
  // The case the hand holds, with a scale of marks along it, and the ring under the pointer.
  const ImVec2 case_end = sub(shape.ring, mul(shape.along, shape.ring_radius));
  const float case_length = length(sub(case_end, shape.case_start));
  if (case_length >= 2.0f * s) {
    const ImVec2 corners[4] = {add(shape.case_start, mul(across, shape.half_width)), add(case_end, mul(across, shape.half_width)),
                               sub(case_end, mul(across, shape.half_width)), sub(shape.case_start, mul(across, shape.half_width))};
    draw->AddConvexPolyFilled(corners, 4, theme.panel);
    draw->AddPolyline(corners, 4, theme.hand, ImDrawFlags_Closed, 2.0f * s);
    for (int mark = 1; mark < 6; ++mark) {
      const ImVec2 at = add(shape.case_start, mul(shape.along, case_length * static_cast<float>(mark) / 6.0f));
      draw->AddLine(add(at, mul(across, 0.5f * shape.half_width)), sub(at, mul(across, 0.5f * shape.half_width)),
                    theme.hand, 1.0f * s);
    }
  }
  draw->AddCircle(shape.ring, shape.ring_radius, theme.hand, 0, 2.0f * s);
  // Its reading on the case's upper side, as a scale's window shows it, or the nearest free place.
  const std::string text = reading_text(scene);
  const ImVec2 size = fonts.body->CalcTextSizeA(fonts.body->FontSize, 1e6f, 0.0f, text.c_str());
  const ImVec2 middle = mul(add(shape.case_start, shape.ring), 0.5f);
  const ImVec2 up = across.y <= 0.0f ? across : mul(across, -1.0f);
  const ImVec2 wanted = add(middle, mul(up, shape.half_width + 6.0f * s + 0.5f * std::abs(up.y) * size.y +
                                                0.5f * std::abs(up.x) * size.x));
  // Off the body it pulls, as the other tools' readings are: the hand holds the case over it.
  const ImVec2 at = labels.place(wanted, ImVec2(size.x + 6.0f, size.y + 2.0f), text, true);
  draw_label(draw, fonts.body, at, theme.text, theme.panel, text.c_str());
}

Chart gauge_chart(const GaugeRecord& record, double frame_step, const Theme& theme) {
  Chart chart;
  chart.title = "Force gauge";
  chart.plain = true;
  chart.legend = Chart::Legend::none;
  chart.y_tick_count = 4;
  chart.x_tick_count = 0;
  chart.x_label = "time (s)";
  chart.y_label = "";  // the panel's title says it: "Force gauge (N)"
  // The latest stretch alone: a lesson that runs for minutes, or pulls long apart, would squeeze
  // a pull of a few seconds into a line.
  const std::vector<GaugeSample>& samples = record.samples();
  const std::size_t first = record.latest_stretch_start();
  // One line, as the figures over it are taken: the gauge's reading, or the hand's pull and the
  // lesson's together when the lesson pulled the body too (the scale in the world reads the
  // hand's alone). No legend to cover it: the panel's title and figures say which.
  bool lesson_pulled = false;
  for (std::size_t i = first; i < samples.size(); ++i) lesson_pulled = lesson_pulled || samples[i].lesson_pulls;
  ChartSeries reading;
  reading.name = lesson_pulled ? "hand + " + record.lesson_pulls() : "gauge";
  reading.colour = theme.hand;
  double highest = 0.0, latest = 0.0;
  for (std::size_t i = first; i < samples.size(); ++i) {
    const GaugeSample& sample = samples[i];
    const double shown = lesson_pulled ? std::abs(sample.pull) : sample.force;
    reading.points.push_back({sample.t, shown});
    highest = std::max(highest, shown);
    latest = sample.t;
  }
  chart.series.push_back(std::move(reading));
  // The slip shaded, as the lesson's plots shade it, where the hand was pulling.
  for (std::size_t i = first; i < samples.size();) {
    if (!samples[i].slipping) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < samples.size() && samples[j + 1].slipping) ++j;
    chart.bands.push_back({samples[i].t - frame_step, samples[j].t});
    i = j + 1;
  }
  chart.band_colour = theme.slip_band;
  chart.band_name = "slipping";
  chart.mark_now = true;
  chart.now_colour = theme.now_marker;
  chart.now_x = latest;
  // From a little before the hand took hold to the latest sample.
  const double start = samples.empty() ? 0.0 : samples[first].t - frame_step;
  const double span = std::max(latest - start, 1.0);
  chart.fixed_x = true;
  chart.x_low = std::max(0.0, start - 0.1 * span);
  chart.x_high = std::max(latest, start + span) + 0.05 * span;
  chart.fixed_y = true;
  chart.y_low = 0.0;
  chart.y_high = std::max(1.0, 1.15 * highest);
  return chart;
}

}  // namespace frictionlab::ui
