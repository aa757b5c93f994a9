// The classroom window: a lesson's frame with everything that drives it around it. A menu bar
// (lessons, simulation settings, view), the transport bar (play, step, speed, the recorded
// run), sliders that also take typed values, the mouse's hand in the world, keyboard
// shortcuts and a help panel. Immediate mode: every panel reads the running lesson and acts
// on it through Playback; nothing here keeps a copy of the lesson's state.
//
// It knows nothing of windows: frame() runs between ImGui::NewFrame() and ImGui::Render() with
// input in ImGui's io, so the GLFW window and the tests (EGL, scripted input) run the same code.
#pragma once

#include <imgui.h>
#include <imgui_internal.h>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "classroom/cheapest_setting_tab.h"
#include "classroom/classroom_options.h"
#include "classroom/control_places.h"
#include "classroom/exports.h"
#include "classroom/host_requests.h"
#include "classroom/keys.h"
#include "classroom/lesson_file_watch.h"
#include "classroom/lesson_lock.h"
#include "classroom/measuring_tools.h"
#include "classroom/mystery_panel.h"
#include "classroom/open_script_dialog.h"
#include "classroom/parameters_panel.h"
#include "classroom/prediction_panel.h"
#include "classroom/script_messages.h"
#include "classroom/settings.h"
#include "classroom/setup_dialog.h"
#include "classroom/shortcut_keys.h"
#include "classroom/stability_map_tab.h"
#include "classroom/status_line.h"
#include "classroom/transport_bar.h"
#include "classroom/window_choice.h"
#include "classroom/world_hand.h"
#include "classroom_state/mystery.h"
#include "classroom_state/playback.h"
#include "classroom_state/setup_file.h"
#include "draw/chart.h"
#include "draw/frame.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

// The window composes its panels, tabs and dialogs (each a small struct that owns its state and
// draws itself) and routes what they ask of each other: a value set, a lesson opened or
// replaced, a key's meaning.
class Classroom {
 public:
  // Opens the lesson; a script that fails to build opens the first built-in lesson instead,
  // with the script's error shown and its file watched until it builds. Throws InvalidInput
  // when --lock names something the lesson does not have.
  explicit Classroom(ClassroomOptions options);

  // The size the host should prepare fonts at for a display of this size.
  float ui_scale(ImVec2 display) const;
  const WindowSettings& window_settings() const { return window_; }
  WindowSettings& window_settings() { return window_; }

  // One display frame: the keys and mouse in ImGui's io, `wall_seconds` of real time passing,
  // then the whole window built.
  // With `record`, where the frame put things and every text it drew (the layout test).
  void frame(const draw::Fonts& fonts, ImVec2 display, double wall_seconds, draw::FrameRecord* record = nullptr);

  classroom_state::Playback& playback() { return *playback_; }
  const classroom_state::Playback& playback() const { return *playback_; }

  // A key pressed, as the window layer reports it (each press once): a tap pressed and let go
  // between two frames (a slow machine, a quick finger) never shows in ImGui 1.86's per-frame
  // key state, so shortcuts come from here only.
  void key_pressed(Key key, bool ctrl) { shortcut_keys_.pressed(key, ctrl); }

  // Requests the host carries out after the frame is drawn, each taken once.
  std::optional<std::string> take_screenshot_request() { return exports_.take_screenshot_request(); }  // the path to save the window to
  void screenshot_done(const std::string& path, const std::string& error);
  bool take_full_screen_toggle() { return host_.take_full_screen_toggle(); }
  // The page's file chooser, asked for from the Lesson menu (ClassroomOptions::browser).
  bool take_open_file_request() { return host_.take_open_file(); }
  bool quit_requested() const { return host_.quit; }
  // Nothing moves until the user does something: paused, no search measuring between frames,
  // no hand held. The window then waits for input (a few times a second for the file watcher)
  // instead of drawing the same frame sixty times a second.
  bool idle() const;
  // Plays the lesson on to `t` at once, as the window opened with --at does: the measuring tools
  // take the run's start first (where the distance marks count from).
  void run_to(double t);
  // Time the window spent waiting for input while idle: no lesson time, but the file watchers'
  // clocks run on it, so a script saved while nobody touches the window is still seen (the
  // next frame, given no wall time, would never reach their quarter-second look).
  // The watchers look at once; true when what they found changes the picture (a script
  // reloaded, gone or back, a failed script that now opens): only then need the host draw.
  bool waited(double seconds);
  // What the status line says now (saved files, failures to save). Words about the run's
  // moment ("the run is back at t = 0, the theory hidden") go once the run has left it.
  std::string status() const;
  // The words beside the transport bar's time bar: the run's notices and the status line, of
  // the present state only.
  std::string transport_words() const;
  // The measuring tools (Tools menu): which are on, and the stopwatch.
  const MeasuringTools& tools() const { return tools_; }
  // A script named on the command line that does not build yet: its path ("" when none) and why.
  const FailedScript& failed_script() const { return watch_.failed; }
  // The running lesson's script failed while it ran, not when it loaded: an expect row's
  // function (the theory table is then empty), an every-step function (the run stopped) or a
  // plot's theory curve (drawn only once the theory shows).
  // Its message as Lua gives it ("path:line: ..."); "" while neither.
  std::string running_script_error() const;

