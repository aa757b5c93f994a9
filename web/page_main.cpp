// FrictionLab's web page: the classroom on the page's canvas, with the built-in lessons and the
// font in the page's packaged files (/lessons, /fonts) and the student's own lessons and the
// window's settings in the browser's storage (the home folder, which page.js keeps on IndexedDB).
//
// page.html starts it with the arguments its link gives (#lesson=NAME or #setup=TEXT, and
// &projector=1, &at=S), and calls the functions at the end of this file for what the page's own
// controls do (the lesson editor, links, the projector button).
#include <emscripten.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui_internal.h>

#include "classroom/classroom.h"
#include "classroom_state/plain_words.h"
#include "classroom_state/playback.h"
#include "classroom_state/setup_file.h"
#include "lessons/runtime/catalog.h"
#include "physics/validation.h"
#include "web/browser_files.h"
#include "web/browser_window.h"
#include "web/page_arguments.h"

namespace {

namespace fs = std::filesystem;
using namespace frictionlab;

std::unique_ptr<classroom::Classroom> page_classroom;
// Where page.html writes a link's (or a .setup file's) text before the program opens it.
constexpr const char* link_setup = "/link/frictionlab.setup";
std::string returned;  // the last text handed to JavaScript; lives until the next call

const char* hand_over(std::string text) {
  returned = std::move(text);
  return returned.c_str();
}

// A link's `at`: played to, at most to the end of the lesson's own run. Computed before the page
// draws again, so an hour of simulated time asked by a link would freeze the tab for as long.
void run_to_link_time(double seconds) {
  if (!std::isfinite(seconds) || seconds <= 0.0) return;
  page_classroom->run_to(std::min(seconds, page_classroom->playback().lesson().duration()));
}

classroom::ClassroomOptions page_options(const web::PageArguments& given, std::string& problem, std::optional<bool>& help_to_save) {
  const std::string& lesson = given.lesson;
  const std::string& setup = given.setup;
  const bool projector = given.projector;
  classroom::ClassroomOptions options;
  const std::string folder = classroom::settings_folder();
  const bool first_visit = folder.empty() || !std::filesystem::exists(folder + "/settings.ini");
  if (!folder.empty()) options.window = classroom::load_settings(folder + "/settings.ini");
  // Full screen cannot be restored: a browser grants it only right after a key or a click.
  options.window.full_screen = false;
  const std::string kept = classroom::kept_from_last_session(options.window);
  if (projector) options.window.projector = true;
  // The help panel a newcomer's first page opens with would cover what a link was sent for: a
  // lesson in projector mode is for a class in front of the screen, and a lesson or a setup is
  // what a teacher sent a class to look at (F1 still shows the help).
  // Closed for this visit only: what is remembered stays the user's own (web::PageRun).
  if (projector || (first_visit && (!setup.empty() || !lesson.empty()))) {
    help_to_save = options.window.help;
    options.window.help = false;
  }
  options.output_folder = web::downloads_folder;
  options.script_paths = false;
  options.browser = true;
  try {
    options.lesson = lessons::resolve_lesson(lesson.empty() ? lessons::builtin_lessons().front() : lesson);
  } catch (const InvalidInput& error) {
    problem = error.what();
    options.lesson = lessons::resolve_lesson(lessons::builtin_lessons().front());
  }
  if (!setup.empty()) {
    try {
      options = classroom::setup_options(setup, options);
    } catch (const InvalidInput& error) {
      problem = error.what();
    }
  }
  if (!kept.empty()) options.opening_notice = options.opening_notice.empty() ? kept : options.opening_notice + " " + kept;
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  // The lessons packaged with the page; a student's own are in the home folder (classroom_state/user_lessons.h).
  ::setenv("FRICTIONLAB_LESSONS", "/lessons", 1);
  // emscripten starts with a umask of 0777: files the page writes (a student's lesson, a
  // screenshot) would be unreadable, to the page itself too. The usual 022.
  ::umask(022);
  // Files the classroom writes for the user land in Downloads, and leave it as downloads: its
  // messages then say "saved to Downloads/...", which is where the browser puts them.
  std::error_code error;
  fs::current_path("/", error);
  fs::create_directories(web::downloads_folder, error);
  const web::PageArguments given = web::page_arguments(std::vector<std::string>(argv + 1, argv + argc));
  std::string problem;
  std::optional<bool> help_to_save;
  const classroom::ClassroomOptions options = page_options(given, problem, help_to_save);
  // A link's word refused (an --at out of range), said before what opening the rest found.
  if (!given.problem.empty()) problem = problem.empty() ? given.problem : given.problem + " " + problem;
  try {
    page_classroom = std::make_unique<classroom::Classroom>(options);
  } catch (const std::exception& failure) {
    problem = failure.what();
    classroom::ClassroomOptions plain;
    plain.window = options.window;
    plain.output_folder = options.output_folder;
    plain.script_paths = false;
    plain.browser = true;
    plain.lesson = lessons::resolve_lesson(lessons::builtin_lessons().front());
    page_classroom = std::make_unique<classroom::Classroom>(plain);
  }
  run_to_link_time(given.at);
  if (!problem.empty()) EM_ASM({ frictionlabPage.say(UTF8ToString($0)); }, problem.c_str());
  web::PageRun run;
  run.link_setup_path = link_setup;
  run.help_to_save = help_to_save;
  if (const std::string folder = classroom::settings_folder(); !folder.empty()) run.settings_path = folder + "/settings.ini";
  try {
    web::run_page(*page_classroom, run);
  } catch (const std::exception& failure) {
    EM_ASM({ frictionlabPage.say(UTF8ToString($0)); }, failure.what());
    return 2;
  }
  return 0;
}

// What the page's own controls ask of the classroom.
extern "C" {

// The running lesson's script (a built-in's under /lessons, or a student's own).
EMSCRIPTEN_KEEPALIVE const char* frictionlab_lesson_path() { return hand_over(page_classroom->playback().lesson().path()); }

// Opens a script (a student's, just written by the editor): the same file as the running
// lesson reloads as F5 does. Returns "" or the script's message ("file:line: ..."); on a
// mistake the last good lesson keeps running.
EMSCRIPTEN_KEEPALIVE const char* frictionlab_open(const char* path) {
  std::string message;
  if (page_classroom->playback().lesson().path() == path) {
    if (!page_classroom->playback().reload()) message = page_classroom->playback().script_error();
  } else {
    message = page_classroom->open(path);
  }
  // The page wrote the file and ran it here: the watcher must not run it once more.
  page_classroom->playback().file_written();
  frictionlab_wake();
  return hand_over(message);
}

// The page put the running script's last good text back after a failed Apply: not a change to run.
EMSCRIPTEN_KEEPALIVE void frictionlab_file_written() { page_classroom->playback().file_written(); }

// The window as a prepared setup's text, for a link; its lesson named as the page finds it.
EMSCRIPTEN_KEEPALIVE const char* frictionlab_setup_text() {
  return hand_over(classroom_state::setup_text(page_classroom->current_setup(link_setup)));
}

// Opens a setup file's text (a link's), as Lesson > Open a setup does. Returns "" or the message.
EMSCRIPTEN_KEEPALIVE const char* frictionlab_open_setup(const char* path) {
  const std::string message = page_classroom->open_setup(path);
  frictionlab_wake();
  return hand_over(message);
}

// A link followed in an open page (a teacher pastes one into the address bar): its lesson as
// it opens, with the script's own values, no predictions and the theory hidden, as loading the
// page from the link would; not a reload that keeps the values of the lesson before.
EMSCRIPTEN_KEEPALIVE const char* frictionlab_open_link_lesson(const char* name_or_path) {
  const std::string message = page_classroom->open(name_or_path);
  frictionlab_wake();
  return hand_over(message);
}

// A followed link's `at`, as the link's word: the run played to that time, as when the page opens
// from the link, read as the page's arguments are (the window's --at). Returns why it was
// refused, or "".
EMSCRIPTEN_KEEPALIVE const char* frictionlab_run_to(const char* at) {
  const web::PageArguments given = web::page_arguments({"--at", at});
  run_to_link_time(given.at);
  frictionlab_wake();
  return hand_over(given.problem);
}

// The page's Projector button: the larger text of projector mode, on or off.
EMSCRIPTEN_KEEPALIVE void frictionlab_set_projector(int on) {
  page_classroom->window_settings().projector = on != 0;
  frictionlab_wake();
}
EMSCRIPTEN_KEEPALIVE int frictionlab_projector() { return page_classroom->window_settings().projector ? 1 : 0; }

// Text pasted from the system clipboard, typed into whichever field has the keyboard.
EMSCRIPTEN_KEEPALIVE void frictionlab_paste(const char* text) {
  ImGui::GetIO().AddInputCharactersUTF8(text);
  frictionlab_wake();
}

// What the page shows, read by its tests (web/test/) and by nothing the user sees. Positions
// are the canvas's own pixels; the test divides by the screen's pixel ratio.
EMSCRIPTEN_KEEPALIVE const char* frictionlab_control(const char* name) {
  const std::optional<ImRect> rect = page_classroom->control(name);
  if (!rect) return hand_over("");
  return hand_over(std::to_string(rect->Min.x) + " " + std::to_string(rect->Min.y) + " " + std::to_string(rect->Max.x) + " " +
                   std::to_string(rect->Max.y));
}
EMSCRIPTEN_KEEPALIVE const char* frictionlab_body_on_screen(const char* name) {
  const b2Body* body = page_classroom->playback().lesson().scene().body(name);
  if (body == nullptr) return hand_over("");
  const ImVec2 at = page_classroom->world_camera().to_screen(body->GetWorldCenter());
  return hand_over(std::to_string(at.x) + " " + std::to_string(at.y));
}
EMSCRIPTEN_KEEPALIVE const char* frictionlab_parameter(const char* name) {
  for (const lessons::Parameter& parameter : page_classroom->playback().lesson().parameters()) {
    if (parameter.name == name) return hand_over(lessons::parameter_text(parameter));
  }
  return hand_over("");
}
EMSCRIPTEN_KEEPALIVE double frictionlab_time() { return page_classroom->playback().lesson().scene().time(); }
EMSCRIPTEN_KEEPALIVE int frictionlab_playing() { return page_classroom->playback().playing() ? 1 : 0; }
EMSCRIPTEN_KEEPALIVE int frictionlab_help_shown() { return page_classroom->window_settings().help ? 1 : 0; }
EMSCRIPTEN_KEEPALIVE int frictionlab_theory_hidden() { return page_classroom->theory_hidden() ? 1 : 0; }
EMSCRIPTEN_KEEPALIVE const char* frictionlab_gauge_figures() { return hand_over(page_classroom->gauge_figures()); }
EMSCRIPTEN_KEEPALIVE const char* frictionlab_mystery_pair() {
  return hand_over(page_classroom->mystery() ? page_classroom->mystery()->choice().pair : "");
}
EMSCRIPTEN_KEEPALIVE const char* frictionlab_status() { return hand_over(page_classroom->status()); }
// The status line's words as the transport bar shows them (script paths as file names).
EMSCRIPTEN_KEEPALIVE const char* frictionlab_status_words() {
  return hand_over(page_classroom->script_words(page_classroom->playback().notice() + " " + page_classroom->status()));
}
EMSCRIPTEN_KEEPALIVE const char* frictionlab_running_error() { return hand_over(page_classroom->running_script_error()); }
// Lua's message in plain words, for the page's editor and bar (classroom_state/plain_words.h).
EMSCRIPTEN_KEEPALIVE const char* frictionlab_plain_words(const char* message) { return hand_over(classroom_state::plain_words(message)); }
// An ImGui panel by its name: its corners, how far it is scrolled down, its font's height and the
// height inside it that its content scrolls in ("x0 y0 x1 y1 scroll font inner"), or "" when no
// such panel was drawn. (A wheel's notch scrolls a panel five lines, or two thirds of that height
// where it is less: ImGui's step.)
EMSCRIPTEN_KEEPALIVE const char* frictionlab_panel(const char* name) {
  const ImGuiWindow* panel = ImGui::FindWindowByName(name);
  if (panel == nullptr || !panel->WasActive) return hand_over("");
  return hand_over(std::to_string(panel->Pos.x) + " " + std::to_string(panel->Pos.y) + " " +
                   std::to_string(panel->Pos.x + panel->Size.x) + " " + std::to_string(panel->Pos.y + panel->Size.y) + " " +
                   std::to_string(panel->Scroll.y) + " " + std::to_string(panel->CalcFontSize()) + " " +
                   std::to_string(panel->InnerRect.GetHeight()));
}

}  // extern "C"
