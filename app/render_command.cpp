// frictionlab render: a lesson's frames as PNG files, with no display and no GPU.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "app/command_line.h"
#include "app/modes.h"
#include "app/options.h"
#include "app/table.h"
#include "draw/headless_render.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string lesson;
  std::vector<double> times;
  int width = 1280, height = 720;
  draw::ThemeName theme = draw::ThemeName::light;
  StepSettings settings;
  std::map<std::string, std::string> overrides;
  std::string out;
  std::string moment;       // --moment NAME: its time, parameters and theme
  bool have_theme = false;  // --theme given: it wins over the moment's
  MysteryOptions mystery;   // --mystery PAIR --seed N
};

std::vector<double> parse_times(const Option& at, const std::string& text) {
  std::vector<double> times;
  std::stringstream parts(text);
  std::string part;
  // At most an hour (the table's range): the record grows with every step, and the lesson's
  // expectations read all of it.
  while (std::getline(parts, part, ',')) times.push_back(at.number(part));
  if (times.empty() || text.back() == ',') throw InvalidInput("--at " + text + ": give times in seconds, as in --at 0.5,2");
  if (times.size() > 100) throw InvalidInput("--at: at most 100 times in one render, got " + std::to_string(times.size()));
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

void parse_size(const Option& size, const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw InvalidInput("--size " + text + ": write it as WIDTHxHEIGHT, as in --size 1280x720");
  const Range& across = size.range, up = size.height_range;
  width = static_cast<int>(option_number("--size width", text.substr(0, x), across.low, across.high, across.low_open, across.unit));
  height = static_cast<int>(option_number("--size height", text.substr(x + 1), up.low, up.high, up.low_open, up.unit));
  if (std::to_string(width) + "x" + std::to_string(height) != text) {
    throw InvalidInput("--size " + text + ": whole numbers of pixels, as in --size 1280x720");
  }
  // The layout is made for a landscape screen, from a 4:3 projector to a 2560x1080 monitor.
  const double aspect = static_cast<double>(width) / height;
  if (aspect < 4.0 / 3.0 - 1e-9 || aspect > 2.4 + 1e-9) {
    throw InvalidInput("--size " + text + ": the picture must be landscape, width / height from 4:3 to 2.4");
  }
}

// An error from parsing a value, with the option and value in front: "--theme pink: ...".
template <class Parse>
auto named(std::string_view option, const std::string& value, Parse parse) {
  try {
    return parse();
  } catch (const InvalidInput& error) {
    throw InvalidInput(std::string(option) + " " + value + ": " + error.what());
  }
}

RenderOptions parse_render(const std::vector<std::string>& args) {
  RenderOptions options;
  bool have_times = false;
  const auto lesson = [&](const std::string& word) {
    if (!options.lesson.empty()) throw InvalidInput("render takes one lesson, got '" + options.lesson + "' and '" + word + "'");
    options.lesson = word;
  };
  read_options(Command::render, args, lesson, [&](const Option& option, const std::string& value) {
    if (options.mystery.take(option, value)) return;
    const std::string_view name = option.name;
    if (name == "--at") {
      options.times = parse_times(option, value);
      have_times = true;
    } else if (name == "--moment") {
      options.moment = value;
    } else if (name == "--size") {
      parse_size(option, value, options.width, options.height);
    } else if (name == "--theme") {
      options.theme = named(option.name, value, [&] { return draw::parse_theme(value); });
      options.have_theme = true;
    } else if (name == "--set") {
      add_override(value, options.overrides);
    } else if (name == "--out") {
      options.out = value;
    } else if (name == "--friction") {
      named(option.name, value, [&] { return step_option(option, value, options.settings); });
    } else if (!step_option(option, value, options.settings)) {  // --hz or --substeps
      throw std::logic_error("render does not read " + std::string(name) + ", which the options table gives it");
    }
  });
  if (options.lesson.empty()) throw InvalidInput("render needs a lesson: frictionlab render LESSON --at S --out PATH");
  if (have_times && !options.moment.empty()) {
    throw InvalidInput("render: give --at or --moment, not both (a moment has its own time)");
  }
  if (options.out.empty()) throw InvalidInput("render: --out PATH is required: a .png file, or a folder for several times");
  options.mystery.choice();  // --mystery without --seed, or the other way round, refused before any work
  return options;
}

// "0.5", "2", "1.0001": as short as it can be while still telling the times apart.
std::string time_text(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", t);
  return text;
}

// Where each picture goes: one time into a .png file (or an existing folder), several into a
// folder, made only once every picture is drawn. Checks only; nothing is made here.
std::vector<std::string> output_paths(const RenderOptions& options, const std::string& lesson_name) {
  const fs::path out(options.out);
  std::string extension = out.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".lua") throw InvalidInput("--out " + options.out + ": that is a lesson script; give a .png file or a folder");
  const bool to_file = extension == ".png";
  if (!to_file && !extension.empty() && !fs::is_directory(out)) {
    throw InvalidInput("--out " + options.out + ": pictures are written as PNG; give a .png file or a folder");
  }
  if (to_file && options.times.size() > 1) {
    throw InvalidInput("--out " + options.out + ": " + std::to_string(options.times.size()) +
                       " times need a folder for --out, not one .png file");
  }
  // A file goes into a folder that exists; a folder may be new, inside one that exists.
  const fs::path parent = out.parent_path();
  if (!parent.empty() && !fs::is_directory(parent)) {
    throw InvalidInput("--out " + options.out + ": " + parent.string() +
                       (fs::exists(parent) ? " is a file, not a folder" : " does not exist"));
  }
  if (!to_file && fs::exists(out) && !fs::is_directory(out)) {
    throw InvalidInput("--out " + options.out + ": that is a file; several times need a folder");
  }
  std::vector<std::string> paths;
  for (double t : options.times) {
    // A moment's picture in a folder takes its golden's name.
    const std::string file = options.moment.empty() ? lesson_name + "_t" + time_text(t) : lesson_name + "_" + options.moment;
    paths.push_back(to_file ? out.string() : (out / (file + ".png")).string());
  }
  return paths;
}

