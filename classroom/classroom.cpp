// ImVec2 arithmetic for ImRect.
#define IMGUI_DEFINE_MATH_OPERATORS
#include "classroom/classroom.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "classroom/force_gauge.h"
#include "classroom/help_panel.h"
#include "classroom/text_boxes.h"
#include "classroom_state/plain_words.h"
#include "draw/frame.h"
#include "draw/image.h"
#include "draw/text_record.h"
#include "files/output_file.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/history_csv.h"

namespace frictionlab::ui {
namespace {

}  // namespace

std::string lesson_name(const std::string& script_path) { return std::filesystem::path(script_path).stem().string(); }

Classroom::Classroom(ClassroomOptions options)
    : window_(options.window),
      lock_(options.lock.begin(), options.lock.end()),
      overrides_(options.overrides),
      output_folder_(options.output_folder),
      script_paths_(options.script_paths),
      browser_(options.browser) {
  setup_dialog_.lock_from = options.lock_from;
  const FileStamp stamp = file_stamp(options.lesson);  // before it is read: a save meanwhile is seen
  try {
    std::optional<Mystery> mystery;
    playback_ = MysteryPanel::build_playback(options.lesson, options.overrides, options.settings, options.mystery, mystery);
    check_lock(playback_->lesson());
    mystery_.begin(std::move(mystery));
    predictions_.predictions = options.predictions;  // a prepared setup's; another lesson in its place asks again
  } catch (const lessons::ScriptError& error) {
    // A student's broken script: show why beside a working lesson, and open it once it builds,
    // with the --set values and the lock it was opened with.
    failed_script_ = options.lesson;
    failed_error_ = error.what();
    failed_stamp_ = stamp;
    playback_ = std::make_unique<Playback>(lessons::resolve_lesson(lessons::builtin_lessons().front()),
                                           std::map<std::string, std::string>{}, options.settings);
  }
  playback_->set_speed(window_.speed);
  // A lesson opens paused at t = 0, its first frame drawn: the class sees the setup, and
  // predicts, before anything moves; Space plays. A stopwatch the options ask for is armed
  // now, at t = 0: a window opened at a later time (--at) has it read the run up to there.
  tools_.on = window_.tools;
  tools_.arm_stopwatch(0.0, false);
  if (!options.opening_notice.empty()) status_ = options.opening_notice;
}

void Classroom::forget_interaction() {
  parameters_.forget();
  hand_.forget();
  failed_script_.clear();
  tools_.stopwatch.reset();  // it timed a run of the lesson that closed
}

void Classroom::check_lock(const lessons::Lesson& lesson) const {
  for (const std::string& name : lock_) {
    bool known = false;
    for (const char* setting : lockable_settings) known = known || name == setting;
    for (const lessons::Parameter& parameter : lesson.parameters()) known = known || name == parameter.name;
    if (!known) {
      std::string controls;
      for (const lessons::Parameter& parameter : lesson.parameters()) controls += parameter.name + ", ";
      throw InvalidInput("--lock " + name + ": " + lesson.path() + " has no control of that name; its controls: " +
                         controls + "hz, substeps, friction");
    }
  }
}

float Classroom::ui_scale(ImVec2 display) const {
  const float fit = frame_scale(static_cast<int>(display.x), static_cast<int>(display.y));
  // Projector mode: a third larger, text and lines alike, for the back of the room.
  return std::max(0.5f, fit) * (window_.projector ? 1.35f : 1.0f);
}

bool Classroom::shown(const std::string& control_name) const { return unlocked(lock_, control_name); }

void Classroom::remember(const std::string& name) { remember_item(controls_, name); }

ParametersOnShow Classroom::parameters_on_show() const {
  const lessons::Lesson& lesson = playback_->lesson();
  // Whether the class's answers may have the panel's room is the same from the lesson's opening
  // to the run's end and after R: the trial's Parameters panel folded as the run ended and its
  // tabs jumped up under the teacher's pointer.
  return {lesson, lock_, mystery_.mystery, hidden_values(), window_.predictions && !lesson.predictions().empty()};
}

std::optional<ImRect> Classroom::control(const std::string& name) const {
  const auto found = controls_.find(name);
  if (found == controls_.end()) return std::nullopt;
  return found->second;
}

void Classroom::frame(const Fonts& fonts, ImVec2 display, double wall_seconds, FrameRecord* record) {
  fonts_ = &fonts;
  std::optional<TextRecording> noting;
  if (record != nullptr) {
    *record = FrameRecord{};
    noting.emplace(&record->texts);
  }
  controls_.clear();
  const float s = fonts.scale;
  handle_keys();
  // One setting of the cheapest-setting search a frame: the window stays live while it measures.
  cheapest_.measure_next();
  playback_->advance(wall_seconds);
  watch_files(wall_seconds);

  tools_.on = window_.tools;
  tools_.follow(playback_->lesson(), playback_->playing(), playback_->at_run_end());
  ImGui::PushFont(fonts.body);
  menu_bar();
  const float menu_height = ImGui::GetFrameHeight();
  // The transport bar's words have their place from the lesson's opening (the run's end notice's).
  const std::string transport_room = playback_->run_end_notice();
  const float transport_height = TransportBar::shape(transport_room, display.x, s, fonts.small).height;
  // The stopwatch over the title: in the world's first lane it was written across the lanes'
  // names and bodies (terrain's "asphalt box"), and squeezed out of thin lanes.
  // It reads the lesson's one clock, whatever the lanes.
  const float stopwatch_height = MeasuringTools::stopwatch_strip_height(window_.tools.stopwatch, s);
  if (stopwatch_height > 0.0f) {
    tools_.draw_stopwatch_strip(ImVec2(0.0f, menu_height), ImVec2(display.x, stopwatch_height),
                                playback_->lesson().scene().time(), fonts);
  }
  ImGui::PopFont();
  const ImVec2 origin(0.0f, menu_height + stopwatch_height);
  const ImVec2 area(display.x, std::max(1.0f, display.y - menu_height - stopwatch_height - transport_height));
  hand_.projector = window_.projector;
  hand_.hold_view(*playback_, origin, area, s);

  FrameStyle style;
  style.theme = window_.theme;
  style.fonts = &fonts;
  style.origin = origin;
  style.readings = &playback_->readings();
  if (!script_paths_ && !playback_->readings().error.empty()) {
    shown_readings_ = playback_->readings();
    shown_readings_.error = script_words(shown_readings_.error);
    style.readings = &shown_readings_;
  }
  if (!script_paths_) style.script_words = [this](const std::string& text) { return script_words(text); };
  style.view_adjust = hand_.view_adjust;
  style.projector = window_.projector;
  style.record = record;
  style.parameters_panel = [this](ImVec2 corner, ImVec2 size, std::size_t step) {
    parameters_.draw(corner, size, step, parameters_on_show(), fonts_->scale, theme(window_.theme), controls_);
  };
  style.world_tools = [this](WorldToolsPass pass, ImDrawList* draw, const Camera& camera, std::size_t lane,
                             float newtons_to_pixels,
                             LabelPlacer& labels) { world_tools(pass, draw, camera, lane, newtons_to_pixels, labels); };
  if (!playback_->gauge().empty()) {
    style.extra_plot_title = gauge_plot_title(playback_->gauge(), playback_->lesson().scene().frame_step());
    style.extra_plot = [this](ImVec2 corner, ImVec2 size) {
      draw_gauge_plot(corner, size, playback_->gauge(), playback_->lesson().scene().frame_step(), theme(window_.theme), *fonts_);
    };
    style.show_extra_plot = hand_.held;
  }
  style.hidden = hidden_values();
  style.turn_plot_pages = std::exchange(turn_plot_pages_, 0);
  style.more_tabs = [this, s] {
    if (mystery_.mystery) mystery_.tab.draw_tab(*mystery_.mystery, theory_hidden(), theme(window_.theme), controls_);
    if (const std::optional<StepSettings> use = cheapest_.draw(playback_->lesson(), s, theme(window_.theme), controls_)) {
      change_settings(*use);
    }
    // Six tabs do not fit side by side in projector mode: the mystery's takes the map's place
    // (whose boundary would give μs away until the reveal anyway).
    if (!mystery_.mystery) stability_.draw_tab(playback_->lesson(), hidden_values(), controls_);
  };
  if (std::string said = predictions_.forget_outdated(*playback_); !said.empty()) status_ = said;
  predictions_.style(style, *playback_, window_.predictions, theme(window_.theme), controls_,
                     [this] { return hidden_values().theory(); });
  ImGui::PushFont(fonts.body);
  style.parameters_heights = parameters_.heights(parameters_on_show());
  ImGui::PopFont();
  build_frame(playback_->lesson(), playback_->framing(), style, area);

  ImGui::PushFont(fonts.body);
  hand_.handle_mouse(*playback_, origin, area, s, status_);
  const FrameLayout layout = FrameLayout::of(area, s, origin, window_.projector);
  // Over the ground, under the bodies: a lesson's bodies mostly stand on it.
  messages(ImVec2(layout.world_corner.x + 6.0f * s, layout.world_corner.y + layout.world_size.y - 6.0f * s),
           layout.world_size.x - 12.0f * s);
  transport_.draw(ImVec2(0.0f, display.y - transport_height), ImVec2(display.x, transport_height), *playback_,
                  transport_words(), transport_room, s, fonts.small, window_.speed, controls_);
  help_panel(window_.help, s, browser_, script_paths_, output_folder_);
  stability_.draw_window(playback_->lesson(), hidden_values(), theme(window_.theme), fonts);
  open_script_.draw(*this, s, theme(window_.theme));
  if (std::string said = setup_dialog_.draw(*this, output_folder_, s, theme(window_.theme), controls_); !said.empty()) {
    status_ = said;
  }
  ImGui::PopFont();

  // Values asked for while the panels were drawn: applied now, since a rebuild replaces what
  // the panels were reading.
  for (const auto& [name, value] : parameters_.asked) set_value(name, value);
  parameters_.asked.clear();
  after_keys();
}

namespace {

// How many of ImGui's open popups are dialogs (modal, up to the topmost one); those above them
// are menus: the menu bar's, a combo's list, a tab's menu.
int dialog_levels() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  int level = g.OpenPopupStack.Size;
  while (level > 0) {
    const ImGuiWindow* popup = g.OpenPopupStack[level - 1].Window;
    if (popup != nullptr && (popup->Flags & ImGuiWindowFlags_Modal) != 0) break;
    --level;
  }
  return level;
}

}  // namespace

