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
#include <map>
#include <optional>
#include <sstream>
#include <utility>

#include "classroom/force_gauge.h"
#include "classroom/help_panel.h"
#include "classroom/menu_bar.h"
#include "classroom/world_tools.h"
#include "draw/frame.h"
#include "lessons/runtime/catalog.h"

namespace frictionlab::classroom {

Classroom::Classroom(ClassroomOptions options)
    : window_(options.window),
      lock_{std::set<std::string>(options.lock.begin(), options.lock.end()), options.lock_from},
      script_words_{options.script_paths},
      browser_(options.browser) {
  // A whole path on a computer: the status line's "History saved to ./frictionlab_…csv" told a
  // teacher who started the window from a menu nothing of where it went (a teacher's trial).
  // The page's downloads keep their one name, "Downloads", which is what the browser shows.
  exports_.folder = options.output_folder;
  if (!browser_) {
    std::error_code error;
    const std::filesystem::path whole = std::filesystem::weakly_canonical(std::filesystem::absolute(options.output_folder), error);
    if (!error) exports_.folder = whole.string();
  }
  watch_.overrides = options.overrides;
  const classroom_state::FileStamp stamp = classroom_state::file_stamp(options.lesson);  // before it is read: a save meanwhile is seen
  try {
    std::optional<classroom_state::Mystery> mystery;
    playback_ = MysteryPanel::build_playback(options.lesson, options.overrides, options.settings, options.mystery, mystery);
    lock_.check(playback_->lesson());
    mystery_.begin(std::move(mystery));
    predictions_.begin(options.predictions);  // a prepared setup's; another lesson in its place asks again
  } catch (const lessons::ScriptError& error) {
    // A student's broken script: show why beside a working lesson, and open it once it builds,
    // with the --set values and the lock it was opened with.
    watch_.failed.path = options.lesson;
    watch_.failed.error = error.what();
    watch_.failed.stamp = stamp;
    playback_ = std::make_unique<classroom_state::Playback>(lessons::resolve_lesson(lessons::builtin_lessons().front()),
                                           std::map<std::string, std::string>{}, options.settings);
  }
  playback_->set_speed(window_.speed);
  // A lesson opens paused at t = 0, its first frame drawn: the class sees the setup, and
  // predicts, before anything moves; Space plays. A stopwatch the options ask for is armed
  // now, at t = 0: a window opened at a later time (--at) has it read the run up to there.
  tools_.on = window_.tools;
  tools_.arm_stopwatch(0.0, false);
  // What the window opened with (a session's kept settings, a link's lesson) is news of the
  // opening: said until the run leaves it, so that it never crowds out what is said later (the
  // notice past the run's end was cut behind it on a projector's two lines).
  if (!options.opening_notice.empty()) {
    status_.say_of_moment(options.opening_notice, playback_->lesson().scene().frame(), theory_hidden());
  }
}

void Classroom::forget_interaction() {
  parameters_.forget();
  hand_.forget();
  watch_.failed.path.clear();
  tools_.stopwatch.reset();  // it timed a run of the lesson that closed
  forces_on_.clear();        // a body of the lesson that closed
}

ForcesShown Classroom::forces_shown() const {
  ForcesShown shown;
  for (const auto& [name, body] : playback_->lesson().scene().bodies()) {
    if (body->GetType() == b2_dynamicBody) shown.bodies.push_back(name);
  }
  if (std::find(shown.bodies.begin(), shown.bodies.end(), forces_on_) != shown.bodies.end()) shown.on = forces_on_;
  return shown;
}

float Classroom::ui_scale(ImVec2 display) const {
  const float fit = draw::frame_scale(static_cast<int>(display.x), static_cast<int>(display.y));
  // Projector mode: a third larger, text and lines alike, for the back of the room.
  return std::max(0.5f, fit) * (window_.projector ? 1.35f : 1.0f);
}

ParametersOnShow Classroom::parameters_on_show() const {
  const lessons::Lesson& lesson = playback_->lesson();
  // Whether the class's answers may have the panel's room is the same from the lesson's opening
  // to the run's end and after R: the trial's Parameters panel folded as the run ended and its
  // tabs jumped up under the teacher's pointer.
  return {lesson, lock_.names, mystery_.mystery, mystery_.hidden(), window_.predictions && !lesson.predictions().empty()};
}

std::optional<ImRect> Classroom::control(const std::string& name) const {
  const auto found = controls_.find(name);
  if (found == controls_.end()) return std::nullopt;
  return found->second;
}

void Classroom::frame(const draw::Fonts& fonts, ImVec2 display, double wall_seconds, draw::FrameRecord* record) {
  fonts_ = &fonts;
  std::optional<draw::TextRecording> noting;
  if (record != nullptr) {
    *record = draw::FrameRecord{};
    noting.emplace(&record->texts);
  }
  controls_.clear();
  advance(wall_seconds);
  // In the order they are drawn: the strips over the lesson's frame, the frame with the panels it
  // holds, then what lies over it or under it; the values the panels asked for once all is drawn.
  const WindowStrips strips = draw_top_strips(display);
  hand_.projector = window_.projector;
  hand_.hold_view(*playback_, strips.origin, strips.area, fonts.scale);
  // Made before the lesson is read for its frame: it forgets the answers a changed value outdated.
  draw::FrameStyle style = frame_style(strips.origin, record);
  style.column_foot = strips.help_height;
  build_frame(playback_->lesson(), playback_->framing(), style, strips.area);
  draw_around_frame(display, strips);
  apply_asked_values();
}

void Classroom::advance(double wall_seconds) {
  carry_out(shortcut_keys_.route(window_.theme));
  // One setting of the cheapest-setting search a frame: the window stays live while it measures.
  cheapest_.measure_next();
  playback_->advance(wall_seconds);
  watch_.look(*playback_, wall_seconds, [this](const std::string& path) { return open(path); });
  tools_.on = window_.tools;
  tools_.follow(playback_->lesson(), playback_->playing(), playback_->at_run_end());
}

Classroom::WindowStrips Classroom::draw_top_strips(ImVec2 display) {
  const float s = fonts_->scale;
  WindowStrips strips;
  ImGui::PushFont(fonts_->body);
  MenuBar{playback_, window_, lock_, browser_, script_words_, mystery_, predictions_, tools_, forces_shown(), controls_}.draw(
      [this](const WindowChoice& chosen) { carry_out(chosen); });
  const float menu_height = ImGui::GetFrameHeight();
  // The transport bar's words have their place from the lesson's opening (the run's end notice's).
  strips.transport_room = playback_->run_end_notice();
  strips.transport_height = TransportBar::shape(strips.transport_room, display.x, s, fonts_->small).height;
  // The stopwatch over the title: in the world's first lane it was written across the lanes'
  // names and bodies (terrain's "asphalt box"), and squeezed out of thin lanes.
  // It reads the lesson's one clock, whatever the lanes.
  const float stopwatch_height = MeasuringTools::stopwatch_strip_height(window_.tools.stopwatch, s);
  if (stopwatch_height > 0.0f) {
    tools_.draw_stopwatch_strip(ImVec2(0.0f, menu_height), ImVec2(display.x, stopwatch_height),
                                playback_->lesson().scene().time(), *fonts_);
  }
  // The help's strip over the transport bar, in the body's text that the panel is drawn in. It
  // takes its height from the column's foot, not from the whole frame: a frame laid out above it
  // shrank the world and the plots the class watches (a world on a projector, 336 px high, to
  // 235: stacked_blocks' labels crowded off their arrows and the legend's scale bar was cut),
  // and they changed size as F1 was pressed. The column is the teacher's, who is reading the help.
  strips.help_height = help_strip_height(window_.help);
  ImGui::PopFont();
  strips.origin = ImVec2(0.0f, menu_height + stopwatch_height);
  strips.area = ImVec2(display.x, std::max(1.0f, display.y - menu_height - stopwatch_height - strips.transport_height));
  return strips;
}

draw::FrameStyle Classroom::frame_style(ImVec2 origin, draw::FrameRecord* record) {
  draw::FrameStyle style;
  style.theme = window_.theme;
  style.fonts = fonts_;
  style.origin = origin;
  style.readings = &playback_->readings();
  if (!script_words_.paths && !playback_->readings().error.empty()) {
    shown_readings_ = playback_->readings();
    shown_readings_.error = script_words(shown_readings_.error);
    style.readings = &shown_readings_;
  }
  if (!script_words_.paths) style.script_words = script_words_;
  style.view_adjust = hand_.view_adjust;
  style.projector = window_.projector;
  if (const ForcesShown forces = forces_shown(); !forces.on.empty()) style.forces_on = playback_->lesson().scene().body(forces.on);
  style.record = record;
  style.parameters_panel = [this](ImVec2 corner, ImVec2 size, std::size_t step) {
    parameters_.draw(corner, size, step, parameters_on_show(), fonts_->scale, theme(window_.theme), controls_);
  };
  style.world_tools = WorldTools{*playback_, tools_, hand_, theme(window_.theme), *fonts_};
  if (!playback_->gauge().empty()) {
    style.extra_plot_title = gauge_plot_title(playback_->gauge(), playback_->lesson().scene().frame_step());
    style.extra_plot = [this](ImVec2 corner, ImVec2 size) {
      return draw_gauge_plot(corner, size, playback_->gauge(), playback_->lesson().scene().frame_step(),
                             theme(window_.theme), *fonts_, window_.projector);
    };
    style.show_extra_plot = hand_.held;
  }
  style.hidden = mystery_.hidden();
  style.turn_plot_pages = shortcut_keys_.take_plot_pages();
  style.more_tabs = [this] { draw_more_tabs(); };
  if (std::string said = predictions_.forget_outdated(*playback_); !said.empty()) status_.text = said;
  predictions_.style(style, *playback_, window_.predictions, theme(window_.theme), controls_,
                     [this] { return mystery_.hidden().theory(); });
  ImGui::PushFont(fonts_->body);
  style.parameters_heights = parameters_.heights(parameters_on_show());
  style.parameters_step_for_the_theory = parameters_.last_step_with_sliders(parameters_on_show());
  ImGui::PopFont();
  return style;
}

void Classroom::carry_out(const WindowChoice& chosen) {
  const LessonMenuChoice& lesson = chosen.lesson;
  if (lesson.open) status_.text = open(*lesson.open);
  if (lesson.open_file) host_.open_file = true;
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
  // From here in the order the keys' shortcuts have always been carried out in, several keys
  // of one frame at once (a menu chooses one item a frame).
  if (lesson.screenshot) {
    if (std::string why = exports_.request_screenshot(playback_->lesson()); !why.empty()) status_.text = why;
  }
  if (lesson.export_history) status_.text = exports_.save_history(*playback_, mystery_.hidden());
  if (chosen.play_pause) playback_->toggle();
  if (chosen.step) playback_->step_once();
  if (chosen.step_back) playback_->scrub_to(playback_->lesson().scene().time() - playback_->lesson().scene().frame_step());
  if (chosen.simulation.settings) change_settings(*chosen.simulation.settings);
  if (chosen.simulation.reset) playback_->reset();
  if (lesson.reload) playback_->reload();
  if (chosen.view.full_screen) host_.full_screen_toggle = true;
  if (chosen.view.help) window_.help = !window_.help;
  if (chosen.view.projector) window_.projector = !window_.projector;
  if (chosen.reveal) predictions_.reveal_key(playback_->lesson(), window_.predictions);
  const double now = playback_->lesson().scene().time();
  if (chosen.stopwatch_start_stop) {
    window_.tools.stopwatch = true;  // a stopwatch started unseen would be no use
    tools_.stopwatch.start_stop(now);
  }
  if (chosen.stopwatch_lap) tools_.stopwatch.lap(now);
  if (chosen.view.theme) window_.theme = *chosen.view.theme;
  if (chosen.view.forces_on) forces_on_ = *chosen.view.forces_on;
  if (chosen.view.forces_on_next) forces_on_ = next_forces_on(forces_shown());
  if (chosen.mystery.make) status_.text = make_mystery(*chosen.mystery.make);
  if (chosen.mystery.reveal) reveal_mystery();
  if (chosen.said) status_.say_of_moment(*chosen.said, playback_->lesson().scene().frame(), theory_hidden());
  if (lesson.quit) host_.quit = true;
}

std::string Classroom::gauge_figures() const {
  return classroom::gauge_figures(playback_->gauge(), playback_->lesson().scene().frame_step());
}

void Classroom::draw_more_tabs() {
  if (mystery_.mystery) mystery_.tab.draw_tab(*mystery_.mystery, theory_hidden(), theme(window_.theme), controls_);
  if (const std::optional<StepSettings> use = cheapest_.draw(playback_->lesson(), fonts_->scale, theme(window_.theme), controls_)) {
    change_settings(*use);
  }
  // The map's boundary would give a mystery's μs away: until the reveal the Mystery tab takes
  // the map's place. Revealed, the map comes back beside it, for the μs the class has just been
  // told; but not in projector mode, where six tabs do not fit the column side by side and
  // every tab would shrink and move at the reveal (nothing may move under the teacher's pointer).
  const bool map_shown = !mystery_.mystery || (mystery_.mystery->revealed() && !window_.projector);
  if (map_shown) stability_.draw_tab(playback_->lesson(), mystery_.hidden(), controls_);
}

void Classroom::draw_around_frame(ImVec2 display, const WindowStrips& strips) {
  const float s = fonts_->scale;
  ImGui::PushFont(fonts_->body);
  hand_.handle_mouse(*playback_, strips.origin, strips.area, s, status_.text);
  const draw::FrameLayout layout = draw::FrameLayout::of(strips.area, s, strips.origin, window_.projector, playback_->lesson());
  // Over the ground, under the bodies: a lesson's bodies mostly stand on it.
  messages_panel(ImVec2(layout.world_corner.x + 6.0f * s, layout.world_corner.y + layout.world_size.y - 6.0f * s),
                 layout.world_size.x - 12.0f * s, *playback_, watch_.failed, browser_, script_words_, theme(window_.theme), controls_);
  transport_.draw(ImVec2(0.0f, display.y - strips.transport_height), ImVec2(display.x, strips.transport_height), *playback_,
                  transport_words(), strips.transport_room, s, fonts_->small, window_.speed, controls_);
  // Under the column, as wide as it, at the frame's foot (FrameStyle::column_foot).
  help_panel(window_.help, browser_, script_words_.paths, exports_.folder,
             ImVec2(layout.column_corner.x, strips.origin.y + strips.area.y - strips.help_height),
             ImVec2(display.x - layout.column_corner.x, strips.help_height));
  stability_.draw_window(playback_->lesson(), mystery_.hidden(), theme(window_.theme), *fonts_);
  open_script_.draw([this](const std::string& path) { return open(path); }, s, theme(window_.theme));
  const SetupFiles setups{[this](const std::string& path) { return open_setup(path); },
                          [this](const std::string& path) { return save_setup(path); }};
  if (std::string said = setup_dialog_.draw(playback_->lesson().path(), exports_.folder, setups, s, theme(window_.theme), controls_);
      !said.empty()) {
    status_.text = said;
  }
  ImGui::PopFont();
}

void Classroom::apply_asked_values() {
  // Values asked for while the panels were drawn: applied now, since a rebuild replaces what
  // the panels were reading.
  // Each goes to the playback as it came: a number as the number, a typed text for the lesson to
  // read. A refusal is said beside its control; a value taken lets the mystery keep its pair.
  for (const auto& [name, value] : parameters_.asked) {
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
      parameters_.errors[name] = refusal_in_class_words(playback_->lesson().parameter(name), error.what());
    }
  }
  parameters_.asked.clear();
  // The Space that ended the typing plays once the value it kept has been set (a rebuild first).
  if (shortcut_keys_.finish()) playback_->toggle();
}