// --moment NAME: the moment's time, its parameters under the --set ones, its theme unless
// --theme is given. Throws InvalidInput listing the lesson's moments when it has no such one.
void apply_moment(const std::string& path, RenderOptions& options) {
  const lessons::Lesson defaults(path);
  const lessons::Moment* moment = nullptr;
  try {
    moment = &defaults.moment(options.moment);
  } catch (const InvalidInput& error) {
    throw InvalidInput("render: --moment " + options.moment + ": " + error.what());
  }
  options.times = {moment->at};
  for (const auto& [name, value] : moment->set) options.overrides.emplace(name, value);
  if (!options.have_theme) options.theme = moment->theme == "dark" ? draw::ThemeName::dark : draw::ThemeName::light;
}

}  // namespace

void parse_render_arguments(const std::vector<std::string>& args) { parse_render(args); }

int run_render(const std::vector<std::string>& args, std::ostream& out) {
  RenderOptions options = parse_render(args);
  const std::string path = lessons::resolve_lesson(options.lesson);
  if (!options.moment.empty()) apply_moment(path, options);
  lessons::Lesson lesson(path, options.overrides, options.settings);
  // A moment's picture shows the lesson at that moment; past the lesson's end it would show a
  // run that is over (the script warns of it when it opens).
  if (!options.moment.empty() && options.times.front() > lesson.duration()) {
    std::ostringstream message;
    message << "render: --moment " << options.moment << ": at " << options.times.front()
            << " s it comes after the lesson's end, at " << lesson.duration() << " s, with these values";
    throw InvalidInput(message.str());
  }
  // Neither --at nor --moment: halfway through the run, where most lessons have their event
  // behind them and their motion still on, the picture the window draws without a display.
  if (options.times.empty()) options.times = {0.5 * lesson.duration()};
  draw::HiddenValues hidden;
  if (const std::optional<classroom_state::MysteryChoice> mystery = options.mystery.choice()) {
    hidden.parameters = apply_mystery(lesson, *mystery, options.overrides).hidden();
  }
  // The record grows with every step up to the last time drawn, as in frictionlab run.
  require_record_fits(options.times.back(), lesson.settings().hz, lesson.scene().probes().size(),
                      "draw an earlier --at or lower --hz");
  const std::vector<std::string> paths = output_paths(options, fs::path(path).stem().string());
  const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);

  std::unique_ptr<draw::HeadlessRenderer> renderer;
  try {
    renderer = std::make_unique<draw::HeadlessRenderer>(options.width, options.height, options.theme);
  } catch (const draw::HeadlessUnavailable& error) {
    throw InvalidInput(std::string("render: ") + error.what());
  }
  renderer->hide(hidden);
  // Every picture is drawn and encoded before any is written: a lesson that fails at a later
  // time leaves nothing behind, and an encoded frame is a tenth of the raw one.
  std::vector<std::pair<std::string, std::string>> files;
  for (std::size_t i = 0; i < options.times.size(); ++i) {
    lesson.step_to(options.times[i]);
    const std::vector<std::uint8_t> png = draw::encode_png(renderer->render(lesson, framing));
    files.emplace_back(paths[i], std::string(png.begin(), png.end()));
  }
  const fs::path folder = paths.size() == 1 && paths[0] == options.out ? fs::path() : fs::path(options.out);
  const bool made_folder = !folder.empty() && !fs::exists(folder);
  std::error_code error;
  if (made_folder && !fs::create_directories(folder, error)) {
    throw InvalidInput("--out " + options.out + ": cannot make a folder there");
  }
  try {
    write_files_atomically(files);
  } catch (const InvalidInput&) {
    if (made_folder) fs::remove_all(folder, error);
    throw;
  }
  for (const auto& file : files) out << file.first << '\n';
  return 0;
}

}  // namespace frictionlab
