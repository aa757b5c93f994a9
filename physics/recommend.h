// The cheapest model that answers the question: each built-in lesson has a benchmark problem
// with an exact answer, and the recommender measures the friction treatments, step rates and
// sub-steps on it (error against the exact answer, CPU time per simulated second) to find the
// cheapest setting that meets a tolerance. One setting per call of run_next(), so a window can
// measure between frames and show its progress.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "physics/reduced_model.h"
#include "physics/run_check.h"
#include "physics/scene.h"

namespace frictionlab {

// What a run answered: its error against the exact answer, and how it failed ("" when it did
// not: see RunCheck). An infinite error is an answer wrong altogether, such as a box that
// slides where it should tip.
struct Outcome {
  double error = 0.0;
  std::string fails;
};

// A problem that is a block on a line, so the reduced one-degree-of-freedom models can answer
// it too: the model, its exact motion, and how a run is judged.
struct LineProblem {
  OneDofBlock block;
  double t_end = 1.0;
  std::function<double(double t)> exact_position;
  bool final_only = false;  // judged by where it comes to rest, not by the largest error over the run
  ExpectedMotion expected;
};

// The reduced models: explicit Euler, semi-implicit Euler and RK4 with the regularized law at a
// threshold speed epsilon, and RK4 between located events (Coulomb's law exactly, no epsilon).
enum class ReducedMethod { explicit_euler, semi_implicit_euler, rk4, located_events };
std::string reduced_method_name(ReducedMethod method);
// The model at step 1/hz, judged as its problem says (positions every 1 ms for located events,
// whose state is known between steps).
Outcome run_reduced(const LineProblem& line, ReducedMethod method, double hz, double epsilon);

struct BenchmarkProblem {
  std::string name;      // short, for a chart's title
  std::string label;     // shorter, for a table's column
  std::string lesson;    // the built-in lesson it stands for ("" for the benchmark's others)
  std::string question;  // what is compared with the exact answer, in words
  std::string unit;      // of the error
  double simulated = 1.0;  // s, for the cost per simulated second
  // The Box2D scene with a setting: |simulated − exact|, and how the run failed if it did.
  std::function<Outcome(const StepSettings&)> run;
  std::optional<LineProblem> line;  // when it is a block on a line
  double error(const StepSettings& settings) const { return run(settings).error; }
};
// spring_pull, incline, tipping_box or where_methods_fail; throws InvalidInput listing them
// for another name.
BenchmarkProblem lesson_problem(const std::string& lesson);
// Every problem the benchmark charts, each with an exact answer: the three lessons' problems
// (incline's is a slope a degree above the sticking angle), the slope a degree below it,
// slides to rest with c and with b, the tipping threshold found by bisection against
// d/(2·mu_s), and the disk that starts to roll.
std::vector<BenchmarkProblem> benchmark_problems();

struct Trial {
  StepSettings settings;
  double error = 0.0;
  std::string fails;  // how the run failed, "" if it did not
  double cost = 0.0;  // CPU s per simulated s
  bool meets = false;  // within the tolerance, and no failure
};

// CPU seconds this thread has used: a measurement's own cost, whatever other threads (Mesa's
// rasterizer in the window) are doing.
double thread_cpu_seconds();
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
  // "7 failed: chatters 4, wrong answer 3", or "" when none did.
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