void Classroom::run_to(double t) {
  tools_.on = window_.tools;
  tools_.follow(playback_->lesson(), false);
  playback_->run_to(t);
}

bool Classroom::idle() const {
  return !playback_->playing() && !cheapest_.measuring() && !hand_.drags() && !exports_.screenshot_asked();
}

void Classroom::change_settings(const StepSettings& settings) {
  try {
    playback_->set_settings(settings);
  } catch (const InvalidInput& error) {
    status_.text = error.what();
  }
}

std::string Classroom::status() const { return status_.now(playback_->lesson().scene().frame(), theory_hidden()); }

std::string Classroom::transport_words() const {
  // Notices (the run is over, the file reloaded) and what was saved where, on one line.
  // A notice (a body fell off, the file reloaded) says what just happened, and the past-end
  // words wait until it is gone: the two together were cut in the middle on a projector's two
  // lines ("R starts again; … its rows.", a teacher's trial).
  std::string said = script_words(playback_->notice());
  if (const std::string past = playback_->past_end_words(); !past.empty() && said.empty()) said = past;
  if (const std::string now = status(); !now.empty()) said += (said.empty() ? "" : "  ") + script_words(now);
  if (playback_->behind()) said = "running slower than asked  " + said;
  return said;
}

std::string Classroom::running_script_error() const {
  if (playback_->lesson().failed()) return playback_->lesson().last_error();
  if (!playback_->readings().error.empty()) return playback_->readings().error;
  return playback_->lesson().theory_error();
}

