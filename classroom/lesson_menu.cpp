// The Lesson menu (classroom/lesson_menu.h).
#include "classroom/lesson_menu.h"

#include <imgui.h>

#include <vector>

#include "classroom/exports.h"
#include "classroom_state/user_lessons.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/catalog.h"

namespace frictionlab::classroom {

LessonMenuChoice lesson_menu(const std::string& lesson_path, const LessonLock& lock, bool browser, bool script_paths,
                             ControlPlaces& controls) {
  LessonMenuChoice choice;
  const bool open = ImGui::BeginMenu("Lesson");
  remember_item(controls, "Lesson menu");
  if (!open) return choice;
  // Under a teacher's lock the class stays on the lesson the teacher chose.
  const bool may_switch = !lock.locked();
  if (!may_switch) {
    // Greyed lessons say why, and how the teacher gets them back.
    const std::string why = lock.words(browser);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 24.0f * ImGui::GetFontSize());
    ImGui::TextDisabled("%s", why.c_str());
    draw::note_text(why.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Separator();
  }
  // Titles, with the name to open it by (frictionlab NAME) beside each.
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    const bool current = lesson_name(lesson_path) == entry.name;
    if (ImGui::MenuItem(entry.title.c_str(), entry.name.c_str(), current, may_switch)) choice.open = entry.name;
    remember_item(controls, "lesson " + entry.name);
  }
  // The student's own folder, read each time the menu is drawn, so a copy saved there shows at once.
  const std::vector<classroom_state::UserLesson> own = classroom_state::user_lessons();
  if (!own.empty()) {
    ImGui::Separator();
    if (script_paths) {
      ImGui::TextDisabled("Your lessons, in %s", classroom_state::user_lessons_folder().c_str());
    } else {
      ImGui::TextDisabled("Your lessons, kept in this browser");
    }
    // Titles, as the built-in lessons have them, with the file's name beside each.
    for (const classroom_state::UserLesson& lesson : own) {
      const bool current = lesson_path == lesson.path;
      const std::string file = lesson.name + ".lua";
      ImGui::PushID(lesson.path.c_str());  // two lessons may share a title (a copy received beside one's own)
      if (ImGui::MenuItem(lesson.title.c_str(), file.c_str(), current, may_switch)) choice.open = lesson.path;
      ImGui::PopID();
      remember_item(controls, "user lesson " + lesson.name);
    }
  }
  ImGui::Separator();
  if (browser) {
    // The page: a file from the computer through the browser's own chooser (a script or a
    // setup); a setup saved arrives as a download; the editor's Apply reloads a script.
    choice.open_file = ImGui::MenuItem("Open a file from this computer (.lua, .setup)...", nullptr, false, may_switch);
    remember_item(controls, "Open a file");
    choice.save_setup = ImGui::MenuItem("Save as a setup (download)");
    remember_item(controls, "Save as a setup");
  } else {
    choice.open_script = ImGui::MenuItem("Open a script...", nullptr, false, may_switch);
    remember_item(controls, "Open a script");
    // A prepared setup (lesson, values, lock, mystery), saved before class and opened in it.
    choice.open_setup = ImGui::MenuItem("Open a setup...", nullptr, false, may_switch);
    remember_item(controls, "Open a setup");
    choice.save_setup = ImGui::MenuItem("Save as a setup...");
    remember_item(controls, "Save as a setup");
    choice.reload = ImGui::MenuItem("Reload the script", "F5");
  }
  choice.screenshot = ImGui::MenuItem("Screenshot (PNG)", "Ctrl+S");
  choice.export_history = ImGui::MenuItem("Export the history (CSV)", "Ctrl+E");
  // A page is closed as the browser closes it.
  if (!browser) {
    ImGui::Separator();
    choice.quit = ImGui::MenuItem("Quit");
  }
  ImGui::EndMenu();
  return choice;
}

void running_script_path(const std::string& path) {
  // In screen points: the menu bar is laid out as a group, so SameLine's x would be off by the
  // window's padding.
  const float left = ImGui::GetCursorScreenPos().x + 20.0f;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowWidth() - 16.0f;
  const std::string shown = draw::path_that_fits(path, right - left);
  if (shown.empty()) return;
  ImGui::SameLine();
  ImGui::SetCursorScreenPos(ImVec2(right - ImGui::CalcTextSize(shown.c_str()).x, ImGui::GetCursorScreenPos().y));
  ImGui::TextDisabled("%s", shown.c_str());
  draw::note_text(shown.c_str());
  if (shown != path && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
}

}  // namespace frictionlab::classroom
