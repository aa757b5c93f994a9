#include "bench/cheapest_setting.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace frictionlab {

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

std::pair<Outcome, double> measure(const std::function<Outcome()>& run, double simulated, int repeats) {
  Outcome outcome;
  std::vector<double> costs;
  // The answer is the same each time (the step is fixed); the cost is the median of the
  // repeats, without the judging.
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const double start = thread_cpu_seconds();
    outcome = run();
    const double spent = thread_cpu_seconds() - start - outcome.judging;
    costs.push_back(spent / (outcome.simulated > 0.0 ? outcome.simulated : simulated));
  }
  std::sort(costs.begin(), costs.end());
  return {outcome, costs[costs.size() / 2]};
}

Trial measure_setting(const BenchmarkProblem& problem, const StepSettings& settings, int repeats, double tolerance) {
  const auto [outcome, cost] = measure([&] { return problem.run(settings); }, problem.simulated, repeats);
  Trial trial{settings, outcome.error, outcome.fails, cost, false};
  trial.meets = trial.error <= tolerance && trial.fails.empty();
  return trial;
}

std::string Recommender::failures() const {
  std::map<std::string, int> counts;
  int failed = 0;
  for (const Trial& trial : trials_) {
    if (trial.fails.empty()) continue;
    ++counts[trial.fails];
    ++failed;
  }
  if (failed == 0) return "";
  std::ostringstream text;
  text << failed << " of " << trials_.size() << " failed:";
  for (const auto& [why, count] : counts) text << (&why == &counts.begin()->first ? " " : ", ") << why << ' ' << count;
  return text.str();
}

void Recommender::run_next() {
  if (done()) return;
  trials_.push_back(measure_setting(problem_, candidates_[next_++], repeats_, tolerance_));
}

std::optional<Trial> Recommender::cheapest() const {
  std::optional<Trial> best;
  for (const Trial& trial : trials_) {
    if (trial.meets && (!best || trial.cost < best->cost)) best = trial;
  }
  return best;
}

}  // namespace frictionlab
