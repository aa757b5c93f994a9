// frictionlab bench: how accuracy on the spring's stick-slip problem trades against CPU time, for
// each friction treatment in Box2D and for the reduced one-degree-of-freedom models, against the
// exact event-driven solution (stick_slip_accuracy.csv; the work-precision chart is drawn from
// its runs, work_precision_charts.cpp).
// Figures are measured here and reported, never asserted: the machines are shared.
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/table.h"
#include "bench/cheapest_setting.h"
#include "bench/problems.h"
#include "bench/reports/reports.h"
#include "physics/reduced_model.h"

namespace frictionlab {

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

}  // namespace frictionlab
