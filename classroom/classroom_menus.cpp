// The classroom's menus (lessons, simulation settings, view); the help panel is classroom/help_panel.h.
#define IMGUI_DEFINE_MATH_OPERATORS
#include <algorithm>
#include <filesystem>
#include <vector>

#include "classroom/classroom.h"
#include "classroom_state/user_lessons.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/catalog.h"

namespace frictionlab::ui {

std::string Classroom::lock_words() const {
  if (lock_.empty()) return "";
  // Nothing in the window unlocks it: the class cannot undo what the teacher prepared.
  if (!setup_dialog_.lock_from.empty() && browser_) {
    // The page's setups come from a link or a file from the computer, copied where nobody looks.
    return "Locked by the prepared setup this page opened, for the class to stay on this lesson. To unlock: open the "
           "page's address without its #setup= part, or a setup file without its lock line.";
  }
  if (!setup_dialog_.lock_from.empty()) {
    return "Locked by the setup " + std::filesystem::path(setup_dialog_.lock_from).filename().string() +
           ", for the class to stay on this lesson. To unlock: delete its lock line (in " + setup_dialog_.lock_from +
           "), then quit and open the setup again.";
  }
  return "Locked by --lock on the command line, for the class to stay on this lesson. To unlock: quit and start "
         "FrictionLab without --lock.";
}

void Classroom::menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  const bool lesson_menu = ImGui::BeginMenu("Lesson");
  remember("Lesson menu");
  if (lesson_menu) {
    // Under a teacher's lock the class stays on the lesson the teacher chose.
    const bool may_switch = lock_.empty();
    if (!may_switch) {
      // Greyed lessons say why, and how the teacher gets them back.
      const std::string why = lock_words();
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 24.0f * ImGui::GetFontSize());
      ImGui::TextDisabled("%s", why.c_str());
      note_text(why.c_str());
      ImGui::PopTextWrapPos();
      ImGui::Separator();
    }
    // Titles, with the name to open it by (frictionlab NAME) beside each.
    for (const lessons::CatalogEntry& entry : lessons::catalog()) {
      const bool current = lesson_name(playback_->lesson().path()) == entry.name;
      if (ImGui::MenuItem(entry.title.c_str(), entry.name.c_str(), current, may_switch)) status_ = open(entry.name);
      remember("lesson " + entry.name);
    }
    // The student's own folder, read each time the menu is drawn, so a copy saved there shows at once.
    const std::vector<UserLesson> own = user_lessons();
    if (!own.empty()) {
      ImGui::Separator();
      if (script_paths_) {
        ImGui::TextDisabled("Your lessons, in %s", user_lessons_folder().c_str());
      } else {
        ImGui::TextDisabled("Your lessons, kept in this browser");
      }
      // Titles, as the built-in lessons have them, with the file's name beside each.
      for (const UserLesson& lesson : own) {
        const bool current = playback_->lesson().path() == lesson.path;
        const std::string file = lesson.name + ".lua";
        ImGui::PushID(lesson.path.c_str());  // two lessons may share a title (a copy received beside one's own)
        if (ImGui::MenuItem(lesson.title.c_str(), file.c_str(), current, may_switch)) status_ = open(lesson.path);
        ImGui::PopID();
        remember("user lesson " + lesson.name);
      }
    }
    ImGui::Separator();
    if (browser_) {
      // The page: a file from the computer through the browser's own chooser (a script or a
      // setup); a setup saved arrives as a download; the editor's Apply reloads a script.
      if (ImGui::MenuItem("Open a file from this computer (.lua, .setup)...", nullptr, false, may_switch)) {
        open_file_request_ = true;
      }
      remember("Open a file");
      if (ImGui::MenuItem("Save as a setup (download)")) {
        try {
          // save_setup says where it went ("Setup saved to Downloads/..."), or returns why not.
          if (std::string why = save_setup(output_path(lesson_name(playback_->lesson().path()), ".setup")); !why.empty()) {
            status_ = why;
          }
        } catch (const std::exception& error) {
          status_ = std::string("Could not save the setup: ") + error.what();
        }
      }
      remember("Save as a setup");
    } else {
      if (ImGui::MenuItem("Open a script...", nullptr, false, may_switch)) open_script_.ask();
      remember("Open a script");
      // A prepared setup (lesson, values, lock, mystery), saved before class and opened in it.
      if (ImGui::MenuItem("Open a setup...", nullptr, false, may_switch)) setup_dialog_.ask(SetupDialog::Kind::open);
      remember("Open a setup");
      if (ImGui::MenuItem("Save as a setup...")) setup_dialog_.ask(SetupDialog::Kind::save);
      remember("Save as a setup");
      if (ImGui::MenuItem("Reload the script", "F5")) playback_->reload();
    }
    if (ImGui::MenuItem("Screenshot (PNG)", "Ctrl+S")) request_screenshot();
    if (ImGui::MenuItem("Export the history (CSV)", "Ctrl+E")) save_history();
    // A page is closed as the browser closes it.
    if (!browser_) {
      ImGui::Separator();
      if (ImGui::MenuItem("Quit")) quit_ = true;
    }
    ImGui::EndMenu();
  }
  const bool simulation = ImGui::BeginMenu("Simulation");
  remember("Simulation menu");
  if (simulation) {
    StepSettings settings = playback_->lesson().settings();
    const bool may_treat = shown("friction"), may_rate = shown("hz"), may_substep = shown("substeps");
    ImGui::TextDisabled("Friction treatment");
    const std::pair<FrictionTreatment, const char*> treatments[] = {
        {FrictionTreatment::stick_slip, "stick-slip (converges to Coulomb)"},
        {FrictionTreatment::threshold, "threshold (games' speed switch)"},
        {FrictionTreatment::regularized, "regularized (smooth, creeps)"},
        {FrictionTreatment::box2d, "box2d (one coefficient)"}};
    for (const auto& [treatment, label] : treatments) {
      const bool chosen = ImGui::MenuItem(label, nullptr, settings.treatment == treatment, may_treat);
      remember("treatment " + std::string(treatment_name(treatment)));
      if (chosen && settings.treatment != treatment) {
        settings.treatment = treatment;
        change_settings(settings);
      }
    }
    ImGui::Separator();
    ImGui::TextDisabled("Step rate");
    for (const double hz : {30.0, 60.0, 120.0, 240.0, 480.0, 960.0, 1920.0}) {
      const std::string label = std::to_string(static_cast<int>(hz)) + " Hz";
      const bool chosen = ImGui::MenuItem(label.c_str(), nullptr, settings.hz == hz, may_rate);
      remember("hz " + label.substr(0, label.size() - 3));
      if (chosen && settings.hz != hz) {
        settings.hz = hz;
        change_settings(settings);
      }
    }
    ImGui::Separator();
    ImGui::TextDisabled("Sub-steps per step");
    for (const int substeps : {1, 2, 4, 8, 16}) {
      const std::string label = std::to_string(substeps);
      const bool chosen = ImGui::MenuItem(label.c_str(), nullptr, settings.substeps == substeps, may_substep);
      remember("substeps " + label);
      if (chosen && settings.substeps != substeps) {
        settings.substeps = substeps;
        change_settings(settings);
      }
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Reset to t = 0", "R")) playback_->reset();
    ImGui::EndMenu();
  }
  if (std::optional<std::string> said = mystery_.tab.draw_menu(*this, controls_)) status_ = *said;
  const bool view = ImGui::BeginMenu("View");
  remember("View menu");
  if (view) {
    bool dark = window_.theme == ThemeName::dark;
    if (ImGui::MenuItem("Dark theme", "D", &dark)) window_.theme = dark ? ThemeName::dark : ThemeName::light;
    ImGui::MenuItem("Projector mode", "P", &window_.projector);
    if (ImGui::MenuItem("Full screen", "F11")) full_screen_toggle_ = true;
    ImGui::MenuItem("Help", "F1", &window_.help);
    ImGui::Separator();
    // Off: the theory shows from the start, as for a teacher who takes no predictions.
    ImGui::MenuItem("Ask for predictions first", nullptr, &window_.predictions);
    remember("Ask for predictions first");
    if (ImGui::MenuItem("Reveal the theory", "T", false, theory_hidden())) predictions_.predictions.revealed = true;
    // A second round: the teacher changed a value after the reveal, and the class predicts anew
    // (before, the theory stayed up and the old answers were judged against the new run).
    const bool answered = predictions_.predictions.revealed || !predictions_.predictions.answers.empty();
    const bool asks = window_.predictions && !playback_->lesson().predictions().empty();
    if (ImGui::MenuItem("Predict again (new answers, theory hidden)", nullptr, false, asks && answered)) predict_again();
    remember("Predict again");
    ImGui::EndMenu();
  }
  tools_.draw_menu(window_.tools, playback_->lesson().scene().time(), playback_->playing(), controls_);
  // Which file is running, so a student knows which script to edit: as much of its path as
  // fits at the right of the bar, never cut (the whole of it under the pointer).
  // In screen points: the menu bar is laid out as a group, so SameLine's x would be off by
  // the window's padding.
  const std::string path = script_words(playback_->lesson().path());
  const float left = ImGui::GetCursorScreenPos().x + 20.0f;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowWidth() - 16.0f;
  const std::string shown = path_that_fits(path, right - left);
  if (!shown.empty()) {
    ImGui::SameLine();
    ImGui::SetCursorScreenPos(ImVec2(right - ImGui::CalcTextSize(shown.c_str()).x, ImGui::GetCursorScreenPos().y));
    ImGui::TextDisabled("%s", shown.c_str());
    note_text(shown.c_str());
    if (shown != path && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
  }
  ImGui::EndMainMenuBar();
}

}  // namespace frictionlab::ui
