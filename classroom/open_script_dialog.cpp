// The Lesson menu's dialog that opens a script by its path (classroom/open_script_dialog.h).
#include "classroom/open_script_dialog.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <imgui.h>

namespace frictionlab::classroom {

void OpenScriptDialog::draw(const std::function<std::string(const std::string& path)>& open, float scale, const draw::Theme& colours) {
  if (asked) {
    ImGui::OpenPopup("Open a lesson script");
    asked = false;
    error.clear();
  }
  const float s = scale;
  ImGui::SetNextWindowSize(ImVec2(640.0f * s, 0.0f), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal("Open a lesson script", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted("A .lua file (path from the folder FrictionLab was started in, or from /):");
  ImGui::SetNextItemWidth(560.0f * s);
  if (ImGui::IsWindowAppearing() || refocus) ImGui::SetKeyboardFocusHere();
  refocus = false;
  bool go = ImGui::InputText("##path", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue);
  // Scripts in the current folder, one click each.
  std::error_code listing;
  std::vector<std::string> scripts;
  for (std::filesystem::directory_iterator entry(".", listing), end; !listing && entry != end; entry.increment(listing)) {
    if (entry->path().extension() == ".lua") scripts.push_back(entry->path().filename().string());
  }
  std::sort(scripts.begin(), scripts.end());
  for (const std::string& name : scripts) {
    if (ImGui::Selectable(name.c_str())) {
      std::snprintf(path, sizeof path, "%s", name.c_str());
      go = true;
    }
  }
  if (ImGui::Button("Open")) go = true;
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  if (go) {
    error = open(path);
    if (error.empty()) ImGui::CloseCurrentPopup();
    else refocus = true;  // back into the path next frame, to correct it
  }
  if (!error.empty()) {
    ImGui::PushTextWrapPos(560.0f * s);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colours.bad), "%s", error.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndPopup();
}

}  // namespace frictionlab::classroom
