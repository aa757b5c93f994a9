#include "physics/recommend.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <sstream>

#include "physics/closed_forms.h"
#include "physics/scenarios.h"

namespace frictionlab {
namespace {

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// A block released on a 40° slope (above atan 0.6 = 31°, so it slides): the distance it has
// gone against ½·g·(sin θ − μk·cos θ)·t², at every step of 2 s.
double incline_error(const StepSettings& settings) {
  Incline setup;
  setup.angle = 40.0 * M_PI / 180.0;
  auto scene = make_incline(setup, settings);
  const double a = theory::incline_sliding_acceleration(setup.angle, setup.block.pair.mu_k, standard_gravity);
  double worst = 0.0;
  while (scene->time() < 2.0 - 0.5 * scene->frame_step()) {
    scene->step();
    const double exact = 0.5 * a * scene->time() * scene->time();
    worst = std::max(worst, std::abs(scene->probe("distance").history.back() - exact));
  }
  return worst;
}

// The tipping box pushed at 0.7 m (above d/(2·μs) = 0.5 m): it must tip, at the push
// m·g·d/(2·h); a box that slides instead has the answer wrong altogether.
double tipping_error(const StepSettings& settings) {
  PushedBox setup;
  setup.push_height = 0.7;
  const double mg = setup.block.mass * standard_gravity;
  const double tipping_push = mg * setup.block.width / (2.0 * setup.push_height);
  const PushResult result = run_pushed_box(setup, settings, tipping_push / setup.push_rate + 1.0);
  return result.tipped ? std::abs(result.force - tipping_push) : INFINITY;
}

}  // namespace

BenchmarkProblem lesson_problem(const std::string& lesson) {
  if (lesson == "spring_pull") {
    return {lesson, "the spring-pulled block's largest position error over 10 s, against the exact stick-slip solution",
            "m", 10.0, [](const StepSettings& settings) { return spring_pull_max_error(SpringPull{}, settings, 10.0); }};
  }
  if (lesson == "incline") {
    return {lesson, "the distance slid down a 40\u00b0 slope, largest error over 2 s against \u00bd\u00b7a\u00b7t\u00b2", "m", 2.0,
            incline_error};
  }
  if (lesson == "tipping_box") {
    return {lesson, "the push at which the box pushed at 0.7 m tips, against m\u00b7g\u00b7d/(2\u00b7h) = 35.0 N", "N", 2.75,
            tipping_error};
  }
  throw InvalidInput("no benchmark problem for '" + lesson + "'; there is one for spring_pull, incline and tipping_box");
}

std::string describe(const StepSettings& settings) {
  std::ostringstream text;
  text << treatment_name(settings.treatment) << " at " << settings.hz << " Hz, " << settings.substeps << " sub-step"
       << (settings.substeps == 1 ? "" : "s");
  return text.str();
}

Recommender::Recommender(BenchmarkProblem problem, double tolerance, int repeats)
    : problem_(std::move(problem)), tolerance_(tolerance), repeats_(std::max(1, repeats)) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InvalidInput("the tolerance must be a positive number of " + problem_.unit);
  }
  for (const FrictionTreatment treatment : {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                                            FrictionTreatment::regularized, FrictionTreatment::box2d}) {
    for (const double hz : {30.0, 60.0, 120.0, 240.0, 480.0, 960.0, 1920.0}) {
      for (const int substeps : {1, 2, 4}) {
        StepSettings settings;
        settings.treatment = treatment;
        settings.hz = hz;
        settings.substeps = substeps;
        candidates_.push_back(settings);
      }
    }
  }
}

void Recommender::run_next() {
  if (done()) return;
  Trial trial;
  trial.settings = candidates_[next_++];
  std::vector<double> costs;
  // The error is the same each time (the step is fixed); the cost is the median of the repeats.
  for (int r = 0; r < repeats_; ++r) {
    const double start = cpu_seconds();
    trial.error = problem_.error(trial.settings);
    costs.push_back((cpu_seconds() - start) / problem_.simulated);
  }
  std::sort(costs.begin(), costs.end());
  trial.cost = costs[costs.size() / 2];
  trial.meets = trial.error <= tolerance_;
  trials_.push_back(trial);
}

std::optional<Trial> Recommender::cheapest() const {
  std::optional<Trial> best;
  for (const Trial& trial : trials_) {
    if (trial.meets && (!best || trial.cost < best->cost)) best = trial;
  }
  return best;
}

}  // namespace frictionlab
