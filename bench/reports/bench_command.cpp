// frictionlab bench: what the friction listener costs, and how accuracy on the stick-slip
// problem trades against CPU time for each treatment and for the reduced models.
// Figures are measured here and reported, never asserted: the machines are shared.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <ostream>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "app/modes.h"
#include "app/command_line.h"
#include "bench/reports/reports.h"
#include "app/options.h"
#include "app/table.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"
#include "bench/lesson_problem.h"
#include "physics/reduced_model.h"
#include "bench/cheapest_setting.h"
#include "physics/stability.h"

namespace frictionlab {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

namespace {

// CPU seconds per step of both worlds, timed in alternating blocks so that a busy neighbour
// slows both alike.
struct PileCost {
  int boxes;
  double listener, plain;
};
PileCost time_pile(int rows, int steps, int repeats) {
  const StepSettings settings;
  Pyramid with = make_pyramid(rows, true, settings);
  Pyramid without = make_pyramid(rows, false, settings);
  const float h = static_cast<float>(1.0 / settings.hz);
  for (int i = 0; i < 30; ++i) {  // let the contacts form and the pile settle before timing
    with.scene->step();
    without.plain->Step(h, settings.velocity_iterations, settings.position_iterations);
  }
  std::vector<double> listener, plain;
  for (int r = 0; r < repeats; ++r) {
    double start = thread_cpu_seconds();
    for (int i = 0; i < steps; ++i) with.scene->step();
    listener.push_back((thread_cpu_seconds() - start) / steps);
    start = thread_cpu_seconds();
    for (int i = 0; i < steps; ++i) without.plain->Step(h, settings.velocity_iterations, settings.position_iterations);
    plain.push_back((thread_cpu_seconds() - start) / steps);
  }
  return {with.boxes, median(listener), median(plain)};
}

std::string listener_cost(bool quick, std::ostream& out) {
  std::ostringstream csv;
  csv << "boxes,listener_ms_per_step,box2d_mixer_ms_per_step,ratio\n";
  std::vector<std::vector<std::string>> table{{"boxes", "with listener (ms/step)", "Box2D mixer (ms/step)", "ratio"}};
  for (int rows : {22, 44, 89}) {
    const int steps = quick ? 10 : (rows > 60 ? 60 : 200);
    const PileCost cost = time_pile(rows, steps, quick ? 1 : 5);
    csv << cost.boxes << ',' << cost.listener * 1e3 << ',' << cost.plain * 1e3 << ',' << cost.listener / cost.plain
        << '\n';
    table.push_back({std::to_string(cost.boxes), format_number(cost.listener * 1e3), format_number(cost.plain * 1e3),
                     format_number(cost.listener / cost.plain, 3)});
  }
  out << "Cost of the pair-table listener (pyramid of boxes, 240 Hz, 8 velocity iterations)\n";
  print_table(out, table);
  return csv.str();
}

std::string stick_slip_accuracy(bool quick, std::ostream& out, std::vector<AccuracyRun>& runs) {
  const BenchmarkProblem spring = spring_problem();
  const LineProblem& line = *spring.line;
  const int repeats = quick ? 1 : 3;
  std::ostringstream csv;
  csv << "method,hz,max_position_error_m,cpu_s_per_simulated_s,fails\n";
  std::vector<std::vector<std::string>> table{{"method", "hz", "max error (mm)", "CPU ms per simulated s", "fails"}};
  auto add = [&](const std::string& method, double hz, const Outcome& outcome, double cost) {
    csv << method << ',' << hz << ',' << outcome.error << ',' << cost << ',' << outcome.fails << '\n';
    table.push_back({method, format_number(hz), format_number(outcome.error * 1e3, 3), format_number(cost * 1e3, 3), outcome.fails});
    runs.push_back({method, hz, outcome.error, cost, outcome.fails});
  };
  // The listener's default threshold speed for the threshold and regularized treatments and
  // for the reduced regularized models alike.
  const double epsilon = StepSettings{}.threshold_speed;
  const std::vector<double> rates = quick ? std::vector<double>{60, 240} : std::vector<double>{60, 120, 240, 480, 960};
  for (FrictionTreatment treatment : {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                                      FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    for (double hz : rates) {
      StepSettings settings;
      settings.hz = hz;
      settings.treatment = treatment;
      const auto [outcome, cost] = measure([&] { return spring.run(settings); }, line.t_end, repeats);
      add("Box2D + " + std::string(treatment_name(treatment)), hz, outcome, cost);
    }
  }
  for (const ReducedMethod method : {ReducedMethod::explicit_euler, ReducedMethod::semi_implicit_euler, ReducedMethod::rk4,
                                     ReducedMethod::located_events}) {
    for (double hz : rates) {
      const auto [outcome, cost] = measure([&] { return run_reduced(line, method, hz, epsilon); }, line.t_end, repeats);
      add(reduced_method_name(method), hz, outcome, cost);
    }
  }
  const auto solve = [&] {
    solve_exact(line.block, line.t_end);
    return Outcome{};
  };
  const auto [reference, exact_cost] = measure(solve, line.t_end, repeats);
  add("1-DOF exact event-driven (reference)", 0, reference, exact_cost);
  out << "\nSpring-pull stick-slip over " << line.t_end
      << " s: max position error against the exact solution (regularized and threshold: epsilon = " << epsilon
      << " m/s)\n";
  print_table(out, table);
  return csv.str();
}

// How many times faster than real time each built-in lesson runs headless at 240 Hz, and the
// share of the stepping spent inside the script's Lua (hands, forces, probes, every_step).
// A lesson's run takes a few milliseconds, while this shared machine's speed wanders: so the
// lessons take turns, a run each per round, and every lesson is timed over the same stretch of
// the machine's moods. Run one lesson's repeats after another's and two lessons of equal cost
// could differ by a third, the one timed in a slow spell.
// Two figures per lesson. On this shared machine the same run takes either its usual time or
// about half as long again, the core switching between the two at random (often within a
// second, more often after it has idled). A round can only be slowed by that, never sped up:
// the fastest round is the code at the core's full pace, the median what this machine gave.
std::string lesson_speed(bool quick, std::ostream& out) {
  const std::vector<std::string> names = lessons::builtin_lessons();
  // 61 rounds of about 0.2 s: twelve seconds, longer than the slow spells, which last a second or two.
  const int rounds = quick ? 1 : 61;
  std::vector<std::vector<double>> costs(names.size()), shares(names.size());
  std::vector<double> simulated(names.size(), 0.0);
  for (int round = 0; round < rounds; ++round) {
    // The first pass of a round times the speed alone; the second also clocks every call into
    // Lua for the share (reading the clock costs time of its own).
    for (const bool share_pass : {false, true}) {
      for (std::size_t i = 0; i < names.size(); ++i) {
        lessons::Lesson lesson(lessons::resolve_lesson(names[i]));
        // The duration first: a script may work it out at length (stacked_blocks integrates
        // the slip), and that is not stepping.
        simulated[i] = lesson.duration();
        lesson.time_script(share_pass);
        const auto wall_start = std::chrono::steady_clock::now();
        const double cpu_start = thread_cpu_seconds();
        lesson.step_to(simulated[i]);
        const double cpu = thread_cpu_seconds() - cpu_start;
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
        if (share_pass) {
          shares[i].push_back(lesson.seconds_in_script() / wall);
        } else {
          costs[i].push_back(cpu / simulated[i]);
        }
      }
    }
  }
  std::ostringstream csv;
  // The fastest round's column comes last, so a reader of the older columns by position still
  // finds them where they were.
  csv << "lesson,hz,simulated_s,cpu_ms_per_simulated_s,times_real_time,script_share,times_real_time_fastest_round\n";
  std::vector<std::vector<std::string>> table{{"lesson", "simulated (s)", "CPU ms per simulated s", "× real time (median)",
                                               "fastest round", "script share of step time"}};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double cost = median(costs[i]), share = median(shares[i]);
    const double fastest = *std::min_element(costs[i].begin(), costs[i].end());
    csv << names[i] << ",240," << simulated[i] << ',' << cost * 1e3 << ',' << 1.0 / cost << ',' << share << ','
        << 1.0 / fastest << '\n';
    table.push_back({names[i], format_number(simulated[i]), format_number(cost * 1e3, 3),
                     format_number(std::round(1.0 / cost), 6),  // "3124", not "3.12e+03"
                     format_number(std::round(1.0 / fastest), 6), format_number(share * 100.0, 2) + " %"});
  }
  out << "\nBuilt-in lessons, headless at 240 Hz (median and fastest of " << rounds
      << " runs each, the lessons taking turns)\n";
  print_table(out, table);
  return csv.str();
}

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
