// frictionlab list | run | check: lessons headless, as a test suite or a teacher without a
// window uses them.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "app/command_line.h"
#include "app/csv_log.h"
#include "app/modes.h"
#include "app/options.h"
#include "app/table.h"
#include "classroom_state/mystery.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"
#include "physics/validation.h"

namespace frictionlab {
namespace {

using lessons::Lesson;

struct RunOptions {
  std::string lesson;
  std::optional<double> duration;
  StepSettings settings;
  std::map<std::string, std::string> overrides;
  std::string csv;
  MysteryOptions mystery;
};

RunOptions parse_run(const std::vector<std::string>& args) {
  RunOptions options;
  const auto lesson = [&](const std::string& word) {
    if (!options.lesson.empty()) throw InvalidInput("run takes one lesson, got '" + options.lesson + "' and '" + word + "'");
    options.lesson = word;
  };
  read_options(Command::run, args, lesson, [&](const Option& option, const std::string& value) {
    if (options.mystery.take(option, value) || step_option(option, value, options.settings)) return;
    if (option.name == "--duration") {
      options.duration = option.number(value);
    } else if (option.name == "--set") {
      add_override(value, options.overrides);
    } else if (option.name == "--csv") {
      // Empty, it would write nothing and say nothing: exit 0 with no file.
      if (value.empty()) throw InvalidInput("--csv \"\": give a file name, or - for standard output");
      options.csv = value;
    } else {
      throw std::logic_error("run does not read " + std::string(option.name) + ", which the options table gives it");
    }
  });
  if (options.lesson.empty()) throw InvalidInput("run needs a lesson: frictionlab run LESSON; see frictionlab list");
  return options;
}

// Steps the lesson until `duration`, writing each step to `csv` when there is one.
void run_for(Lesson& lesson, double duration, CsvLog* csv) {
  const double h = lesson.scene().frame_step();
  while (lesson.scene().time() < duration - 0.5 * h) {
    lesson.step();
    if (csv) csv->row(lesson.scene());
  }
}

// Runs the lesson for `duration` and prints its expectations; returns how many failed. With
// values `hidden` (a mystery pair's), the predictions, errors and tolerances worked out from them
// are hidden too.

int run_and_report(Lesson& lesson, double duration, CsvLog* csv, std::ostream& out, const std::set<std::string>& hidden = {}) {
  require_record_fits(duration, lesson.settings().hz, lesson.scene().probes().size(), "shorten --duration or lower --hz");
  if (csv) csv->header(lesson, hidden);
  run_for(lesson, duration, csv);
  for (const std::string& warning : lesson.warnings()) out << "warning: " << warning << '\n';
  std::vector<std::vector<std::string>> table{{"expectation", "unit", "theory", "measured", "error", "tolerance", "pass"}};
  int failed = 0;
  const bool theory_hidden = !hidden.empty();
  for (const lessons::ExpectationResult& row : lesson.expectations()) {
    if (theory_hidden) {
      table.push_back({row.name, row.unit, "hidden",
                       !row.measured_yet ? row.measured_text : row.numeric ? format_number(row.measured) : row.measured_text,
                       "", "", row.passes ? "yes" : "NO"});
    } else if (row.numeric) {
      table.push_back({row.name, row.unit, format_number(row.predicted),
                       row.measured_yet ? format_number(row.measured) : row.measured_text,
                       row.measured_yet ? format_number(row.error(), 2) : "", format_number(row.tolerance, 2),
                       row.passes ? "yes" : "NO"});
    } else {
      table.push_back({row.name, "", row.predicted_text, row.measured_text, "", "", row.passes ? "yes" : "NO"});
    }
    if (!row.passes) ++failed;
  }
  print_table(out, table);
  const std::size_t total = table.size() - 1;
  out << total - static_cast<std::size_t>(failed) << " of " << total << " expectations met after "
      << format_number(lesson.scene().time()) << " s at " << format_number(lesson.settings().hz) << " Hz ("
      << treatment_name(lesson.settings().treatment) << ")\n";
  return failed;
}

void print_heading(const Lesson& lesson, std::ostream& out, const std::set<std::string>& hidden = {}) {
  out << lesson.title() << "\n" << lesson.question() << "\n";
  std::string values;
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    values += (values.empty() ? "" : ", ") + parameter.name + " = " + (hidden.count(parameter.name) > 0 ? "? (a mystery)" : parameter.shown());
  }
  out << "  " << values << "\n\n";
}

// check --random: settings drawn inside the lesson's own sliders' ranges, as many as the options
// table allows, from default_random_seed (app/command_line.h) unless --seed gives one.

// SplitMix64, written out so that a seed draws the same settings with every compiler and
// standard library (std::uniform_real_distribution's algorithm is not specified).
class Draws {
 public:
  explicit Draws(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  std::uint64_t state_;
};

using validation::exact_text;  // the shortest text that reads back as the same double, as --set takes it

// A value for one slider in setting `index`: the first setting puts every slider at its
// minimum, the second at its maximum; after that each slider is at an end one time in five
// each, else anywhere between, rounded to four significant figures so that the command line
// reproducing it stays short (rounding never leaves the range).
std::string draw_value(const lessons::Parameter& parameter, int index, Draws& draws) {
  if (parameter.is_choice()) return parameter.choices[draws.next() % parameter.choices.size()];
  const std::uint64_t pick = draws.next() % 5;
  if (index == 0 || (index > 1 && pick == 0)) return exact_text(parameter.min);
  if (index == 1 || pick == 1) return exact_text(parameter.max);
  const double value = parameter.min + draws.unit() * (parameter.max - parameter.min);
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  const double rounded = validation::read_decimal(text);
  if (rounded < parameter.min) return exact_text(parameter.min);
  if (rounded > parameter.max) return exact_text(parameter.max);
  return exact_text(rounded);
}

// A word as a shell takes it: quoted when it holds anything but letters, digits and ._-=/+.
std::string shell_word(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || std::strchr("._-=/+,", c) != nullptr;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Checks the lesson `name` at `count` settings drawn from `seed`; the values in `fixed` (from
// --set) are kept in every setting. Prints each failing setting as the command line that
// reproduces it, with the rows it missed. Returns how many settings failed.
int check_random_settings(const std::string& name, const std::map<std::string, std::string>& fixed,
                          const StepSettings& settings, const std::vector<std::string>& step_options, int count,
                          std::uint64_t seed, std::ostream& out) {
  const std::string path = lessons::resolve_lesson(name);
  lessons::ScriptText script(path, lessons::read_script(path));
  std::vector<lessons::Parameter> sliders;
  {
    const Lesson defaults(script, fixed, settings);  // the sliders as the script declares them
    for (const lessons::Parameter& parameter : defaults.parameters()) {
      if (fixed.count(parameter.name) == 0) sliders.push_back(parameter);
    }
    script = defaults.script();  // compiled: every setting after this one skips reading the text
  }
  // The lesson's name salts the seed, so that two lessons checked together draw differently.
  std::uint64_t salt = 1469598103934665603ULL;
  for (const char c : std::filesystem::path(path).stem().string()) salt = (salt ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  Draws draws(seed ^ salt);
  int failed = 0;
  for (int index = 0; index < count; ++index) {
    std::map<std::string, std::string> values = fixed;
    for (const lessons::Parameter& slider : sliders) values[slider.name] = draw_value(slider, index, draws);
    std::string command = "frictionlab check " + shell_word(name);
    for (const auto& [parameter, value] : values) command.append(" --set ").append(shell_word(parameter + "=" + value));
    for (const std::string& option : step_options) command.append(" ").append(shell_word(option));
    std::vector<std::string> missed;
    try {
      Lesson lesson(script, values, settings);
      require_record_fits(lesson.duration(), lesson.settings().hz, lesson.scene().probes().size(), "lower --hz");
      run_for(lesson, lesson.duration(), nullptr);
      for (const lessons::ExpectationResult& row : lesson.expectations()) {
        if (row.passes) continue;
        if (row.numeric && row.measured_yet) {
          missed.push_back(row.name + ": theory " + format_number(row.predicted) + ", measured " +
                           format_number(row.measured) + ", error " + format_number(row.error(), 2) + ", tolerance " +
                           format_number(row.tolerance, 2) + (row.unit.empty() ? "" : " " + row.unit));
        } else {
          const std::string predicted = row.numeric ? format_number(row.predicted) : row.predicted_text;
          missed.push_back(row.name + ": theory " + predicted + ", measured " + row.measured_text);
        }
      }
    } catch (const InvalidInput& error) {
      missed.push_back(std::string("could not be run: ") + error.what());
    }
    if (missed.empty()) continue;
    ++failed;
    out << "FAIL: " << command << '\n';
    for (const std::string& row : missed) out << "  " << row << '\n';
  }
  out << name << ": " << count - failed << " of " << count << " random settings meet every expectation (seed " << seed
      << ")\n";
  return failed;
}

}  // namespace

int run_list(const std::vector<std::string>& args, std::ostream& out) {
  bool tsv = false;
  read_options(
      Command::list, args,
      [](const std::string& word) { throw InvalidInput("list: lists every lesson and takes none by name, got '" + word + "'"); },
      [&](const Option&, const std::string&) { tsv = true; });  // --tsv, its only option
  // The moments by name, the README's frame marked with a star.
  const auto moment_names = [](const lessons::CatalogEntry& entry, const char* separator, bool star) {
    std::string names;
    for (const lessons::Moment& moment : entry.moments) {
      names += (names.empty() ? "" : separator) + moment.name + (moment.readme && star ? "*" : "");
    }
    return names;
  };
  if (tsv) {
    // For scripts (scripts/readme_frames.sh): one lesson a line, tab-separated, no heading.
    for (const lessons::CatalogEntry& entry : lessons::catalog()) {
      std::string readme;
      for (const lessons::Moment& moment : entry.moments) {
        if (moment.readme) readme = moment.name;
      }
      out << entry.name << '\t' << entry.title << '\t' << readme << '\t' << moment_names(entry, ",", false) << '\n';
    }
    return 0;
  }
  std::vector<std::vector<std::string>> table{{"lesson", "title", "moments (* the README's frame)"}};
  for (const lessons::CatalogEntry& entry : lessons::catalog()) table.push_back({entry.name, entry.title, moment_names(entry, ", ", true)});
  print_table(out, table);
  out << "Scripts are in " << lessons::lessons_directory() << "; run one with: frictionlab run LESSON\n";
  return 0;
}

int run_lesson(const std::vector<std::string>& args, std::ostream& out) {
  const RunOptions options = parse_run(args);
  const std::optional<classroom_state::MysteryChoice> mystery_choice = options.mystery.choice();
  Lesson lesson(lessons::resolve_lesson(options.lesson), options.overrides, options.settings);
  std::set<std::string> hidden;
  if (mystery_choice) hidden = apply_mystery(lesson, *mystery_choice, options.overrides).hidden();
  std::optional<CsvLog> csv;
  if (!options.csv.empty()) csv.emplace(options.csv, lesson, out, std::cerr);
  // With --csv -, the rows are standard output's; the run's settings and the table go to standard error.
  std::ostream& report = options.csv == "-" ? std::cerr : out;
  print_heading(lesson, report, hidden);
  // The lesson's own duration only when none is given: its function may not even be needed.
  const double duration = options.duration ? *options.duration : lesson.duration();
  run_and_report(lesson, duration, csv ? &*csv : nullptr, report, hidden);
  if (csv) csv->finish();
  return 0;
}

namespace {

struct CheckOptions {
  std::vector<std::string> names;
  std::map<std::string, std::string> overrides;
  StepSettings settings;
  std::vector<std::string> step_options;  // as given, for the command lines --random prints
  std::optional<int> random_count;
  std::optional<std::uint64_t> seed;
};

CheckOptions parse_check(const std::vector<std::string>& args) {
  // Lessons, and the values and step settings to check them at (a student checks a threshold
  // from both sides: check my_lesson.lua --set launch_speed=2.4), or at N settings drawn inside
  // the sliders' ranges (check my_lesson.lua --random 50).
  CheckOptions options;
  const auto add_lesson = [&](const std::string& word) { options.names.push_back(word); };
  read_options(Command::check, args, add_lesson, [&](const Option& option, const std::string& value) {
    if (option.name == "--set") {
      add_override(value, options.overrides);
    } else if (option.name == "--random") {
      const std::string allowed = "a whole number of settings " + option.range_words();
      // No more digits than the table's largest count has, so that std::stoi cannot overflow.
      const std::size_t most_digits = std::to_string(static_cast<long long>(option.range.high)).size();
      const bool digits = !value.empty() && value.size() <= most_digits &&
                          std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!digits || std::stoi(value) < option.range.low || std::stoi(value) > option.range.high) {
        throw InvalidInput("check: --random " + value + ": give " + allowed);
      }
      options.random_count = std::stoi(value);
    } else if (option.name == "--seed") {
      options.seed = classroom_state::parse_mystery_seed("check: --seed", value);
    } else if (step_option(option, value, options.settings)) {  // --hz, --substeps or --friction
      options.step_options.push_back(std::string(option.name));
      options.step_options.push_back(value);
    } else {
      throw std::logic_error("check does not read " + std::string(option.name) + ", which the options table gives it");
    }
  });
  if (options.names.empty() && !options.overrides.empty()) {
    throw InvalidInput("check: --set names a parameter of one lesson; name the lesson too, as in check push --set mass=2");
  }
  if (options.seed && !options.random_count) {
    throw InvalidInput("check: --seed S draws the settings of --random N; give --random N with it");
  }
  return options;
}

}  // namespace

void parse_run_arguments(const std::vector<std::string>& args) { parse_run(args); }
void parse_check_arguments(const std::vector<std::string>& args) { parse_check(args); }

int run_check(const std::vector<std::string>& args, std::ostream& out) {
  CheckOptions options = parse_check(args);
  std::vector<std::string>& names = options.names;
  const std::map<std::string, std::string>& overrides = options.overrides;
  const std::optional<int>& random_count = options.random_count;
  if (names.empty()) names = lessons::builtin_lessons();
  // Every lesson is checked even when one cannot be run: a broken script is reported and the
  // others still get their verdict.
  int failed_lessons = 0, broken_lessons = 0;
  for (const std::string& name : names) {
    try {
      if (random_count) {
        if (check_random_settings(name, overrides, options.settings, options.step_options, *random_count,
                                  options.seed.value_or(default_random_seed), out) > 0) {
          ++failed_lessons;
        }
      } else {
        Lesson lesson(lessons::resolve_lesson(name), overrides, options.settings);
        out << "== " << name << ": ";
        print_heading(lesson, out);
        if (run_and_report(lesson, lesson.duration(), nullptr, out) > 0) ++failed_lessons;
      }
    } catch (const InvalidInput& error) {
      say_bad_input(std::cerr, "check " + name + ": ", error.what());
      ++broken_lessons;
    }
    out << '\n';
  }
  if (broken_lessons > 0) {
    out << broken_lessons << " lesson(s) could not be run (see the messages above)\n";
    return 2;
  }
  const std::string what = random_count ? "at every random setting" : "";
  out << (failed_lessons == 0 ? "every lesson meets its expectations" + (what.empty() ? "" : " " + what) + "\n"
                              : std::to_string(failed_lessons) + " lesson(s) missed an expectation\n");
  return failed_lessons == 0 ? 0 : 1;
}

}  // namespace frictionlab
