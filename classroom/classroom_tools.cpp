// The classroom's measuring tools and force gauge: the Tools menu, their drawing in the world's
// lanes, and the gauge's plot under the world once the hand has pulled.
#include <cstdio>

#include "classroom/classroom.h"
#include "classroom/force_gauge.h"
#include "draw/overlays.h"
#include "draw/panels.h"
#include "draw/text_record.h"

namespace frictionlab::ui {

void Classroom::tools_menu() {
  const bool open = ImGui::BeginMenu("Tools");
  remember("Tools menu");
  if (!open) return;
  ToolSettings& on = window_.tools;
  const double now = playback_->lesson().scene().time();
  // Shown before the run, it is armed at once: the teacher's next key may well be Space.
  if (ImGui::MenuItem("Stopwatch (lesson time)", nullptr, &on.stopwatch)) {
    tools_.on = on;
    tools_.arm_stopwatch(now, playback_->playing());
  }
  remember("tool stopwatch");
  // Armed before the run, it has not started: the trial's menu offered to stop it, and a lap of 0 s.
  const bool armed = tools_.stopwatch.armed(now);
  if (ImGui::MenuItem(tools_.stopwatch.start_stop_words(now), "W")) {
    on.stopwatch = true;
    tools_.stopwatch.start_stop(now);
  }
  remember("stopwatch start");
  if (ImGui::MenuItem("Lap", "L", false, tools_.stopwatch.running() && !armed)) tools_.stopwatch.lap(now);
  remember("stopwatch lap");
  if (ImGui::MenuItem("Reset the stopwatch")) tools_.stopwatch.reset();
  remember("stopwatch reset");
  ImGui::Separator();
  ImGui::MenuItem("Distance marks along the surface", nullptr, &on.distance_marks);
  remember("tool distance marks");
  ImGui::MenuItem("Speed of the main body", nullptr, &on.speed);
  remember("tool speed");
  ImGui::MenuItem("Weight along and across a slope", nullptr, &on.weight_components);
  remember("tool weight components");
  ImGui::EndMenu();
}

void Classroom::world_tools(WorldToolsPass pass, ImDrawList* draw, const Camera& camera, std::size_t lane,
                            float newtons_to_pixels, LabelPlacer& labels) {
  const lessons::Lesson& lesson = playback_->lesson();
  const Scene& scene = lesson.scene();
  const float s = fonts_->scale;
  // The gauge in the lane its body is drawn in: the one whose strip holds the point held.
  bool gauge_here = false;
  if (const b2Body* held = scene.grabbed()) {
    const ImVec2 at = camera.to_screen(held->GetWorldCenter());
    gauge_here = (at.y >= camera.origin.y && at.y <= camera.origin.y + camera.size.y) || lane == hand_.drag_lane;
  }
  if (gauge_here && pass == WorldToolsPass::avoid) avoid_gauge(scene, camera, s, labels);
  const Theme& colours = theme(window_.theme);
  tools_.in_world(pass, draw, lesson, camera, lane, newtons_to_pixels, colours, *fonts_, labels);
  if (gauge_here && pass == WorldToolsPass::draw) draw_gauge(draw, scene, camera, colours, *fonts_, labels);
}

std::string Classroom::gauge_plot_title() const {
  // The plot shows the pulls together when the lesson pulled the body too.
  const Scene& scene = playback_->lesson().scene();
  const std::optional<GaugeFigures> figures = playback_->gauge().figures(scene.frame_step());
  if (!figures || figures->lesson_pulls.empty()) return "Force gauge (N)";
  return "Hand + " + figures->lesson_pulls + " (N)";
}

std::string Classroom::gauge_figures() const {
  const Scene& scene = playback_->lesson().scene();
  const std::optional<GaugeFigures> figures = playback_->gauge().figures(scene.frame_step());
  if (!figures) return "";
  // When the lesson pulled the body too, the figures are the pulls together, and say so.
  std::string text = figures->lesson_pulls.empty() ? "" : "hand + " + figures->lesson_pulls + ": ";
  // The peak is the breakaway's once it slid; before, the most it has held so far.
  if (!figures->peak) {
    text += "no peak (sliding when taken)";
  } else {
    text += (figures->broke_away ? "peak " : "held so far ") + format_quantity(*figures->peak, "N");
  }
  text += figures->plateau ? ",  sliding " + format_quantity(*figures->plateau, "N") : ",  sliding: not yet";
  return text;
}

void Classroom::gauge_plot(ImVec2 corner, ImVec2 size) {
  const lessons::Lesson& lesson = playback_->lesson();
  // The latest stretch's figures over the chart, as a class reads them off a sensor's screen.
  const std::string figures = gauge_figures();
  ImGui::SetCursorScreenPos(corner);
  // On one line: in the small font when the body's does not fit.
  const bool small = ImGui::CalcTextSize(figures.c_str()).x > size.x;
  if (small) ImGui::PushFont(fonts_->small);
  ImGui::PushTextWrapPos(0.0f);
  shown_text(figures.c_str());
  ImGui::PopTextWrapPos();
  if (small) ImGui::PopFont();
  const float used = ImGui::GetCursorScreenPos().y - corner.y;
  const Chart chart = gauge_chart(playback_->gauge(), lesson.scene().frame_step(), theme(window_.theme));
  draw_chart(ImGui::GetWindowDrawList(), ImVec2(corner.x, corner.y + used), ImVec2(size.x, std::max(1.0f, size.y - used)),
             chart, theme(window_.theme), *fonts_);
}

}  // namespace frictionlab::ui