std::string Classroom::open(const std::string& name_or_path) {
  try {
    // "~/steep_slope.lua", as a shell would have it.
    const char* home = std::getenv("HOME");
    const std::string named = name_or_path.rfind("~/", 0) == 0 && home != nullptr ? home + name_or_path.substr(1) : name_or_path;
    const std::string path = lessons::resolve_lesson(named);
    // The command line's --set values belong to the script it named.
    auto next = std::make_unique<classroom_state::Playback>(path, watch_.overrides_for(path), playback_->lesson().settings());
    lock_.check(next->lesson());
    next->set_speed(playback_->speed());
    // Paused at t = 0, as a lesson opens.
    playback_ = std::move(next);
    mystery_.begin(std::nullopt);  // it was a pair of the lesson that closed
    predictions_.begin({});
    forget_interaction();
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

std::string Classroom::open_setup(const std::string& path) {
  try {
    ClassroomOptions base;
    base.window = window_;
    const ClassroomOptions options = setup_options(path, base);
    std::optional<classroom_state::Mystery> mystery;
    auto next = MysteryPanel::build_playback(options.lesson, options.overrides, options.settings, options.mystery, mystery);
    next->set_speed(playback_->speed());
    // Paused at t = 0, as a lesson opens; the setup's lock in place of the one before.
    playback_ = std::move(next);
    lock_ = LessonLock{std::set<std::string>(options.lock.begin(), options.lock.end()), options.lock_from};
    // The setup's predictions, never the last lesson's; asked or not as it says (else as before).
    predictions_.begin(options.predictions);
    window_.predictions = options.window.predictions;
    forget_interaction();
    mystery_.begin(std::move(mystery));
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

classroom_state::PreparedSetup Classroom::current_setup(const std::string& path) const {
  return SetupDialog::of_window(path, playback_->lesson(), lock_.names, mystery_, window_.predictions, predictions_.predictions);
}

std::string Classroom::save_setup(const std::string& path) {
  std::string why = SetupDialog::save(path, current_setup(path), playback_->lesson());
  if (why.empty()) status_.text = "Setup saved to " + path;
  return why;
}

bool Classroom::waited(double seconds) {
  return watch_.look(*playback_, seconds, [this](const std::string& path) { return open(path); });
}

std::string Classroom::window_title() const {
  return "FrictionLab: " + playback_->lesson().title() + mystery_.title_words();
}

void Classroom::screenshot_done(const std::string& path, const std::string& error) {
  status_.text = error.empty() ? "Screenshot saved to " + path : "Could not save the screenshot: " + error;
}

}  // namespace frictionlab::classroom
