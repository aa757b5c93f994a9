// Prepared setups in the classroom: the window's state as a setup file (ui/setup_file.h), saving
// it, opening one in place of the running lesson, and the Lesson menu's dialog for both.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "ui/classroom.h"
#include "ui/text_record.h"

namespace frictionlab::ui {

std::string Classroom::open_setup(const std::string& path) {
  try {
    ClassroomOptions base;
    base.window = window_;
    const ClassroomOptions options = setup_options(path, base);
    std::optional<Mystery> mystery;
    auto next = build_playback(options.lesson, options.overrides, options.settings, options.mystery, mystery);
    next->set_speed(playback_->speed());
    // Paused at t = 0, as a lesson opens; the setup's lock in place of the one before.
    playback_ = std::move(next);
    mystery_ = std::move(mystery);
    lock_ = std::set<std::string>(options.lock.begin(), options.lock.end());
    // The setup's predictions, never the last lesson's; asked or not as it says (else as before).
    predictions_ = options.predictions;
    window_.predictions = options.window.predictions;
    forget_interaction();
    for (int k = 0; k < 2; ++k) {
      answer_text_[k][0] = '\0';
      answer_error_[k].clear();
    }
    select_mystery_tab_ = mystery_.has_value();
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

PreparedSetup Classroom::current_setup(const std::string& path) const {
  const lessons::Lesson& lesson = playback_->lesson();
  PreparedSetup setup;
  setup.lesson = setup_lesson_name(lesson.path(), path);
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    // A mystery is saved as its pair and seed: its values are drawn again when it opens.
    if (mystery_ && (parameter.name == mystery_->mu_s_name() || parameter.name == mystery_->mu_k_name())) continue;
    setup.values.push_back({parameter.name, parameter_text(parameter), 0});
  }
  setup.lock.assign(lock_.begin(), lock_.end());
  if (mystery_) setup.mystery = mystery_->choice();
  setup.settings = lesson.settings();
  setup.ask_predictions = window_.predictions;
  // In the lesson's order; a box the class typed in and emptied again is no answer.
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    const auto answer = predictions_.answers.find(prediction.expectation);
    if (answer != predictions_.answers.end() && !answer->second.empty()) setup.answers.push_back({prediction.expectation, answer->second, 0});
  }
  setup.revealed = predictions_.revealed;
  return setup;
}

std::string Classroom::save_setup(const std::string& path) {
  try {
    const PreparedSetup setup = current_setup(path);
    // What the window marks as no number is refused here too: the file would not open again.
    for (const PreparedSetup::Answer& answer : setup.answers) {
      const std::string problem = prediction_problem(playback_->lesson(), answer.row, answer.text);
      if (!problem.empty()) {
        throw InvalidInput(path + ": the class's prediction of " + answer.row + " is " + answer.text + ": " + problem +
                           "; correct it or clear it in the theory panel, then save");
      }
    }
    write_setup(path, setup);
    status_ = "Setup saved to " + path;
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

void Classroom::setup_popup() {
  const char* const titles[] = {"", "Open a setup", "Save as a setup"};
  if (setup_dialog_asked_) {
    ImGui::OpenPopup(titles[static_cast<int>(setup_dialog_)]);
    setup_dialog_asked_ = false;
    setup_error_.clear();
    if (setup_dialog_ == SetupDialog::save && setup_path_[0] == '\0') {
      // A name to start from: the lesson's, in the folder screenshots go to.
      const std::string suggested = (std::filesystem::path(output_folder_) / (lesson_name(playback_->lesson().path()) + ".setup")).string();
      std::snprintf(setup_path_, sizeof setup_path_, "%s", suggested.c_str());
    }
  }
  if (setup_dialog_ == SetupDialog::none) return;
  const float s = fonts_->scale;
  ImGui::SetNextWindowSize(ImVec2(640.0f * s, 0.0f), ImGuiCond_Appearing);
  const char* title = titles[static_cast<int>(setup_dialog_)];
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const bool saving = setup_dialog_ == SetupDialog::save;
  ImGui::TextUnformatted(saving ? "Save the lesson, its values, the lock, the mystery and the predictions to:"
                                : "A setup file (path from the folder FrictionLab was started in, or from /):");
  ImGui::SetNextItemWidth(560.0f * s);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  bool go = ImGui::InputText("##setup path", setup_path_, sizeof setup_path_, ImGuiInputTextFlags_EnterReturnsTrue);
  remember("setup path");
  if (ImGui::Button(saving ? "Save" : "Open")) go = true;
  remember("setup go");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  if (go) {
    // "~/class.setup", as a shell would have it.
    const char* home = std::getenv("HOME");
    const std::string typed = setup_path_;
    const std::string path = typed.rfind("~/", 0) == 0 && home != nullptr ? home + typed.substr(1) : typed;
    setup_error_ = saving ? save_setup(path) : open_setup(path);
    if (setup_error_.empty()) {
      if (!saving) status_ = "Opened the setup " + path;
      setup_dialog_ = SetupDialog::none;
      ImGui::CloseCurrentPopup();
    }
  }
  if (cancel) {
    setup_dialog_ = SetupDialog::none;
    ImGui::CloseCurrentPopup();
  }
  if (!setup_error_.empty()) {
    ImGui::PushTextWrapPos(560.0f * s);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme(window_.theme).bad), "%s", setup_error_.c_str());
    note_text(setup_error_.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::EndPopup();
}

}  // namespace frictionlab::ui
