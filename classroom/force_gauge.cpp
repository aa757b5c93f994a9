#include "classroom/force_gauge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "classroom/measuring_tools.h"
#include "draw/overlays.h"
#include "draw/text_record.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

// The screen-point arithmetic of draw/drawing.h, used throughout here.
using draw::add;
using draw::length;
using draw::mul;
using draw::sub;

GaugeShape gauge_shape(const Scene& scene, const draw::Camera& camera, float scale) {
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
  return "gauge " + draw::format_quantity(static_cast<double>(scene.forces_applied().back().Length()), "N");
}

}  // namespace

void avoid_gauge(const Scene& scene, const draw::Camera& camera, float scale, draw::LabelPlacer& labels) {
  if (scene.grabbed() == nullptr || scene.applied_forces().empty()) return;
  const GaugeShape shape = gauge_shape(scene, camera, scale);
  // The scale's spring, from the point held to the hand's end of it, and the case with its ring.
  labels.avoid(draw::DrawnSegment{shape.hook, shape.hand, shape.half_width});
  labels.avoid(draw::DrawnSegment{shape.case_start, add(shape.ring, mul(shape.along, shape.ring_radius)),
                            shape.half_width + 2.0f * scale});
}

void draw_gauge(ImDrawList* draw, const Scene& scene, const draw::Camera& camera, const draw::Theme& theme, const draw::Fonts& fonts,
                draw::LabelPlacer& labels) {
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
  draw::draw_label(draw, fonts.body, at, theme.text, theme.panel, text.c_str());
}

draw::Chart gauge_chart(const classroom_state::GaugeRecord& record, double frame_step, const draw::Theme& theme,
                        bool steady) {
  draw::Chart chart;
  chart.title = "Force gauge";
  chart.plain = true;
  chart.legend = draw::Chart::Legend::none;
  chart.y_tick_count = 4;
  // On a projector it is laid out as the lesson's plots are on their pages, ticks as fine as its
  // height reads and the x axis' name ending the tick labels' line: under them it took a line of
  // the data's height, and the guide says it ends the line (a teacher's trial, issue 31).
  chart.steady = steady;
  if (steady) chart.y_tick_spacing = draw::plot_tick_spacing_points(true);
  chart.x_tick_count = 0;
  chart.x_label = "time (s)";
  chart.y_label = "";  // the panel's title says it: "Force gauge (N)"
  // The latest stretch alone: a lesson that runs for minutes, or pulls long apart, would squeeze
  // a pull of a few seconds into a line.
  const std::vector<classroom_state::GaugeSample>& samples = record.samples();
  const std::size_t first = record.latest_stretch_start();
  // One line, as the figures over it are taken: the gauge's reading, or the hand's pull and the
  // lesson's together when the lesson pulled the body too (the scale in the world reads the
  // hand's alone). No legend to cover it: the panel's title and figures say which.
  bool lesson_pulled = false;
  for (std::size_t i = first; i < samples.size(); ++i) lesson_pulled = lesson_pulled || samples[i].lesson_pulls;
  draw::ChartSeries reading;
  reading.name = lesson_pulled ? "hand + " + record.lesson_pulls() : "gauge";
  reading.colour = theme.hand;
  double highest = 0.0, latest = 0.0;
  for (std::size_t i = first; i < samples.size(); ++i) {
    const classroom_state::GaugeSample& sample = samples[i];
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

std::string gauge_plot_title(const classroom_state::GaugeRecord& record, double frame_step) {
  // The plot shows the pulls together when the lesson pulled the body too.
  const std::optional<classroom_state::GaugeFigures> figures = record.figures(frame_step);
  if (!figures || figures->lesson_pulls.empty()) return "Force gauge (N)";
  return "Hand + " + figures->lesson_pulls + " (N)";
}

std::string gauge_figures(const classroom_state::GaugeRecord& record, double frame_step) {
  const std::optional<classroom_state::GaugeFigures> figures = record.figures(frame_step);
  if (!figures) return "";
  // When the lesson pulled the body too, the figures are the pulls together, and say so.
  std::string text = figures->lesson_pulls.empty() ? "" : "hand + " + figures->lesson_pulls + ": ";
  // The peak is the breakaway's once it slid; before, the most it has held so far.
  if (!figures->peak) {
    text += "no peak (sliding when taken)";
  } else {
    text += (figures->broke_away ? "peak " : "held so far ") + draw::format_quantity(*figures->peak, "N");
  }
  text += figures->plateau ? ",  sliding " + draw::format_quantity(*figures->plateau, "N") : ",  sliding: not yet";
  return text;
}

draw::ChartLayout draw_gauge_plot(ImVec2 corner, ImVec2 size, const classroom_state::GaugeRecord& record, double frame_step,
                                  const draw::Theme& theme, const draw::Fonts& fonts, bool steady) {
  const std::string figures = gauge_figures(record, frame_step);
  ImGui::SetCursorScreenPos(corner);
  // On one line: in the small font when the body's does not fit.
  const bool small = ImGui::CalcTextSize(figures.c_str()).x > size.x;
  if (small) ImGui::PushFont(fonts.small);
  ImGui::PushTextWrapPos(0.0f);
  draw::shown_text(figures.c_str());
  ImGui::PopTextWrapPos();
  if (small) ImGui::PopFont();
  const float used = ImGui::GetCursorScreenPos().y - corner.y;
  const draw::Chart chart = gauge_chart(record, frame_step, theme, steady);
  return draw_chart(ImGui::GetWindowDrawList(), ImVec2(corner.x, corner.y + used),
                    ImVec2(size.x, std::max(1.0f, size.y - used)), chart, theme, fonts);
}

}  // namespace frictionlab::classroom