  // Opens another lesson (a built-in name or a script's path). On failure the current lesson
  // keeps running and the message is returned (also shown in the window); "" on success.
  std::string open(const std::string& name_or_path);
  // Writes the record (time and every probe, one row per frame) as CSV into the output
  // folder; returns the path, or throws std::runtime_error.
  std::string export_history() const { return exports_.export_history(*playback_, mystery_.hidden()); }

  // The mystery pair, if the teacher made one (--mystery, or the Mystery menu).
  // Its actions are the mystery panel's (classroom/mystery_panel.h); these forward to it.
  const std::optional<classroom_state::Mystery>& mystery() const { return mystery_.mystery; }
  // Makes a pair of the running lesson a mystery: its μs and μk drawn from the seed, hidden
  // until revealed, the lesson back at t = 0. Returns "" or why not (the lesson keeps running).
  std::string make_mystery(const classroom_state::MysteryChoice& choice) { return mystery_.make(choice, *playback_, parameters_); }
  void reveal_mystery() { mystery_.reveal(); }
  // The class's answers, as typed in the Mystery tab.
  void answer_mystery(std::optional<double> mu_s, std::optional<double> mu_k) { mystery_.answer(mu_s, mu_k); }

  // Opens a prepared setup (classroom_state/setup_file.h): its lesson with its values, lock and mystery, at
  // t = 0. On failure the running lesson keeps running and the message ("file:line: ...") is
  // returned (also shown in the window); "" on success.
  std::string open_setup(const std::string& path);
  // The window as a setup saved at `path` would hold it: the lesson (named from there), every
  // value but a mystery's, the lock, the mystery's pair and seed, the step settings, whether
  // predictions are asked, the class's answers to the lesson's predict rows and the reveal.
  classroom_state::PreparedSetup current_setup(const std::string& path) const;
  // Writes current_setup to `path` (never over a .lua script or a file that is not a setup
  // FrictionLab wrote, nor with a typed prediction that is not a number). Returns "" or why not.
  std::string save_setup(const std::string& path);
  // The window's title: the program and the lesson (never a hidden value).
  std::string window_title() const;

  // Where the named control was drawn in the last frame ("mu_s slider", "mu_s value",
  // "mu_s reset", "play", "step", "reset", "speed", "scrub"...), for tests that click it.
  std::optional<ImRect> control(const std::string& name) const;
  // The Cheapest setting tab (its tolerance as typed, whether a search was started), and the
  // Stability map tab (its chart as last drawn: the map and this lesson's marks).
  const CheapestSettingTab& cheapest_setting_tab() const { return cheapest_; }
  const StabilityMapTab& stability_map_tab() const { return stability_; }
  bool shown(const std::string& control_name) const { return lock_.shown(control_name); }  // --lock
  // Why the Lesson menu's lessons are greyed, and how to unlock them; "" when nothing is locked.
  std::string lock_words() const { return lock_.words(browser_); }
  // The world view's cameras in the last frame (one per lane): where the mouse's hand finds
  // bodies. The first one.
  const draw::Camera& world_camera() const { return hand_.cameras.front(); }
  // The wheel's zoom and the drag's pan on the lesson's view; a double click on empty space
  // (or opening another lesson) puts the view back.
  const draw::ViewAdjust& view_adjust() const { return hand_.view_adjust; }
  // The class's predictions for the lesson on screen (typed in the theory panel before Play),
  // and whether the theory is still kept from the class.
  classroom_state::ClassPredictions& predictions() { return predictions_.predictions; }
  bool theory_hidden() const { return predictions_.theory_hidden(playback_->lesson(), window_.predictions); }
  // The message beside a control whose value was refused; empty when there is none.
  std::string control_error(const std::string& name) const {
    const auto found = parameters_.errors.find(name);
    return found == parameters_.errors.end() ? "" : found->second;
  }

