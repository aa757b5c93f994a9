// The View menu (classroom/view_menu.h).
#include "classroom/view_menu.h"

#include <imgui.h>

namespace frictionlab::classroom {

ViewMenuChoice view_menu(const WindowSettings& window, ControlPlaces& controls, const std::function<void()>& predictions_items) {
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
  ImGui::Separator();
  predictions_items();
  ImGui::EndMenu();
  return choice;
}

}  // namespace frictionlab::classroom
