// frictionlab [LESSON]: the classroom window. Without a display it says so and draws the lesson
// to a PNG instead, so the main command always shows something.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "app/command_line.h"
#include "app/modes.h"
#include "app/options.h"
#include "desktop/window.h"
#include "draw/image.h"
#include "lessons/runtime/catalog.h"
#include "physics/validation.h"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

struct WindowOptions {
  std::string lesson;
  std::vector<std::string> lock;
  std::map<std::string, std::string> overrides;
  StepSettings settings;
  std::optional<draw::ThemeName> theme;
  bool projector = false;
  std::optional<double> at;
  std::string screenshot;
  bool reveal = false;     // --reveal: the picture with the theory shown
  MysteryOptions mystery;  // --mystery PAIR --seed N
  std::string setup;       // --setup FILE: the lesson, values, lock and mystery from a prepared setup
};

std::vector<std::string> split_names(const std::string& option, const std::string& text) {
  std::vector<std::string> names;
  std::stringstream parts(text);
  std::string part;
  while (std::getline(parts, part, ',')) names.push_back(part);
  // getline drops a trailing empty part: "mu_s," must be refused like "mu_s,,mu_k".
  const bool empty_name = text.empty() || text.back() == ',' || std::find(names.begin(), names.end(), "") != names.end();
  if (empty_name) throw InvalidInput(option + " " + text + ": give names separated by commas, as in " + option + " mu_s,mu_k");
  return names;
}

WindowOptions parse_window(const std::vector<std::string>& args) {
  WindowOptions options;
  std::vector<std::string_view> given_options;  // for --setup, which holds some of them
  const auto lesson = [&](const std::string& word) {
    if (!options.lesson.empty()) throw InvalidInput("the window takes one lesson, got '" + options.lesson + "' and '" + word + "'");
    options.lesson = word;
  };
  read_options(Command::window, args, lesson, [&](const Option& option, const std::string& value) {
    given_options.push_back(option.name);
    if (options.mystery.take(option, value)) return;
    const std::string_view name = option.name;
    if (name == "--projector") {
      options.projector = true;
    } else if (name == "--setup") {
      options.setup = value;
    } else if (name == "--lock") {
      options.lock = split_names("--lock", value);
    } else if (name == "--set") {
      add_override(value, options.overrides);
    } else if (name == "--theme") {
      try {
        options.theme = draw::parse_theme(value);
      } catch (const InvalidInput& error) {
        throw InvalidInput("--theme " + value + ": " + error.what());
      }
    } else if (name == "--at") {
      options.at = option.number(value);
    } else if (name == "--screenshot") {
      const fs::path path(value);
      if (path.extension() != ".png") throw InvalidInput("--screenshot " + value + ": screenshots are written as PNG; give a .png file");
      if (!path.parent_path().empty() && !fs::is_directory(path.parent_path())) {
        throw InvalidInput("--screenshot " + value + ": the folder " + path.parent_path().string() + " does not exist");
      }
      options.screenshot = value;
    } else if (name == "--reveal") {
      options.reveal = true;
    } else {
      bool stepped = false;
      try {
        stepped = step_option(option, value, options.settings);
      } catch (const InvalidInput& error) {
        throw InvalidInput(name == "--friction" ? "--friction " + value + ": " + error.what() : error.what());
      }
      if (!stepped) throw std::logic_error("the window does not read " + std::string(name) + ", which the options table gives it");
    }
  });
  // The reveal is a teacher's key in a window; on the command line it is for a picture's sake.
  if (options.reveal && options.screenshot.empty()) {
    throw InvalidInput("--reveal shows the theory in a --screenshot picture; in the window, T reveals it: give --screenshot FILE.png, or leave --reveal out");
  }
  options.mystery.choice();  // --mystery without --seed, or the other way round, refused before the window opens
  if (!options.setup.empty()) {
    // The setup holds these: given beside it, which one was meant is not for the program to guess.
    std::string given = options.lesson.empty() ? "" : "the lesson '" + options.lesson + "'";
    for (const Option& option : options_table()) {
      if (!given.empty() || !option.held_by_setup || !includes(option.commands, Command::window)) continue;
      if (std::find(given_options.begin(), given_options.end(), option.name) != given_options.end()) given = option.name;
    }
    if (!given.empty()) {
      throw InvalidInput("--setup " + options.setup + " holds the lesson, its values, the lock and the mystery: give " + given +
                         " in the setup file, or leave --setup out");
    }
  }
  return options;
}

