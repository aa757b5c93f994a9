// The cheapest model that answers the question: each built-in lesson has a benchmark problem
// with an exact answer, and the recommender measures the friction treatments, step rates and
// sub-steps on it (error against the exact answer, CPU time per simulated second) to find the
// cheapest setting that meets a tolerance. One setting per call of run_next(), so a window can
// measure between frames and show its progress.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/scene.h"

namespace frictionlab {

struct BenchmarkProblem {
  std::string name;      // short, for a chart's title
  std::string lesson;    // the built-in lesson it stands for ("" for the benchmark's others)
  std::string question;  // what is compared with the exact answer, in words
  std::string unit;      // of the error
  double simulated = 1.0;  // s, for the cost per simulated second
  // |simulated − exact| for a setting; infinite when the run gets the answer wrong altogether.
  std::function<double(const StepSettings&)> error;
};
// spring_pull, incline or tipping_box; throws InvalidInput listing them for another name.
BenchmarkProblem lesson_problem(const std::string& lesson);
// Every problem the benchmark charts, each with an exact answer: the three lessons' problems,
// the block on a slope just below its sticking angle, slides to rest with c and with b, the
// tipping threshold found by bisection against d/(2·mu_s), and the disk that starts to roll.
std::vector<BenchmarkProblem> benchmark_problems();

struct Trial {
  StepSettings settings;
  double error = 0.0;
  double cost = 0.0;  // CPU s per simulated s
  bool meets = false;
};

// CPU seconds this thread has used: a measurement's own cost, whatever other threads (Mesa's
// rasterizer in the window) are doing.
double thread_cpu_seconds();
// One setting on one problem: its error, and the median cost of `repeats` runs.
Trial measure_setting(const BenchmarkProblem& problem, const StepSettings& settings, int repeats, double tolerance);

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
