// The Simulation menu (classroom/simulation_menu.h).
#include "classroom/simulation_menu.h"

#include <imgui.h>

#include <string>
#include <utility>

namespace frictionlab::classroom {

SimulationChoice simulation_menu(const StepSettings& settings, const LessonLock& lock, ControlPlaces& controls) {
  SimulationChoice choice;
  const bool open = ImGui::BeginMenu("Simulation");
  remember_item(controls, "Simulation menu");
  if (!open) return choice;
  StepSettings chosen = settings;
  const auto choose = [&](bool picked, bool differs, auto set) {
    if (!picked || !differs) return;
    set(chosen);
    choice.settings = chosen;
  };
  ImGui::TextDisabled("Friction treatment");
  const std::pair<FrictionTreatment, const char*> treatments[] = {
      {FrictionTreatment::stick_slip, "stick-slip (converges to Coulomb)"},
      {FrictionTreatment::threshold, "threshold (games' speed switch)"},
      {FrictionTreatment::regularized, "regularized (smooth, creeps)"},
      {FrictionTreatment::box2d, "box2d (one coefficient)"}};
  for (const auto& [treatment, label] : treatments) {
    const bool picked = ImGui::MenuItem(label, nullptr, settings.treatment == treatment, lock.shown("friction"));
    remember_item(controls, "treatment " + std::string(treatment_name(treatment)));
    choose(picked, settings.treatment != treatment, [treatment = treatment](StepSettings& to) { to.treatment = treatment; });
  }
  ImGui::Separator();
  ImGui::TextDisabled("Step rate");
  for (const double hz : {30.0, 60.0, 120.0, 240.0, 480.0, 960.0, 1920.0}) {
    const std::string label = std::to_string(static_cast<int>(hz)) + " Hz";
    const bool picked = ImGui::MenuItem(label.c_str(), nullptr, settings.hz == hz, lock.shown("hz"));
    remember_item(controls, "hz " + label.substr(0, label.size() - 3));
    choose(picked, settings.hz != hz, [hz](StepSettings& to) { to.hz = hz; });
  }
  ImGui::Separator();
  ImGui::TextDisabled("Sub-steps per step");
  for (const int substeps : {1, 2, 4, 8, 16}) {
    const std::string label = std::to_string(substeps);
    const bool picked = ImGui::MenuItem(label.c_str(), nullptr, settings.substeps == substeps, lock.shown("substeps"));
    remember_item(controls, "substeps " + label);
    choose(picked, settings.substeps != substeps, [substeps](StepSettings& to) { to.substeps = substeps; });
  }
  ImGui::Separator();
  choice.reset = ImGui::MenuItem("Reset to t = 0", "R");
  ImGui::EndMenu();
  return choice;
}

}  // namespace frictionlab::classroom
