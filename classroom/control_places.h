// Where each named control of the window was drawn in the last frame ("mu_s slider", "measure",
// "mystery reveal"...): the window's tabs and dialogs note their controls here, and tests find
// them by name to click them.
#pragma once

#include <imgui.h>
#include <imgui_internal.h>

#include <map>
#include <string>

namespace frictionlab::classroom {

using ControlPlaces = std::map<std::string, ImRect>;

// The last item drawn, under `name`.
inline void remember_item(ControlPlaces& places, const std::string& name) {
  places[name] = ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
}

}  // namespace frictionlab::classroom