void Classroom::handle_keys() {
  std::vector<std::pair<Key, bool>> taps;
  taps.swap(taps_);
  const auto hit = [&](Key key, bool ctrl) {
    return std::find(taps.begin(), taps.end(), std::make_pair(key, ctrl)) != taps.end();
  };
  int dialogs = dialog_levels();
  const bool menu_open = ImGui::GetCurrentContext()->OpenPopupStack.Size > dialogs;
  Typing typed = typing();
  // Escape with a dialog open closes it, doing nothing it offers, as its Cancel does (the trial's
  // teacher pressed Escape to leave "Save as a setup" and it stayed); a menu over a dialog closes
  // first. Before the frame's dialogs are drawn, so the one closed draws nothing this frame and
  // a path being typed in it goes with it.
  if (hit(Key::escape, false) && dialogs > 0) {
    if (menu_open) {
      close_menus_ = true;
      return;
    }
    ImGui::ClosePopupToLevel(dialogs - 1, true);
    // The keys pressed after Escape in the same frame are the window's again (a quick Escape,
    // Space closes the dialog and plays), or the dialog's below if one is still open; the typing
    // was in the dialog closed. (The frame's taps keep no order: a key pressed just before the
    // Escape counts too.)
    dialogs = dialog_levels();
    typed = Typing::nothing;
    std::erase(taps, std::make_pair(Key::escape, false));
  }
  // Space in a box that takes a number (classroom/text_boxes.h) ends the typing as Enter does (the value
  // kept; ImGui 1.86 reads Enter from the key's state, so it is pressed for this frame only) and
  // then plays: a teacher types the class's answer and presses Space to start. The box lets no
  // blank in. In a box of free text (a file's name), Space is typed.
  if (typed == Typing::number && hit(Key::space, false)) {
    ImGuiIO& io = ImGui::GetIO();
    enter_for_typing_ = io.KeysDown[io.KeyMap[ImGuiKey_Enter]];
    io.KeysDown[io.KeyMap[ImGuiKey_Enter]] = true;
    io.KeysDownDuration[io.KeyMap[ImGuiKey_Enter]] = 0.0f;
    if (dialogs == 0) play_after_typing_ = true;
    close_menus_ = menu_open;
    return;
  }
  // Typing a value or a path, or a dialog open: the other keys are the text's or the dialog's
  // (Escape in a box puts its text back, as ImGui does).
  if (typed != Typing::nothing || dialogs > 0) return;
  // A menu open: Escape closes it; a shortcut closes it and acts (the class watches the run, not
  // the menu; the trial's Space did nothing while the Tools menu was open).
  if (menu_open && !taps.empty()) close_menus_ = true;
  if (hit(Key::escape, false)) return;
  if (hit(Key::s, true)) request_screenshot();
  if (hit(Key::e, true)) save_history();
  if (hit(Key::space, false)) playback_->toggle();
  if (hit(Key::period, false)) playback_->step_once();
  if (hit(Key::comma, false)) {
    playback_->scrub_to(playback_->lesson().scene().time() - playback_->lesson().scene().frame_step());
  }
  if (hit(Key::r, false)) playback_->reset();
  if (hit(Key::f5, false)) playback_->reload();
  if (hit(Key::f11, false)) full_screen_toggle_ = true;
  if (hit(Key::f1, false)) window_.help = !window_.help;
  if (hit(Key::p, false)) window_.projector = !window_.projector;
  if (hit(Key::t, false)) {
    ClassPredictions& asked = predictions_.predictions;
    if (theory_hidden()) {
      asked.revealed = true;
    } else if (asked.revealed && window_.predictions && !playback_->lesson().predictions().empty()) {
      // T again hides the theory: a reveal by mistake (a click that landed on the button before
      // the class answered) is undone with one key, the answers as they were.
      asked.revealed = false;
    }
  }
  const double now = playback_->lesson().scene().time();
  if (hit(Key::w, false)) {
    window_.tools.stopwatch = true;  // a stopwatch started unseen would be no use
    tools_.stopwatch.start_stop(now);
  }
  if (hit(Key::l, false)) tools_.stopwatch.lap(now);
  // The plots' page buttons are drawn as ← and →: the keys turn the pages too.
  if (hit(Key::left, false)) --turn_plot_pages_;
  if (hit(Key::right, false)) ++turn_plot_pages_;
  if (hit(Key::d, false)) window_.theme = window_.theme == ThemeName::dark ? ThemeName::light : ThemeName::dark;
}

