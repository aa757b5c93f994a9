// The cheapest model that answers the question: the recommender measures the friction
// treatments, step rates and sub-steps on any problem (a run function; a lesson's is built in
// bench/lesson_problem.h) by its error and CPU time per simulated second, to find
// the cheapest setting that meets a tolerance. One setting per call of run_next(), so a window can
// measure between frames and show its progress.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/problems.h"

namespace frictionlab {

struct Trial {
  StepSettings settings;
  double error = 0.0;
  std::string fails;  // how the run failed, "" if it did not
  double cost = 0.0;  // CPU s per simulated s
  bool meets = false;  // within the tolerance, and no failure
};

// One setting on one problem: its error, and the median cost of `repeats` runs.
Trial measure_setting(const BenchmarkProblem& problem, const StepSettings& settings, int repeats, double tolerance);
// The same for any run: its outcome, and the median CPU time per simulated second.
std::pair<Outcome, double> measure(const std::function<Outcome()>& run, double simulated, int repeats);

class Recommender {
 public:
  // Every treatment at 30 to 1920 Hz with 1, 2 or 4 sub-steps. Throws InvalidInput for a
  // tolerance that is not a positive number.
  Recommender(BenchmarkProblem problem, double tolerance, int repeats = 3);
  const BenchmarkProblem& problem() const { return problem_; }
  double tolerance() const { return tolerance_; }
  bool done() const { return next_ == candidates_.size(); }
  double progress() const { return static_cast<double>(next_) / static_cast<double>(candidates_.size()); }
  void run_next();
  void run_all() {
    while (!done()) run_next();
  }
  const std::vector<Trial>& trials() const { return trials_; }
  // The trial that meets the tolerance at the least cost; none when no setting tried does.
  std::optional<Trial> cheapest() const;
  // "7 of 84 failed: chatters 4, wrong answer 3", or "" when none did.
  std::string failures() const;

 private:
  BenchmarkProblem problem_;
  double tolerance_;
  int repeats_;
  std::vector<StepSettings> candidates_;
  std::size_t next_ = 0;
  std::vector<Trial> trials_;
};

// "stick-slip at 240 Hz, 1 sub-step".
std::string describe(const StepSettings& settings);

}  // namespace frictionlab
