// The View menu (classroom/view_menu.h).
#include "classroom/view_menu.h"

#include <imgui.h>

#include <algorithm>

#include "lessons/runtime/class_words.h"

namespace frictionlab::classroom {

std::string next_forces_on(const ForcesShown& shown) {
  if (shown.bodies.size() < 2) return "";
  const auto at = std::find(shown.bodies.begin(), shown.bodies.end(), shown.on);
  if (shown.on.empty() || at == shown.bodies.end()) return shown.bodies.front();
  return at + 1 == shown.bodies.end() ? "" : *(at + 1);
}

ViewMenuChoice view_menu(const WindowSettings& window, const ForcesShown& forces, ControlPlaces& controls,
                         const std::function<void()>& predictions_items) {
  ViewMenuChoice choice;
  const bool open = ImGui::BeginMenu("View");
  remember_item(controls, "View menu");
  if (!open) return choice;
  // Each item ticked as the window is now; a click flips it, as its key does.
  bool dark = window.theme == draw::ThemeName::dark;
  if (ImGui::MenuItem("Dark theme", "D", &dark)) choice.theme = dark ? draw::ThemeName::dark : draw::ThemeName::light;
  remember_item(controls, "Dark theme");
  bool projector = window.projector;
  if (ImGui::MenuItem("Projector mode", "P", &projector)) choice.projector = true;
  remember_item(controls, "Projector mode");
  if (ImGui::MenuItem("Full screen", "F11")) choice.full_screen = true;
  remember_item(controls, "Full screen");
  bool help = window.help;
  if (ImGui::MenuItem("Help", "F1", &help)) choice.help = true;
  remember_item(controls, "Help");
  // Greyed where the lesson has one moving body: its forces are every force drawn.
  if (ImGui::BeginMenu("Forces on", forces.bodies.size() > 1)) {
    // B's item is the one it goes to next.
    const std::string next = next_forces_on(forces);
    if (ImGui::MenuItem("every body", next.empty() ? "B" : "", forces.on.empty())) choice.forces_on = "";
    remember_item(controls, "Forces on every body");
    for (const std::string& body : forces.bodies) {
      if (ImGui::MenuItem(lessons::class_words(body).c_str(), next == body ? "B" : "", forces.on == body)) choice.forces_on = body;
      remember_item(controls, "Forces on " + body);
    }
    ImGui::EndMenu();
  }
  remember_item(controls, "Forces on");
  ImGui::Separator();
  predictions_items();
  ImGui::EndMenu();
  return choice;
}

}  // namespace frictionlab::classroom
