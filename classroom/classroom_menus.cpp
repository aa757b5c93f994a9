// The classroom's menu bar: what the Lesson and Simulation menus chose, carried out
// (classroom/lesson_menu.h, classroom/simulation_menu.h); the Mystery menu (the mystery tab's),
// the View menu (its predictions items the prediction panel's), the Tools menu (the measuring
// tools'), and the running script's path at the bar's right. The help panel is help_panel.h.
#define IMGUI_DEFINE_MATH_OPERATORS
#include <vector>

#include "classroom/classroom.h"
#include "classroom/lesson_menu.h"
#include "classroom/simulation_menu.h"
#include "draw/text_record.h"
#include "draw/words.h"

namespace frictionlab::classroom {

void Classroom::menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  const LessonMenuChoice lesson = lesson_menu(playback_->lesson().path(), lock_, browser_, script_words_.paths, controls_);
  if (lesson.open) status_.text = open(*lesson.open);
  if (lesson.open_file) open_file_request_ = true;
  if (lesson.open_script) open_script_.ask();
  if (lesson.open_setup) setup_dialog_.ask(SetupDialog::Kind::open);
  if (lesson.save_setup && !browser_) setup_dialog_.ask(SetupDialog::Kind::save);
  if (lesson.save_setup && browser_) {
    // The page's download: save_setup says where it went ("Setup saved to Downloads/..."), or why not.
    try {
      const std::string path = exports_.output_path(playback_->lesson(), lesson_name(playback_->lesson().path()), ".setup");
      if (std::string why = save_setup(path); !why.empty()) status_.text = why;
    } catch (const std::exception& error) {
      status_.text = std::string("Could not save the setup: ") + error.what();
    }
  }
  if (lesson.reload) playback_->reload();
  if (lesson.screenshot) {
    if (std::string why = exports_.request_screenshot(playback_->lesson()); !why.empty()) status_.text = why;
  }
  if (lesson.export_history) status_.text = exports_.save_history(*playback_, mystery_.hidden());
  if (lesson.quit) quit_ = true;
  const SimulationChoice simulation = simulation_menu(playback_->lesson().settings(), lock_, controls_);
  if (simulation.settings) change_settings(*simulation.settings);
  if (simulation.reset) playback_->reset();
  if (std::optional<std::string> said = mystery_.tab.draw_menu(*this, controls_)) status_.text = *said;
  const bool view = ImGui::BeginMenu("View");
  remember("View menu");
  if (view) {
    bool dark = window_.theme == draw::ThemeName::dark;
    if (ImGui::MenuItem("Dark theme", "D", &dark)) window_.theme = dark ? draw::ThemeName::dark : draw::ThemeName::light;
    ImGui::MenuItem("Projector mode", "P", &window_.projector);
    if (ImGui::MenuItem("Full screen", "F11")) full_screen_toggle_ = true;
    ImGui::MenuItem("Help", "F1", &window_.help);
    ImGui::Separator();
    if (std::optional<std::string> said = predictions_.menu_items(window_.predictions, *playback_, controls_)) {
      status_.say_of_moment(*said, playback_->lesson().scene().frame(), theory_hidden());
    }
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
  const std::string shown = draw::path_that_fits(path, right - left);
  if (!shown.empty()) {
    ImGui::SameLine();
    ImGui::SetCursorScreenPos(ImVec2(right - ImGui::CalcTextSize(shown.c_str()).x, ImGui::GetCursorScreenPos().y));
    ImGui::TextDisabled("%s", shown.c_str());
    draw::note_text(shown.c_str());
    if (shown != path && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
  }
  ImGui::EndMainMenuBar();
}

}  // namespace frictionlab::classroom