std::string time_text(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", t);
  return text;
}

}  // namespace

void parse_window_arguments(const std::vector<std::string>& args) { parse_window(args); }

int run_window_mode(const std::vector<std::string>& args, std::ostream& out) {
  const WindowOptions options = parse_window(args);
  const std::string path = !options.setup.empty() ? ""
                           : lessons::resolve_lesson(options.lesson.empty() ? lessons::builtin_lessons().front() : options.lesson);
  // The window's settings come from the settings folder; a screenshot run reads them (the
  // README's screenshot script gives each shot a folder of its own) but never writes them.
  const std::string folder = classroom::settings_folder();
  const std::string settings_path = folder.empty() ? "" : folder + "/settings.ini";
  classroom::ClassroomOptions classroom_options;
  classroom_options.lesson = path;
  classroom_options.overrides = options.overrides;
  classroom_options.settings = options.settings;
  classroom_options.lock = options.lock;
  classroom_options.mystery = options.mystery.choice();
  classroom_options.window = settings_path.empty() ? classroom::WindowSettings{} : classroom::load_settings(settings_path);
  // What the settings file brought back, before the command line and a setup have their say:
  // `--projector` on a new machine is no projector mode kept from the last session.
  const std::string kept = classroom::kept_from_last_session(classroom_options.window);
  classroom_options.window.help =
      classroom::opens_with_help(classroom_options.window.help, settings_path.empty() || !fs::exists(settings_path),
                                 options.projector, !options.screenshot.empty());
  if (options.theme) classroom_options.window.theme = *options.theme;
  if (options.projector) classroom_options.window.projector = true;
  // A prepared setup: read and checked against its lesson before the window opens.
  if (!options.setup.empty()) classroom_options = classroom::setup_options(options.setup, classroom_options);
  // A picture is no session: what came back from the last one is said to a person only.
  if (options.screenshot.empty()) {
    std::string& notice = classroom_options.opening_notice;
    if (!kept.empty()) notice = notice.empty() ? kept : notice + " " + kept;
  }
  classroom::Classroom classroom(classroom_options);
  // T in the first frame, after the run to --at: the picture a class sees once it is revealed.
  if (options.reveal && classroom.theory_hidden()) classroom.key_pressed(classroom::Key::t, false);

  desktop::WindowRun run;
  run.at = options.at;
  run.screenshot = options.screenshot;
  run.fill_screen = options.projector;
  if (options.screenshot.empty() && !folder.empty()) {
    run.settings_path = settings_path;
    run.imgui_ini = folder + "/imgui.ini";
  }
  try {
    desktop::run_window(classroom, run);
  } catch (const desktop::NoDisplay& error) {
    if (!options.screenshot.empty()) throw InvalidInput(std::string("--screenshot needs a display: ") + error.what());
    // A script that does not build has no picture to give: its mistake is the answer.
    if (!classroom.failed_script().path.empty()) throw InvalidInput(classroom.failed_script().error);
    // No window here (a server, CI, a remote shell): the same lesson as a picture instead.
    const double at = options.at ? *options.at : 0.5 * classroom.playback().readings().duration;
    const std::string& lesson = classroom_options.lesson;  // the setup's, with --setup
    const std::string stem = fs::path(lesson).stem().string();
    const std::string picture =
        draw::unused_path(fs::current_path().string(), "frictionlab_" + stem + "_t" + time_text(at), ".png");
    out << "frictionlab: " << error.what() << ", so no window; drawing " << stem << " at t = " << time_text(at)
        << " s to a PNG instead (frictionlab render draws any moment):\n";
    std::vector<std::string> render_args{lesson, "--at", time_text(at), "--out", picture};
    for (const auto& [name, value] : classroom_options.overrides) render_args.insert(render_args.end(), {"--set", name + "=" + value});
    const StepSettings& settings = classroom_options.settings;
    render_args.insert(render_args.end(), {"--hz", validation::exact_text(settings.hz), "--substeps", std::to_string(settings.substeps),
                                           "--friction", std::string(treatment_name(settings.treatment))});
    if (const auto& mystery = classroom_options.mystery) {
      render_args.insert(render_args.end(), {"--mystery", mystery->pair, "--seed", std::to_string(mystery->seed)});
    }
    if (options.theme) render_args.insert(render_args.end(), {"--theme", std::string(draw::theme_name(*options.theme))});
    return run_render(render_args, out);
  }
  return 0;
}

}  // namespace frictionlab