  // The force gauge's figures over its plot: "peak 39.4 N,  sliding 29.1 N", or "hand + spring:
  // peak ..." when the lesson pulled the body too; "" before the hand pulls.
  std::string gauge_figures() const;

 private:
  // What frame() draws, in its order. The lesson's time and the files watched moved on, with the
  // keys' shortcuts carried out and the tools following the lesson first.
  void advance(double wall_seconds);
  // The window's strips over and under the lesson's frame, and the room they leave it.
  struct WindowStrips {
    ImVec2 origin, area;            // the lesson's frame: its corner, under the menu bar and the stopwatch, and its size
    float help_height = 0.0f;       // the help panel's strip, at the frame's foot under its column (0 while it is closed)
    float transport_height = 0.0f;  // the transport bar's, at the window's foot
    std::string transport_room;     // the words the transport bar keeps room for (the run's end notice)
  };
  // The menu bar and the stopwatch's strip under it; the help's strip's height.
  WindowStrips draw_top_strips(ImVec2 display);
  // How the lesson's frame is drawn, with the panels and plots the window puts in it.
  draw::FrameStyle frame_style(ImVec2 origin, draw::FrameRecord* record);
  // The tabs the window adds beside the lesson's own (FrameStyle::more_tabs).
  void draw_more_tabs();
  // The mouse's hand, then the script's messages over the world's ground, the transport bar,
  // the help panel and the windows and dialogs over the frame.
  void draw_around_frame(ImVec2 display, const WindowStrips& strips);
  // The values the panels asked for while drawn, set now that nothing reads the lesson.
  void apply_asked_values();
  // What the menu bar's menus or the keys' shortcuts chose, each given to what it drives: a
  // lesson or setup opened, a dialog asked for, a file saved, the run moved, the view changed.
  void carry_out(const WindowChoice& chosen);
  // Forgets what the hands and boxes were doing in the lesson that is being replaced.
  void forget_interaction();
  // The lesson as the Parameters panel shows it now.
  ParametersOnShow parameters_on_show() const;
  // Whose forces the world draws now (a body a student's script no longer makes: every body's).
  ForcesShown forces_shown() const;
  void change_settings(const StepSettings& settings);

  std::unique_ptr<classroom_state::Playback> playback_;
  WindowSettings window_;
  MeasuringTools tools_;
  LessonLock lock_;
  ScriptWords script_words_;
  bool browser_ = false;
  HostRequests host_;
  // The readings with their error in script_words, for the theory panel (script_paths off).
  lessons::LessonReadings shown_readings_;
  // The moving body whose forces alone the world draws (View > Forces on, B), by name, for a
  // rebuilt world has new bodies; empty: every body's. Every lesson opens with every body's.
  std::string forces_on_;

 public:
  // A text as the class sees it: with script_paths off, every script's path in it ("path:line:
  // ...", "Reloaded path.") is its file's name alone.
  std::string script_words(const std::string& text) const { return script_words_(text); }

 private:
  const draw::Fonts* fonts_ = nullptr;

  // Interaction state only: what is being dragged, typed or asked for.
  ControlPlaces controls_;
  ShortcutKeys shortcut_keys_;
  PredictionPanel predictions_;
  ParametersPanel parameters_;
  TransportBar transport_;
  WorldHand hand_;
  Exports exports_;
  CheapestSettingTab cheapest_;
  StabilityMapTab stability_;
  MysteryPanel mystery_;
  SetupDialog setup_dialog_;
  OpenScriptDialog open_script_;
  StatusLine status_;
  LessonFileWatch watch_;  // the running lesson's script and the command line's that failed
};

}  // namespace frictionlab::classroom
