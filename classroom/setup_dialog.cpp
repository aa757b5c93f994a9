// The setup dialog (classroom/setup_dialog.h): the window's state as a setup file
// (classroom_state/setup_file.h) and saving it; the classroom opens one in place of the running
// lesson (Classroom::open_setup).
#include "classroom/setup_dialog.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "classroom/exports.h"
#include "draw/text_record.h"

namespace frictionlab::classroom {

std::string SetupDialog::draw(const std::string& lesson_path, const std::string& output_folder, const SetupFiles& files, float scale,
                              const draw::Theme& colours, ControlPlaces& controls) {
  const char* const titles[] = {"", "Open a setup", "Save as a setup"};
  if (asked) {
    ImGui::OpenPopup(titles[static_cast<int>(kind)]);
    asked = false;
    error.clear();
    if (kind == Kind::save && path[0] == '\0') {
      // A name to start from: the lesson's, in the folder screenshots go to.
      const std::string suggested =
          (std::filesystem::path(output_folder) / (lesson_name(lesson_path) + ".setup")).string();
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
    error = saving ? files.save(file) : files.open(file);
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
    draw::note_text(error.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndPopup();
  return said;
}

classroom_state::PreparedSetup SetupDialog::of_window(const std::string& path, const lessons::Lesson& lesson, const std::set<std::string>& lock,
                                    const MysteryPanel& mystery, bool ask_predictions, const classroom_state::ClassPredictions& predictions) {
  classroom_state::PreparedSetup setup;
  setup.lesson = classroom_state::setup_lesson_name(lesson.path(), path);
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    // A mystery is saved as its pair and seed: its values are drawn again when it opens.
    if (mystery.holds(parameter.name)) continue;
    setup.values.push_back({parameter.name, lessons::parameter_text(parameter), 0});
  }
  setup.lock.assign(lock.begin(), lock.end());
  if (mystery.mystery) setup.mystery = mystery.mystery->choice();
  setup.settings = lesson.settings();
  setup.ask_predictions = ask_predictions;
  // In the lesson's order; a box the class typed in and emptied again is no answer.
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    const auto answer = predictions.answers.find(prediction.expectation);
    if (answer != predictions.answers.end() && !answer->second.empty()) setup.answers.push_back({prediction.expectation, answer->second, 0});
  }
  setup.revealed = predictions.revealed;
  return setup;
}

std::string SetupDialog::save(const std::string& path, const classroom_state::PreparedSetup& setup, const lessons::Lesson& lesson) {
  try {
    // What the window marks as no number is refused here too: the file would not open again.
    for (const classroom_state::PreparedSetup::Answer& answer : setup.answers) {
      const std::string problem = classroom_state::prediction_problem(lesson, answer.row, answer.text);
      if (!problem.empty()) {
        throw InvalidInput(path + ": the class's prediction of " + answer.row + " is " + answer.text + ": " + problem +
                           "; correct it or clear it in the theory panel, then save");
      }
    }
    classroom_state::write_setup(path, setup);
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

}  // namespace frictionlab::classroom
