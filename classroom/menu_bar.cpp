// The window's menu bar (classroom/menu_bar.h).
#include "classroom/menu_bar.h"

#include <imgui.h>

namespace frictionlab::classroom {

void MenuBar::draw(const std::function<void(const WindowChoice&)>& carry_out) const {
  if (!ImGui::BeginMainMenuBar()) return;
  const lessons::Lesson& lesson = playback->lesson();
  WindowChoice chosen;
  chosen.lesson = lesson_menu(lesson.path(), lock, browser, script_words.paths, controls);
  chosen.simulation = simulation_menu(lesson.settings(), lock, controls);
  chosen.mystery = mystery.tab.draw_menu(lesson, mystery.mystery, lock.words(browser), controls);
  chosen.view = view_menu(window, forces, controls, [&] { chosen.said = predictions.menu_items(window.predictions, *playback, controls); });
  // Read again: Predict again (the View menu) took the run back to t = 0.
  tools.draw_menu(window.tools, playback->lesson().scene().time(), playback->playing(), controls);
  carry_out(chosen);
  running_script_path(script_words(playback->lesson().path()));
  ImGui::EndMainMenuBar();
}

}  // namespace frictionlab::classroom
