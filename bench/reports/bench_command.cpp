// frictionlab bench: its options, the parts run in order with a progress bar and their files
// written, each part in a file named for what it measures (listener_cost.cpp,
// stick_slip_accuracy.cpp, lesson_speed.cpp, ...); and bench --recommend, the cheapest setting
// for a lesson (bench/cheapest_setting.h).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <ostream>
#include <sstream>

#include "app/command_line.h"
#include "app/modes.h"
#include "app/options.h"
#include "app/table.h"
#include "bench/cheapest_setting.h"
#include "bench/lesson_problem.h"
#include "bench/reports/reports.h"

namespace frictionlab {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

namespace {

// frictionlab bench --recommend LESSON --tol X [--set NAME=VALUE]: the cheapest setting whose
// run of the lesson's own script meets its expectations within X times their tolerances.
// Each run builds the lesson's Lua and Box2D afresh, so the cost is the median of 2 runs.
int run_recommend(const std::string& lesson, const std::map<std::string, std::string>& overrides,
                  const std::string& tolerance_text, std::ostream& out) {
  // Its range is the options table's, which the help and the manual page are held to.
  const double tolerance = option_for(Command::bench, "--tol").number(tolerance_text);
  const BenchmarkProblem problem = lessons::lesson_problem(lesson, overrides);
  Recommender recommender(problem, tolerance, 2);
  out << "Measuring " << problem.question << " (" << problem.unit << "), for every friction treatment at 30 to 1920 Hz "
      << "with 1, 2 or 4 sub-steps:\n";
  const bool terminal = &out == &std::cout && isatty(STDOUT_FILENO);
  while (!recommender.done()) {
    recommender.run_next();
    if (!terminal) continue;  // a progress bar is for a person watching, not for a file
    const int width = 40, filled = static_cast<int>(recommender.progress() * width + 0.5);
    out << "\r[" << std::string(static_cast<std::size_t>(filled), '#') << std::string(static_cast<std::size_t>(width - filled), ' ')
        << "] " << static_cast<int>(recommender.progress() * 100.0 + 0.5) << " %" << std::flush;
  }
  out << "\n\n";
  std::vector<Trial> trials = recommender.trials();
  std::sort(trials.begin(), trials.end(), [](const Trial& a, const Trial& b) { return a.cost < b.cost; });
  std::vector<std::vector<std::string>> table{{"setting", "error (" + problem.unit + ")", "CPU ms per simulated s", "meets", "failed"}};
  int shown = 0;
  for (const Trial& trial : trials) {
    // The cheap end of the list, up to the first few that meet the tolerance.
    if (shown >= 12) break;
    if (trial.meets || shown < 6) {
      table.push_back({describe(trial.settings), std::isfinite(trial.error) ? format_number(trial.error, 3) : "-",
                       format_number(trial.cost * 1e3, 3), trial.meets ? "yes" : "no", trial.fails});
      ++shown;
    }
  }
  print_table(out, table);
  if (const std::string failed = recommender.failures(); !failed.empty()) out << failed << " (a failed run never meets)\n";
  const std::optional<Trial> best = recommender.cheapest();
  if (!best) {
    out << "\nNo setting tried answers within " << format_number(tolerance, 3) << " " << problem.unit << ".\n";
    return 1;
  }
  out << "\nCheapest within " << format_number(tolerance, 3) << " " << problem.unit << ": " << describe(best->settings)
      << " (error " << format_number(best->error, 3) << " " << problem.unit << ", " << format_number(best->cost * 1e3, 3)
      << " ms CPU per simulated s). In the window: the Cheapest setting tab; here: --hz " << best->settings.hz << " --substeps "
      << best->settings.substeps << " --friction " << treatment_name(best->settings.treatment) << "\n";
  return 0;
}

// The bench's progress on one line of a terminal: the whole run's share done, and the part
// being measured. Each part is given its share of a full run's time (measured in a
// Release build: drawing the window's frames on llvmpipe takes half of it).
class ProgressBar {
 public:
  ProgressBar(bool shown, std::ostream& out) : shown_(shown), out_(out) {}
  // The part about to run and its share of the whole; returns how to report within it.
  Progress stage(std::string name, double share) {
    done_ += share_;
    share_ = share;
    name_ = std::move(name);
    return [this](double fraction) { draw(done_ + share_ * std::clamp(fraction, 0.0, 1.0)); };
  }
  void clear() {
    if (shown_) out_ << '\r' << std::string(90, ' ') << '\r' << std::flush;
  }

