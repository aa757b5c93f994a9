// The Stability map tab (classroom/stability_map_tab.h): the map made for the lesson's mu_s and slope,
// its words, and its own window.
#include "classroom/stability_map_tab.h"

#include <algorithm>
#include <cmath>

#include "classroom_state/playback.h"
#include "draw/stability_chart.h"
#include "draw/text_record.h"
#include "physics/materials.h"
#include "physics/scenarios.h"
#include "physics/validation.h"

namespace frictionlab::classroom {
namespace {

struct Threshold {
  std::string name;
  double epsilon, h;
};

}  // namespace

void StabilityMapTab::update(const lessons::Lesson& lesson, const draw::HiddenValues& hidden) {
  mu_s_hidden = false;
  double mu_s = NAN, gravity = standard_gravity;
  std::string slope;
  std::vector<Threshold> thresholds;
  const StepSettings& settings = lesson.settings();
  const double h = 1.0 / settings.hz;  // the regularized law's step in a lesson: one a frame
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    if (parameter.coefficient == &static_coefficient && std::isnan(mu_s)) {
      // A mystery's μs would be read off the map's boundary: no map until it is revealed.
      if (hidden.hides(parameter.name)) {
        chart = draw::Chart{};
        words.clear();
        mu_s_hidden = true;
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
  words.clear();
  if (!(mu_s > 0.0)) {
    chart = draw::Chart{};
    return;
  }
  const std::vector<double> steps = logarithmic_range(1e-4, 1e-1, 13), epsilons = logarithmic_range(1e-4, 1e-1, 10);
  // Made once for each mu_s and slope: a few hundred short runs.
  const FrictionPair pair{mu_s, mu_s, 0.0, 0.0};
  if (made_for != std::pair{mu_s, gravity}) {
    made_for = {mu_s, gravity};
    cells = stability_map(pair, gravity, Integrator::semi_implicit_euler, steps, epsilons);
  }
  chart = draw::stability_map_chart("Regularized friction, semi-implicit Euler (Box2D's), \u03bcs " + validation::exact_text(mu_s) + slope,
                                         cells, pair, gravity, Integrator::semi_implicit_euler, epsilons);
  draw::ChartSeries marks{"this lesson's \u03b5 at its step", {}, IM_COL32(0, 90, 200, 255), false, draw::Marker::dot, {}};
  for (const Threshold& threshold : thresholds) {
    marks.points.push_back({threshold.epsilon, threshold.h});
    marks.labels.push_back(threshold.name);
    const double boundary = theoretical_boundary(pair, gravity, threshold.epsilon, Integrator::semi_implicit_euler);
    char line[200];
    std::snprintf(line, sizeof line, "%s %s m/s: %s at a %.3g ms step (boundary %.3g ms)", threshold.name.c_str(),
                  validation::exact_text(threshold.epsilon).c_str(), threshold.h > boundary ? "chatters" : "settles", threshold.h * 1e3,
                  boundary * 1e3);
    words.push_back(line);
  }
  chart.series.push_back({"this lesson's step", {{1e-4, h}, {1e-1, h}}, IM_COL32(0, 90, 200, 255), true, draw::Marker::none, {}});
  chart.series.push_back(marks);
}

void StabilityMapTab::draw_tab(const lessons::Lesson& lesson, const draw::HiddenValues& hidden, ControlPlaces& controls) {
  const bool open = draw::begin_tab("Stability###stability map");
  remember_item(controls, "Stability map tab");
  if (!open) return;
  update(lesson, hidden);
  if (chart.cells.empty()) {
    const char* none = mu_s_hidden ? "\u03bcs is a mystery until revealed: its map would give it away."
                                                         : "This lesson has no \u03bcs to draw the regularized law's map for.";
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", none);
    ImGui::PopTextWrapPos();
    draw::note_text(none);
  } else {
    const char* button = window_open ? "Hide the map" : "Show the map";
    if (ImGui::Button(button)) window_open = !window_open;
    remember_item(controls, "stability map");
    draw::note_text_centred(button, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
    // Beside the button when it fits: the projector's column is narrow for its large text.
    const char* what = "the regularized law here";
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(what).x <=
        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
      ImGui::SameLine();
    }
    ImGui::TextDisabled("%s", what);
    draw::note_text(what);
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& line : words) draw::shown_text(line.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndTabItem();
}

void StabilityMapTab::draw_window(const lessons::Lesson& lesson, const draw::HiddenValues& hidden, const draw::Theme& colours,
                                  const draw::Fonts& fonts) {
  if (!window_open) return;
  update(lesson, hidden);
  const float s = fonts.scale;
  ImGui::SetNextWindowSize(ImVec2(640.0f * s, 480.0f * s), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Stability map", &window_open) && !chart.cells.empty()) {
    const ImVec2 corner = ImGui::GetCursorScreenPos(), size = ImGui::GetContentRegionAvail();
    if (size.x > 40.0f && size.y > 40.0f) {
      draw_chart(ImGui::GetWindowDrawList(), corner, size, chart, colours, fonts);
      ImGui::Dummy(size);
    }
  }
  ImGui::End();
}

}  // namespace frictionlab::classroom