void Classroom::after_keys() {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  if (enter_for_typing_) {
    g.IO.KeysDown[g.IO.KeyMap[ImGuiKey_Enter]] = *enter_for_typing_;
    enter_for_typing_.reset();
  }
  // After the frame, so that a box in a menu took its Enter first.
  if (close_menus_) ImGui::ClosePopupToLevel(dialog_levels(), true);
  close_menus_ = false;
  // The Space that ended the typing plays once the value it kept has been set (a rebuild first).
  if (play_after_typing_) playback_->toggle();
  play_after_typing_ = false;
}

void Classroom::run_to(double t) {
  tools_.on = window_.tools;
  tools_.follow(playback_->lesson(), false);
  playback_->run_to(t);
}

bool Classroom::idle() const {
  return !playback_->playing() && !cheapest_.measuring() && !hand_.drags() && !screenshot_request_;
}

void Classroom::change_settings(const StepSettings& settings) {
  try {
    playback_->set_settings(settings);
  } catch (const InvalidInput& error) {
    status_ = error.what();
  }
}

void Classroom::set_value(const std::string& name, const lessons::GivenValue& value) {
  try {
    const double before = playback_->lesson().parameter(name).value;
    if (value.number) {
      playback_->set_parameter(name, *value.number);
    } else {
      playback_->set_parameter(name, value.text);
    }
    parameters_.errors.erase(name);
    mystery_.keep(name, before, *playback_, parameters_);
  } catch (const InvalidInput& error) {
    parameters_.errors[name] = error.what();
  }
}

