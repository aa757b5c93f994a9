// frictionlab bench, every benchmark problem: each friction treatment at each step rate on
// each problem with an exact answer (error, CPU time per simulated second), a CSV of every
// run and one work-precision chart per problem; and, on the spring problem, what the solver's
// velocity iterations and the sub-steps buy.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/bench.h"
#include "app/table.h"
#include "physics/recommend.h"
#include "ui/chart.h"

namespace frictionlab {
namespace {

const ImU32 treatment_colours[] = {IM_COL32(0, 114, 178, 255), IM_COL32(230, 159, 0, 255), IM_COL32(0, 158, 115, 255),
                                   IM_COL32(204, 121, 167, 255)};
constexpr FrictionTreatment treatments[] = {FrictionTreatment::stick_slip, FrictionTreatment::threshold,
                                            FrictionTreatment::regularized, FrictionTreatment::box2d};
// Exact answers (a block that should not move and does not) are drawn at this floor.
constexpr double error_floor = 1e-12;

}  // namespace

std::vector<std::pair<std::string, std::string>> problem_files(bool quick, const std::string& directory, std::ostream& out) {
  const std::vector<double> rates = quick ? std::vector<double>{60, 240} : std::vector<double>{30, 60, 120, 240, 480, 960, 1920};
  const int repeats = quick ? 1 : 3;
  std::ostringstream csv;
  csv << "problem,measure,unit,treatment,hz,substeps,velocity_iterations,error,cpu_s_per_simulated_s,fails\n";
  std::vector<ui::Chart> charts;
  std::vector<std::vector<std::string>> table{{"problem", "stick-slip", "threshold", "regularized", "box2d", "unit"}};
  for (const BenchmarkProblem& problem : benchmark_problems()) {
    ui::Chart chart;
    chart.title = problem.name;
    chart.x_label = "CPU time per simulated second (s)";
    chart.y_label = "error (" + problem.unit + ")";
    chart.log_x = chart.log_y = true;
    std::vector<std::pair<double, double>> sound;
    std::vector<double> wrong_costs;
    int exact = 0;
    std::vector<std::string> row{problem.name};
    for (std::size_t t = 0; t < 4; ++t) {
      ui::ChartSeries series{std::string(treatment_name(treatments[t])), {}, treatment_colours[t], true, ui::Marker::dot, {}};
      double at_240 = NAN;
      for (const double hz : rates) {
        StepSettings settings;
        settings.treatment = treatments[t];
        settings.hz = hz;
        const Trial run = measure_setting(problem, settings, repeats, INFINITY);
        const bool failed = !std::isfinite(run.error);
        csv << '"' << problem.name << "\",\"" << problem.question << "\"," << problem.unit << ','
            << treatment_name(treatments[t]) << ',' << hz << ",1," << settings.velocity_iterations << ',' << run.error
            << ',' << run.cost << ',' << (failed ? "wrong answer" : "") << '\n';
        if (hz == 240) at_240 = run.error;
        if (failed) {
          wrong_costs.push_back(run.cost);
          continue;
        }
        exact += run.error < error_floor;
        const double shown = std::max(run.error, error_floor);
        series.points.push_back({run.cost, shown});
        series.labels.push_back(std::to_string(static_cast<int>(hz)));
        sound.push_back({run.cost, shown});
      }
      row.push_back(std::isfinite(at_240) ? format_number(at_240, 3) : "wrong");
      chart.series.push_back(series);
    }
    row.push_back(problem.unit);
    table.push_back(row);
    chart.series.push_back({"Pareto front", pareto_front(sound), IM_COL32(20, 20, 20, 255), true, ui::Marker::none, {}});
    if (!wrong_costs.empty()) {
      // A wrong answer has no error to draw: it is crossed along the top, at its cost.
      double top = error_floor;
      for (const auto& point : sound) top = std::max(top, point.second);
      ui::ChartSeries wrong{"wrong answer", {}, IM_COL32(200, 30, 30, 255), false, ui::Marker::cross, {}};
      for (const double cost : wrong_costs) wrong.points.push_back({cost, 3.0 * top});
      chart.series.push_back(wrong);
    }
    if (exact > 0) chart.notes.push_back(std::to_string(exact) + " runs exact (error 0), drawn at 10\u207b\u00b9\u00b2");
    charts.push_back(chart);
  }

  // The spring problem at 240 Hz with the stick-slip treatment: the solver's velocity
  // iterations, and sub-steps at 60 Hz.
  ui::Chart knobs;
  knobs.title = "Spring, stick-slip: iterations and sub-steps";
  knobs.x_label = "CPU time per simulated second (s)";
  knobs.y_label = "error (m)";
  knobs.log_x = knobs.log_y = true;
  ui::ChartSeries iterations{"240 Hz, velocity iterations", {}, treatment_colours[0], true, ui::Marker::dot, {}};
  ui::ChartSeries substeps{"60 Hz, sub-steps", {}, treatment_colours[3], true, ui::Marker::dot, {}};
  const BenchmarkProblem spring = lesson_problem("spring_pull");
  for (const int count : quick ? std::vector<int>{1, 8} : std::vector<int>{1, 2, 4, 8, 16, 32}) {
    StepSettings settings;
    settings.velocity_iterations = count;
    const Trial run = measure_setting(spring, settings, repeats, INFINITY);
    csv << '"' << spring.name << "\",\"" << spring.question << "\",m,stick-slip,240,1," << count << ',' << run.error << ',' << run.cost << ",\n";
    iterations.points.push_back({run.cost, std::max(run.error, error_floor)});
    iterations.labels.push_back(std::to_string(count));
  }
  for (const int count : quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8, 16}) {
    StepSettings settings;
    settings.hz = 60;
    settings.substeps = count;
    const Trial run = measure_setting(spring, settings, repeats, INFINITY);
    csv << '"' << spring.name << "\",\"" << spring.question << "\",m,stick-slip,60," << count << ",8," << run.error << ',' << run.cost << ",\n";
    substeps.points.push_back({run.cost, std::max(run.error, error_floor)});
    substeps.labels.push_back(std::to_string(count) + "\u00d7");
  }
  knobs.series = {iterations, substeps};
  knobs.notes = {"labels: velocity iterations; sub-steps per 1/60 s frame"};
  charts.push_back(knobs);

  out << "\nEvery benchmark problem at 240 Hz: error against the exact answer (CSV: every rate, work_precision.csv)\n";
  print_table(out, table);
  std::vector<std::pair<std::string, std::string>> files{{directory + "/work_precision.csv", csv.str()}};
  if (std::string png = charts_png(charts, 3, 2400, 2100, "problems.png", &out); !png.empty()) {
    files.emplace_back(directory + "/problems.png", std::move(png));
  }
  return files;
}

}  // namespace frictionlab
