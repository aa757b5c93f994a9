// The Lesson menu's dialogs (classroom/dialogs.h): a script by its path, and a prepared setup to open
// or save.
#include "classroom/dialogs.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "classroom/classroom.h"
#include "draw/text_record.h"

namespace frictionlab::ui {

void OpenScriptDialog::draw(Classroom& classroom, float scale, const Theme& colours) {
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
    error = classroom.open(path);
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

std::string SetupDialog::draw(Classroom& classroom, const std::string& output_folder, float scale, const Theme& colours,
                              ControlPlaces& controls) {
  const char* const titles[] = {"", "Open a setup", "Save as a setup"};
  if (asked) {
    ImGui::OpenPopup(titles[static_cast<int>(kind)]);
    asked = false;
    error.clear();
    if (kind == Kind::save && path[0] == '\0') {
      // A name to start from: the lesson's, in the folder screenshots go to.
      const std::string suggested =
          (std::filesystem::path(output_folder) / (lesson_name(classroom.playback().lesson().path()) + ".setup")).string();
      std::snprintf(path, sizeof path, "%s", suggested.c_str());
    }
  }
  if (kind == Kind::none) return "";
  const float s = scale;
  ImGui::SetNextWindowSize(ImVec2(640.0f * s, 0.0f), ImGuiCond_Appearing);
  const char* title = titles[static_cast<int>(kind)];
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    kind = Kind::none;  // closed without its buttons (Escape): none is open any more
    return "";
  }
  std::string said;
  const bool saving = kind == Kind::save;
  ImGui::TextUnformatted(saving ? "Save the lesson, its values, the lock, the mystery and the predictions to:"
                                : "A setup file (path from the folder FrictionLab was started in, or from /):");
  ImGui::SetNextItemWidth(560.0f * s);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  bool go = ImGui::InputText("##setup path", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue);
  remember_item(controls, "setup path");
  if (ImGui::Button(saving ? "Save" : "Open")) go = true;
  remember_item(controls, "setup go");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  if (go) {
    // "~/class.setup", as a shell would have it.
    const char* home = std::getenv("HOME");
    const std::string typed = path;
    const std::string file = typed.rfind("~/", 0) == 0 && home != nullptr ? home + typed.substr(1) : typed;
    error = saving ? classroom.save_setup(file) : classroom.open_setup(file);
    if (error.empty()) {
      if (!saving) said = "Opened the setup " + file;
      kind = Kind::none;
      ImGui::CloseCurrentPopup();
    }
  }
  if (cancel) {
    kind = Kind::none;
    ImGui::CloseCurrentPopup();
  }
  if (!error.empty()) {
    ImGui::PushTextWrapPos(560.0f * s);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colours.bad), "%s", error.c_str());
    note_text(error.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndPopup();
  return said;
}

}  // namespace frictionlab::ui