std::string Classroom::script_words(const std::string& text) const {
  if (script_paths_) return text;
  // Each path to a ".lua" file in the text is left as the file's name: "/a/b/my_push.lua:26: x"
  // reads "my_push.lua:26: x", "Reloaded /lessons/push.lua." reads "Reloaded push.lua.".
  std::string words;
  std::size_t from = 0;
  for (std::size_t end = text.find(".lua"); end != std::string::npos; end = text.find(".lua", end + 4)) {
    // The path's start: after the blank, quote or bracket before it.
    std::size_t start = text.find_last_of(" \n\t'\"(", end);
    start = start == std::string::npos || start < from ? from : start + 1;
    const std::size_t last_slash = text.rfind('/', end);
    if (last_slash == std::string::npos || last_slash < start) continue;
    words += text.substr(from, start - from);
    from = last_slash + 1;
  }
  return words + text.substr(from);
}

std::string Classroom::status() const {
  if (status_moment_ && status_moment_->text == status_ &&
      (status_moment_->frame != playback_->lesson().scene().frame() || status_moment_->theory_hidden != theory_hidden())) {
    return "";
  }
  return status_;
}

std::string Classroom::transport_words() const {
  // Notices (the run is over, the file reloaded) and what was saved where, on one line.
  std::string said = script_words(playback_->notice());
  if (const std::string now = status(); !now.empty()) said += (said.empty() ? "" : "  ") + script_words(now);
  if (playback_->behind()) said = "running slower than asked  " + said;
  return said;
}