 private:
  void draw(double whole) {
    if (!shown_) return;
    const int width = 30, filled = static_cast<int>(std::min(whole, 1.0) * width + 0.5);
    out_ << "\r[" << std::string(static_cast<std::size_t>(filled), '#') << std::string(static_cast<std::size_t>(width - filled), ' ')
         << "] " << static_cast<int>(std::min(whole, 1.0) * 100.0 + 0.5) << " %  " << name_ << std::string(20, ' ') << std::flush;
  }
  bool shown_;
  std::ostream& out_;
  double done_ = 0.0, share_ = 0.0;
  std::string name_;
};

}  // namespace

int run_bench(const std::vector<std::string>& args, std::ostream& out) {
  bool quick = false;
  std::string directory, recommend, tolerance;
  std::map<std::string, std::string> overrides;
  read_options(
      Command::bench, args,
      [](const std::string& word) {
        throw InvalidInput("bench: '" + word + "' is no option; usage: bench [--quick] --out DIR, or bench --recommend "
                           "LESSON --tol X [--set NAME=VALUE ...]");
      },
      [&](const Option& option, const std::string& value) {
        if (option.name == "--quick") {
          quick = true;
        } else if (option.name == "--out") {
          if (value.empty()) throw InvalidInput("bench: --out \"\": give the folder for the CSV files");
          directory = value;
        } else if (option.name == "--recommend") {
          recommend = value;
        } else if (option.name == "--tol") {
          tolerance = value;
        } else if (option.name == "--set") {
          const std::size_t equals = value.find('=');
          if (equals == std::string::npos || equals == 0) {
            throw InvalidInput("bench --set: expected NAME=VALUE, got '" + value + "'");
          }
          try {
            add_override(value, overrides);  // one parameter given two values is refused, as run refuses it
          } catch (const InvalidInput& error) {
            throw InvalidInput(std::string("bench: ") + error.what());
          }
        }
      });
  if (!overrides.empty() && recommend.empty()) throw InvalidInput("bench: --set goes with --recommend LESSON");
  if (!recommend.empty() || !tolerance.empty()) {
    if (recommend.empty()) throw InvalidInput("bench: --tol goes with --recommend LESSON");
    if (quick || !directory.empty()) throw InvalidInput("bench --recommend takes no --quick or --out: it only prints");
    if (tolerance.empty()) throw InvalidInput("bench --recommend: --tol X is required: the largest error to accept");
    return run_recommend(recommend, overrides, tolerance, out);
  }
  if (directory.empty()) throw InvalidInput("bench: --out DIR is required (the folder for the CSV files)");
  prepare_output_folder("bench: --out", directory);

  // Each part prints its table into a buffer, shown once the bar's line is cleared, so the
  // bar never lands inside a table.
  ProgressBar bar(&out == &std::cout && isatty(STDOUT_FILENO), out);
  std::ostringstream part;
  auto finish = [&] {
    bar.clear();
    out << part.str() << std::flush;
    part.str("");
  };
  bar.stage("cost of the listener", 0.05)(0.0);
  const std::string cost = listener_cost(quick, part);
  finish();
  bar.stage("spring stick-slip accuracy", 0.11)(0.0);
  std::vector<AccuracyRun> runs;
  const std::string accuracy = stick_slip_accuracy(quick, part, runs);
  const std::string work_precision = work_precision_png(runs);
  finish();
  bar.stage("lessons' speed", 0.01)(0.0);
  const std::string speed = lesson_speed(quick, part);
  finish();
  const std::string frames = frame_speed(quick, part, bar.stage("frames drawn headless", 0.22));
  finish();
  const std::string window_frames = window_frame_speed(quick, part, bar.stage("the window's frames", 0.42));
  finish();
  const std::string force_labels = force_label_speed(quick, part, bar.stage("the forces' values", 0.08));
  finish();
  const auto stability = stability_files(quick, directory, part, bar.stage("stability maps", 0.01));
  finish();
  const auto problems = problem_files(quick, directory, part, bar.stage("every benchmark problem", 0.10));
  finish();
  std::vector<std::pair<std::string, std::string>> files{{directory + "/listener_cost.csv", cost},
                                                         {directory + "/stick_slip_accuracy.csv", accuracy},
                                                         {directory + "/lesson_speed.csv", speed}};
  if (!frames.empty()) files.emplace_back(directory + "/frame_speed.csv", frames);
  if (!window_frames.empty()) files.emplace_back(directory + "/window_frame.csv", window_frames);
  if (!force_labels.empty()) files.emplace_back(directory + "/force_labels.csv", force_labels);
  files.insert(files.end(), stability.begin(), stability.end());
  files.insert(files.end(), problems.begin(), problems.end());
  if (!work_precision.empty()) files.emplace_back(directory + "/work_precision.png", work_precision);
  write_files_atomically(files);
  out << "\nwrote listener_cost.csv, stick_slip_accuracy.csv, lesson_speed.csv" << (frames.empty() ? "" : ", frame_speed.csv")
      << (window_frames.empty() ? "" : ", window_frame.csv") << (force_labels.empty() ? "" : ", force_labels.csv")
      << ", stability_map.csv"
      << (stability.size() > 1 ? ", stability.png" : "") << (work_precision.empty() ? "" : ", work_precision.png")
      << ", work_precision.csv" << (problems.size() > 1 ? ", problems.png" : "")
      << " in " << directory << "\n";
  return 0;
}

}  // namespace frictionlab
