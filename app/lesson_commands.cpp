// frictionlab list | run | check: lessons headless, as a test suite or a teacher without a
// window uses them.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "app/csv_log.h"
#include "app/modes.h"
#include "app/options.h"
#include "app/table.h"
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
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      if (!options.lesson.empty()) throw InvalidInput("run takes one lesson, got '" + options.lesson + "' and '" + arg + "'");
      options.lesson = arg;
      continue;
    }
    static const std::string known[] = {"--duration", "--hz", "--substeps", "--friction", "--set", "--csv", "--mystery", "--seed"};
    if (std::find(std::begin(known), std::end(known), arg) == std::end(known)) {
      throw InvalidInput("run: unknown option '" + arg +
                         "'; options: --duration S, --hz N, --substeps N, --friction T, --set NAME=VALUE, --csv FILE, "
                         "--mystery MATERIAL/MATERIAL --seed N");
    }
    if (i + 1 >= args.size()) throw InvalidInput("run: " + arg + " needs a value; see frictionlab help");
    refuse_repeat("run", arg, seen);
    const std::string& value = args[++i];
    if (options.mystery.take(arg, value)) continue;
    if (arg == "--duration") {
      options.duration = option_number(arg, value, 0.0, 86400.0, true, " s");
    } else if (arg == "--set") {
      add_override(value, options.overrides);
    } else if (arg == "--csv") {
      // Empty, it would write nothing and say nothing: exit 0 with no file.
      if (value.empty()) throw InvalidInput("--csv \"\": give a file name, or - for standard output");
      options.csv = value;
    } else {
      step_option(arg, value, options.settings);  // --hz, --substeps or --friction
    }
  }
  if (options.lesson.empty()) throw InvalidInput("run needs a lesson: frictionlab run LESSON; see frictionlab list");
  return options;
}

// Runs the lesson for `duration` and prints its expectations; returns how many failed. With
// values `hidden` (a mystery pair's), the predictions, errors and tolerances worked out from them
// are hidden too.
int run_and_report(Lesson& lesson, double duration, CsvLog* csv, std::ostream& out, const std::set<std::string>& hidden = {}) {
  require_record_fits(duration, lesson.settings().hz, lesson.scene().probes().size(), "shorten --duration or lower --hz");
  if (csv) csv->header(lesson, hidden);
  const double h = lesson.scene().frame_step();
  while (lesson.scene().time() < duration - 0.5 * h) {
    lesson.step();
    if (csv) csv->row(lesson.scene());
  }
  for (const std::string& warning : lesson.warnings()) out << "warning: " << warning << '\n';
  std::vector<std::vector<std::string>> table{{"expectation", "unit", "predicted", "measured", "error", "tolerance", "pass"}};
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

}  // namespace

int run_list(const std::vector<std::string>& args, std::ostream& out) {
  const bool tsv = args.size() == 1 && args[0] == "--tsv";
  if (!args.empty() && !tsv) throw InvalidInput("list takes no options but --tsv, got '" + args[0] + "'");
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
  const std::optional<ui::MysteryChoice> mystery_choice = options.mystery.choice();
  Lesson lesson(lessons::resolve_lesson(options.lesson), options.overrides, options.settings);
  std::set<std::string> hidden;
  if (mystery_choice) hidden = apply_mystery(lesson, *mystery_choice, options.overrides).hidden();
  std::optional<CsvLog> csv;
  if (!options.csv.empty()) csv.emplace(options.csv, lesson, out);
  // With --csv -, the rows are standard output's; the table goes to standard error.
  std::ostream& report = options.csv == "-" ? std::cerr : out;
  print_heading(lesson, report, hidden);
  // The lesson's own duration only when none is given: its function may not even be needed.
  const double duration = options.duration ? *options.duration : lesson.duration();
  run_and_report(lesson, duration, csv ? &*csv : nullptr, report, hidden);
  if (csv) csv->finish();
  return 0;
}

int run_check(const std::vector<std::string>& args, std::ostream& out) {
  // Lessons, and the values and step settings to check them at (a student checks a threshold
  // from both sides: check my_lesson.lua --set launch_speed=2.4).
  std::vector<std::string> names;
  std::map<std::string, std::string> overrides;
  StepSettings settings;
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      names.push_back(arg);
      continue;
    }
    static const std::string known[] = {"--hz", "--substeps", "--friction", "--set"};
    if (std::find(std::begin(known), std::end(known), arg) == std::end(known)) {
      throw InvalidInput("check: unknown option '" + arg + "'; options: --set NAME=VALUE, --hz N, --substeps N, --friction T");
    }
    if (i + 1 >= args.size()) throw InvalidInput("check: " + arg + " needs a value; see frictionlab help");
    refuse_repeat("check", arg, seen);
    const std::string& value = args[++i];
    if (arg == "--set") {
      add_override(value, overrides);
    } else {
      step_option(arg, value, settings);  // --hz, --substeps or --friction
    }
  }
  if (names.empty() && !overrides.empty()) {
    throw InvalidInput("check: --set names a parameter of one lesson; name the lesson too, as in check push --set mass=2");
  }
  if (names.empty()) names = lessons::builtin_lessons();
  // Every lesson is checked even when one cannot be run: a broken script is reported and the
  // others still get their verdict.
  int failed_lessons = 0, broken_lessons = 0;
  for (const std::string& name : names) {
    try {
      Lesson lesson(lessons::resolve_lesson(name), overrides, settings);
      out << "== " << name << ": ";
      print_heading(lesson, out);
      if (run_and_report(lesson, lesson.duration(), nullptr, out) > 0) ++failed_lessons;
    } catch (const InvalidInput& error) {
      std::cerr << "frictionlab: check " << name << ": " << error.what() << '\n';
      ++broken_lessons;
    }
    out << '\n';
  }
  if (broken_lessons > 0) {
    out << broken_lessons << " lesson(s) could not be run (see the messages above)\n";
    return 2;
  }
  out << (failed_lessons == 0 ? "every lesson meets its expectations\n"
                              : std::to_string(failed_lessons) + " lesson(s) missed an expectation\n");
  return failed_lessons == 0 ? 0 : 1;
}

}  // namespace frictionlab
