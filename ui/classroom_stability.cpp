// The stability map: where the regularized law settles or chatters for a block with this
// lesson's mu_s (on its slope, when it has one), at Box2D's integrator, with the lesson's own
// step and threshold speeds marked, so a class sees which side of the boundary it is on. The
// tab says it in words and opens the map in a window of its own (the tab is too small for it).
#include <algorithm>
#include <cmath>

#include "physics/scenarios.h"
#include "ui/panels.h"
#include "ui/classroom.h"
#include "ui/text_record.h"
#include "ui/stability_chart.h"

namespace frictionlab::ui {
namespace {

struct Threshold {
  std::string name;
  double epsilon, h;
};

}  // namespace

void Classroom::update_stability_chart() {
  const lessons::Lesson& lesson = playback_->lesson();
  double mu_s = NAN, gravity = standard_gravity;
  std::string slope;
  std::vector<Threshold> thresholds;
  const StepSettings& settings = lesson.settings();
  const double h = 1.0 / settings.hz;  // the regularized law's step in a lesson: one a frame
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    if (parameter.coefficient == "mu_s" && std::isnan(mu_s)) {
      // A mystery's μs would be read off the map's boundary: no map until it is revealed.
      if (mystery_ && mystery_->hides(parameter.name)) {
        stability_chart_ = Chart{};
        stability_words_.clear();
        return;
      }
      mu_s = parameter.value;
    }
    // A block on a slope presses on it with g·cos θ: the boundary moves with it.
    if (parameter.name == "angle" && parameter.unit == "\u00b0") {
      gravity = standard_gravity * std::cos(parameter.value * M_PI / 180.0);
      slope = ", on the " + parameter.shown() + " slope";
    }
    if (parameter.name.find("epsilon") != std::string::npos) thresholds.push_back({parameter.name, parameter.value, h});
  }
  if (settings.treatment == FrictionTreatment::regularized) {
    thresholds.push_back({"treatment", settings.threshold_speed, h / settings.substeps});
  }
  stability_words_.clear();
  if (!(mu_s > 0.0)) {
    stability_chart_ = Chart{};
    return;
  }
  const std::vector<double> steps = logarithmic_range(1e-4, 1e-1, 13), epsilons = logarithmic_range(1e-4, 1e-1, 10);
  // Made once for each mu_s and slope: a few hundred short runs.
  const FrictionPair pair{mu_s, mu_s, 0.0, 0.0};
  if (stability_for_ != std::pair{mu_s, gravity}) {
    stability_for_ = {mu_s, gravity};
    stability_cells_ = stability_map(pair, gravity, Integrator::semi_implicit_euler, steps, epsilons);
  }
  stability_chart_ = stability_map_chart("Regularized friction, semi-implicit Euler (Box2D's), \u03bcs " + exact_text(mu_s) + slope,
                                         stability_cells_, pair, gravity, Integrator::semi_implicit_euler, epsilons);
  ChartSeries marks{"this lesson's \u03b5 at its step", {}, IM_COL32(0, 90, 200, 255), false, Marker::dot, {}};
  for (const Threshold& threshold : thresholds) {
    marks.points.push_back({threshold.epsilon, threshold.h});
    marks.labels.push_back(threshold.name);
    const double boundary = theoretical_boundary(pair, gravity, threshold.epsilon, Integrator::semi_implicit_euler);
    char line[200];
    std::snprintf(line, sizeof line, "%s %s m/s: %s at a %.3g ms step (boundary %.3g ms)", threshold.name.c_str(),
                  exact_text(threshold.epsilon).c_str(), threshold.h > boundary ? "chatters" : "settles", threshold.h * 1e3,
                  boundary * 1e3);
    stability_words_.push_back(line);
  }
  stability_chart_.series.push_back({"this lesson's step", {{1e-4, h}, {1e-1, h}}, IM_COL32(0, 90, 200, 255), true, Marker::none, {}});
  stability_chart_.series.push_back(marks);
}

void Classroom::stability_map_tab() {
  const bool open = begin_tab("Stability###stability map");
  remember("Stability map tab");
  if (!open) return;
  update_stability_chart();
  if (stability_chart_.cells.empty()) {
    const char* none = mystery_ && !mystery_->revealed() ? "\u03bcs is a mystery until revealed: its map would give it away."
                                                         : "This lesson has no \u03bcs to draw the regularized law's map for.";
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", none);
    ImGui::PopTextWrapPos();
    note_text(none);
  } else {
    if (ImGui::Button(stability_window_ ? "Hide the map" : "Show the map")) stability_window_ = !stability_window_;
    remember("stability map");
    ImGui::SameLine();
    ImGui::TextDisabled("the regularized law here");
    note_text("the regularized law here");
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& line : stability_words_) shown_text(line.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndTabItem();
}

void Classroom::stability_map_window() {
  if (!stability_window_) return;
  update_stability_chart();
  const float s = fonts_->scale;
  ImGui::SetNextWindowSize(ImVec2(640.0f * s, 480.0f * s), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Stability map", &stability_window_) && !stability_chart_.cells.empty()) {
    const ImVec2 corner = ImGui::GetCursorScreenPos(), size = ImGui::GetContentRegionAvail();
    if (size.x > 40.0f && size.y > 40.0f) {
      draw_chart(ImGui::GetWindowDrawList(), corner, size, stability_chart_, theme(window_.theme), *fonts_);
      ImGui::Dummy(size);
    }
  }
  ImGui::End();
}

}  // namespace frictionlab::ui
