// Benchmark problems with exact answers, for speed against accuracy (the bench's own: a built-in
// lesson is judged by its own script, bench/lesson_problem.h), each runnable in Box2D with any setting and, where the
// problem is a block on a line, by the reduced 1-DOF models; every run judged by its error and
// by how it failed (RunCheck).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/reduced_model.h"
#include "bench/run_check.h"
#include "physics/scene.h"

namespace frictionlab {

// CPU seconds this thread has used: a measurement's own cost, whatever other threads (Mesa's
// rasterizer in the window) are doing.
double thread_cpu_seconds();

// What a run answered: its error against the exact answer, and how it failed ("" when it did
// not: see RunCheck). An infinite error is an answer wrong altogether, such as a box that
// slides where it should tip.
struct Outcome {
  double error = 0.0;
  std::string fails;
  double judging = 0.0;    // CPU s spent judging the run rather than running it: not its cost
  double simulated = 0.0;  // s simulated, when a run decides it (a bisection); else the problem's
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
  std::string question;  // what is compared with the exact answer, in words
  std::string unit;      // of the error
  double simulated = 1.0;  // s, for the cost per simulated second
  // The Box2D scene with a setting: |simulated − exact|, and how the run failed if it did.
  std::function<Outcome(const StepSettings&)> run;
  std::optional<LineProblem> line;  // when it is a block on a line
  double error(const StepSettings& settings) const { return run(settings).error; }
};
// The bench's own problems, in C++ with exact answers (none of them is a lesson's copy):
// a block (0.4 × 0.2 m, mu_s 0.6, mu_k 0.4) pulled through a spring at constant speed, stick-slip
// over 10 s; a block on a slope a degree above its sticking angle; a box pushed at 0.3 m (slides)
// and at 0.7 m (tips); a block on a slope of `angle` radians below its sticking angle.
BenchmarkProblem spring_problem();
BenchmarkProblem incline_slides_problem();
BenchmarkProblem tipping_push_problem();
BenchmarkProblem incline_sticks_problem(double angle);
// Every problem the benchmark charts, each with an exact answer: the spring, the slope a
// degree above the sticking angle and a degree below it, slides to rest with c and with b, the
// tipping push, the tipping threshold found by bisection against d/(2·mu_s), and the disk that
// starts to roll.
std::vector<BenchmarkProblem> benchmark_problems();

}  // namespace frictionlab