std::string Classroom::running_script_error() const {
  if (playback_->lesson().failed()) return playback_->lesson().last_error();
  if (!playback_->readings().error.empty()) return playback_->readings().error;
  return playback_->lesson().theory_error();
}

void Classroom::messages(ImVec2 corner, float width) {
  std::vector<std::pair<std::string, bool>> lines;  // text, is it a fault
  // A script's mistake, and under it Lua's message in plain words when it is a common one.
  const auto mistake = [&](const std::string& message, const std::string& then) {
    lines.push_back({script_words(message) + then, true});
    if (std::string plain = plain_words(message); !plain.empty()) lines.push_back({std::move(plain), false});
  };
  if (!failed_script_.empty()) {
    mistake(failed_error_, "  (showing " + lesson_name(playback_->lesson().path()) + " until " + lesson_name(failed_script_) + ".lua builds)");
  }
  if (!playback_->script_error().empty()) mistake(playback_->script_error(), "  (the last good version keeps running)");
  if (browser_ && playback_->lesson().failed()) {
    // The page's editor is where the student mends it (the desktop's advice is to save the file).
    mistake(playback_->lesson().last_error(), ". Mend it in the editor (Edit lesson) and Apply, or press R to start again.");
  } else if (!playback_->problem().empty()) {
    mistake(playback_->problem(), "");
  }
  if (lines.empty()) return;
  const Theme& colours = theme(window_.theme);
  ImGui::SetNextWindowPos(corner, ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, FLT_MAX));
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("###messages", nullptr, flags)) {
    ImGui::PushTextWrapPos(0.0f);
    for (const auto& [text, fault] : lines) {
      ImGui::PushStyleColor(ImGuiCol_Text, fault ? colours.bad : ImGui::GetColorU32(ImGuiCol_Text));
      shown_text(text.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
    controls_["messages"] = ImRect(ImGui::GetWindowPos(), ImGui::GetWindowPos() + ImGui::GetWindowSize());
  }
  ImGui::End();
}

std::string Classroom::open(const std::string& name_or_path) {
  try {
    // "~/steep_slope.lua", as a shell would have it.
    const char* home = std::getenv("HOME");
    const std::string named = name_or_path.rfind("~/", 0) == 0 && home != nullptr ? home + name_or_path.substr(1) : name_or_path;
    const std::string path = lessons::resolve_lesson(named);
    // The command line's --set values belong to the script it named.
    const bool named_script = path == failed_script_;
    auto next = std::make_unique<Playback>(path, named_script ? overrides_ : std::map<std::string, std::string>{},
                                           playback_->lesson().settings());
    check_lock(next->lesson());
    next->set_speed(playback_->speed());
    // Paused at t = 0, as a lesson opens.
    playback_ = std::move(next);
    mystery_.begin(std::nullopt);  // it was a pair of the lesson that closed
    predictions_.predictions = {};
    forget_interaction();
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

bool Classroom::waited(double seconds) { return watch_files(seconds); }

bool Classroom::watch_files(double wall_seconds) {
  const bool reloaded = playback_->watch_file(wall_seconds);
  return try_failed_script(wall_seconds) || reloaded;
}

bool Classroom::try_failed_script(double wall_seconds) {
  if (failed_script_.empty()) return false;
  since_failed_check_ += wall_seconds;
  if (since_failed_check_ < 0.25) return false;
  since_failed_check_ = 0.0;
  const FileStamp stamp = file_stamp(failed_script_);
  if (stamp == failed_stamp_) return false;
  failed_stamp_ = stamp;
  const std::string script = failed_script_;
  if (std::string error = open(script); !error.empty()) {
    failed_script_ = script;
    failed_error_ = error;
  }
  return true;
}

std::string Classroom::window_title() const {
  return "FrictionLab: " + playback_->lesson().title() + mystery_.title_words();
}

std::optional<std::string> Classroom::take_screenshot_request() {
  auto request = std::move(screenshot_request_);
  screenshot_request_.reset();
  return request;
}

void Classroom::screenshot_done(const std::string& path, const std::string& error) {
  status_ = error.empty() ? "Screenshot saved to " + path : "Could not save the screenshot: " + error;
}

bool Classroom::take_open_file_request() { return std::exchange(open_file_request_, false); }

bool Classroom::take_full_screen_toggle() {
  const bool toggle = full_screen_toggle_;
  full_screen_toggle_ = false;
  return toggle;
}

std::string Classroom::output_path(const std::string& stem, const std::string& extension) const {
  char time[32];
  std::snprintf(time, sizeof time, "_t%.2f", playback_->lesson().scene().time());
  return unused_path(output_folder_, stem + time, extension);
}

void Classroom::request_screenshot() {
  try {
    screenshot_request_ = output_path("frictionlab_" + lesson_name(playback_->lesson().path()), ".png");
  } catch (const std::exception& error) {
    status_ = std::string("Could not take a screenshot: ") + error.what();
  }
}

void Classroom::save_history() {
  try {
    status_ = "History saved to " + export_history();
  } catch (const std::exception& error) {
    status_ = std::string("Could not save the history: ") + error.what();
  }
}

std::string Classroom::export_history() {
  const lessons::Lesson& lesson = playback_->lesson();
  const Scene& scene = lesson.scene();
  // The one format `frictionlab run --csv` writes too (lessons/runtime/history_csv.h), with the
  // mouse's hand's columns filled in: whether it pulled in the step that ended at the row's
  // time, and what its force gauge read.
  std::string csv = lessons::csv_header(lesson);
  const std::vector<GaugeSample>& gauge = playback_->gauge().samples();
  std::size_t next_sample = 0;
  for (std::size_t i = 0; i < scene.times().size(); ++i) {
    const long frame = static_cast<long>(i) + 1;  // row i is the end of the scene's frame i + 1
    while (next_sample < gauge.size() && gauge[next_sample].frame < frame) ++next_sample;
    const bool pulled = next_sample < gauge.size() && gauge[next_sample].frame == frame;
    csv += lessons::csv_row(scene, i, pulled ? std::optional<double>(gauge[next_sample].force) : std::nullopt);
  }
  const std::string path = output_path("frictionlab_" + lesson_name(lesson.path()) + "_history", ".csv");
  // The values that made the run, beside it, so a file found later says which run it is; a
  // mystery's are "?". Only a settings file FrictionLab wrote is replaced there, and it is put
  // in place before the CSV, so no CSV is ever left without its settings.
  const HiddenValues hidden = hidden_values();
  const std::string settings = lessons::run_settings(lesson, [&](const std::string& name) { return hidden.hides(name); });
  {
    OutputFile settings_file(lessons::settings_path_for(path), lessons::frictionlab_settings_file);
    settings_file.write(settings);
    settings_file.commit();
  }
  write_whole_file(path, csv.data(), csv.size());
  return path;
}

}  // namespace frictionlab::ui
