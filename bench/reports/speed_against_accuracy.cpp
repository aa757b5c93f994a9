// frictionlab bench, every benchmark problem: each friction treatment (the regularized law
// with three threshold speeds) at each step rate on each problem with an exact answer, and the
// reduced 1-DOF models on the problems that are a block on a line; the error, the CPU time per
// simulated second and how a run failed, in a CSV of every run and a work-precision chart per
// problem; and, on the spring problem, what the solver's velocity iterations and the
// sub-steps buy.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "bench/reports/reports.h"
#include "app/table.h"
#include "draw/chart.h"
#include "bench/cheapest_setting.h"

namespace frictionlab {
namespace {

struct Method {
  std::string name;
  std::optional<StepSettings> box2d;    // a Box2D scene with this setting (its rate set per run)
  std::optional<ReducedMethod> reduced; // or a reduced model, on line problems only
};

std::string epsilon_text(double epsilon) {
  std::ostringstream text;
  text << epsilon;
  return text.str();
}

std::vector<Method> methods() {
  std::vector<Method> all;
  auto box2d = [&](FrictionTreatment treatment, double epsilon, const std::string& suffix) {
    StepSettings settings;
    settings.treatment = treatment;
    settings.threshold_speed = epsilon;
    all.push_back({"Box2D + " + std::string(treatment_name(treatment)) + suffix, settings, std::nullopt});
  };
  box2d(FrictionTreatment::stick_slip, 0.01, "");
  box2d(FrictionTreatment::threshold, 0.01, "");
  for (const double epsilon : {0.1, 0.01, 0.001}) {
    box2d(FrictionTreatment::regularized, epsilon, " \u03b5=" + epsilon_text(epsilon));
  }
  box2d(FrictionTreatment::box2d, 0.01, "");
  for (const ReducedMethod method : {ReducedMethod::explicit_euler, ReducedMethod::semi_implicit_euler, ReducedMethod::rk4,
                                     ReducedMethod::located_events}) {
    all.push_back({reduced_method_name(method), std::nullopt, method});
  }
  return all;
}

// A method's name short enough for a list of fitted orders under a chart.
std::string short_method(std::string name) {
  for (const char* long_part : {"Box2D + ", " (regularized)", "1-DOF "}) {
    const std::size_t at = name.find(long_part);
    if (at != std::string::npos) name.erase(at, std::strlen(long_part));
  }
  return name;
}

// The threshold speed a method runs with; blank for those that use none (stick-slip, box2d,
// located events).
std::string epsilon_cell(const Method& method, double reduced_epsilon) {
  if (method.box2d) {
    const FrictionTreatment t = method.box2d->treatment;
    const bool uses = t == FrictionTreatment::threshold || t == FrictionTreatment::regularized;
    return uses ? epsilon_text(method.box2d->threshold_speed) : "";
  }
  return *method.reduced == ReducedMethod::located_events ? "" : epsilon_text(reduced_epsilon);
}

std::string quoted(const std::string& text) { return '"' + text + '"'; }

// How a run failed, in a letter for the terminal's table (its key is printed under it).
constexpr std::pair<const char*, const char*> failure_letters[] = {
    {"not a number", "N"}, {"blew up", "B"}, {"chatters", "C"},         {"spurious stick-slip", "S"},
    {"misses stick-slip", "M"}, {"never comes to rest", "R"}, {"sticks", "T"}, {"creeps", "K"},
    {"slides", "L"},       {"wrong answer", "W"}};

// The error at 240 Hz as the terminal table shows it: the number, and how the run failed.
std::string cell(const Outcome& outcome) {
  std::string letter;
  for (const auto& [failure, code] : failure_letters) {
    if (outcome.fails == failure) letter = code;
  }
  if (!std::isfinite(outcome.error)) return letter;
  return format_number(outcome.error, 2) + (letter.empty() ? "" : " " + letter);
}

// The fitted orders under a problem's chart, in lines of at most about 72 characters.
void note_fitted_orders(draw::Chart& chart, const std::vector<std::pair<std::string, double>>& orders) {
  std::string note = "fitted order:";
  for (const auto& [method, order] : orders) {
    char part[120];
    std::snprintf(part, sizeof part, " %s %.1f%s", short_method(method).c_str(), order, &order == &orders.back().second ? "" : ",");
    if (note.size() + std::strlen(part) > 72) {
      chart.notes.push_back(note);
      note = " ";
    }
    note += part;
  }
  if (!orders.empty()) chart.notes.push_back(note);
}

// The spring problem at 240 Hz with the stick-slip treatment: the solver's velocity
// iterations, and sub-steps at 60 Hz; each run written to the CSV as measured.
std::vector<AccuracyRun> spring_knob_runs(bool quick, int repeats, std::ostream& csv) {
  std::vector<AccuracyRun> knob_runs;
  const BenchmarkProblem spring = spring_problem();
  for (const int count : quick ? std::vector<int>{1, 8} : std::vector<int>{1, 2, 4, 8, 16, 32}) {
    StepSettings settings;
    settings.velocity_iterations = count;
    const Trial run = measure_setting(spring, settings, repeats, INFINITY);
    csv << quoted(spring.name) << ',' << quoted(spring.question) << ",m,\"Box2D + stick-slip\",stick-slip,,240,1," << count << ',' << run.error << ',' << run.cost << ',' << run.fails << '\n';
    knob_runs.push_back({"240 Hz, velocity iterations", static_cast<double>(count), run.error, run.cost, run.fails});
  }
  for (const int count : quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8, 16}) {
    StepSettings settings;
    settings.hz = 60;
    settings.substeps = count;
    const Trial run = measure_setting(spring, settings, repeats, INFINITY);
    csv << quoted(spring.name) << ',' << quoted(spring.question) << ",m,\"Box2D + stick-slip\",stick-slip,,60," << count << ",8," << run.error << ',' << run.cost << ',' << run.fails << '\n';
    knob_runs.push_back({"60 Hz, sub-steps", static_cast<double>(count), run.error, run.cost, run.fails});
  }
  return knob_runs;
}

// The legend chart from a problem chart's series: every method's colour, and the marks.
void finish_methods_legend(draw::Chart& legend) {
  std::erase_if(legend.series, [](const draw::ChartSeries& series) { return series.marker == draw::Marker::cross; });
  for (draw::ChartSeries& series : legend.series) {
    const std::size_t cut = series.name.find(" (order");
    if (cut != std::string::npos) series.name.erase(cut);
    series.points.clear();
  }
  const auto [failed, wrong] = failure_marks();
  legend.series.push_back(failed);
  legend.series.push_back(wrong);
  legend.notes = {"points labelled by step rate (Hz)", "exact answers (error 0) drawn at 10\u207b\u00b9\u00b2",
                  "fitted order: slope of log error against log step", "over the runs that did not fail"};
}

}  // namespace

std::vector<std::pair<std::string, std::string>> problem_files(bool quick, const std::string& directory, std::ostream& out,
                                                                const Progress& progress) {
  const std::vector<double> rates = quick ? std::vector<double>{60, 240} : std::vector<double>{30, 60, 120, 240, 480, 960, 1920};
  const int repeats = quick ? 1 : 3;
  const double reduced_epsilon = StepSettings{}.threshold_speed;
  const std::vector<Method> all = methods();
  const std::vector<BenchmarkProblem> problems = benchmark_problems();
  std::ostringstream csv;
  csv << "problem,measure,unit,method,treatment,epsilon_m_per_s,hz,substeps,velocity_iterations,error,cpu_s_per_simulated_s,fails\n";
  std::vector<draw::Chart> charts;
  // Fitted orders: a row per problem, a column per method (short names).
  std::vector<std::vector<std::string>> order_table{{"fitted order"}};
  for (const Method& method : all) order_table[0].push_back(short_method(method.name));
  // A row per method, a column per problem.
  std::vector<std::vector<std::string>> table{{"method at 240 Hz"}};
  for (const Method& method : all) table.push_back({method.name});
  for (const BenchmarkProblem& problem : problems) table[0].push_back(problem.label + " (" + problem.unit + ")");
  draw::Chart legend;
  legend.title = "Every chart's methods";
  legend.legend = draw::Chart::Legend::only;
  std::size_t done = 0;
  const std::size_t total = problems.size() * all.size() * rates.size();
  for (const BenchmarkProblem& problem : problems) {
    std::vector<AccuracyRun> runs;
    for (std::size_t m = 0; m < all.size(); ++m) {
      const Method& method = all[m];
      std::string at_240 = "";
      for (const double hz : rates) {
        progress(static_cast<double>(done++) / static_cast<double>(total));
        if (method.reduced && !problem.line) continue;  // a box that tips, a disk that rolls: not a block on a line
        std::pair<Outcome, double> measured;
        if (method.box2d) {
          StepSettings settings = *method.box2d;
          settings.hz = hz;
          measured = measure([&] { return problem.run(settings); }, problem.simulated, repeats);
        } else {
          measured = measure([&] { return run_reduced(*problem.line, *method.reduced, hz, reduced_epsilon); }, problem.simulated,
                             repeats);
        }
        const auto& [outcome, cost] = measured;
        const StepSettings shown = method.box2d.value_or(StepSettings{});
        csv << quoted(problem.name) << ',' << quoted(problem.question) << ',' << problem.unit << ',' << quoted(method.name) << ','
            << (method.box2d ? std::string(treatment_name(shown.treatment)) : "") << ','
            << epsilon_cell(method, reduced_epsilon) << ',' << hz << ','
            << (method.box2d ? "1," + std::to_string(shown.velocity_iterations) : ",") << ',' << outcome.error << ',' << cost << ','
            << outcome.fails << '\n';
        if (hz == 240) at_240 = cell(outcome);
        runs.push_back({method.name, hz, outcome.error, cost, outcome.fails});
      }
      table[m + 1].push_back(method.reduced && !problem.line ? "-" : at_240);
    }
    std::vector<std::pair<std::string, double>> orders;
    draw::Chart chart = work_precision_chart(problem.name, "error (" + problem.unit + ")", runs, true, &orders);
    std::vector<std::string> order_row{problem.label};
    for (const Method& method : all) {
      const auto found = std::find_if(orders.begin(), orders.end(), [&](const auto& entry) { return entry.first == method.name; });
      order_row.push_back(found == orders.end() ? "-" : format_number(found->second, 2));
    }
    order_table.push_back(order_row);
    // One legend for all (the colours are the same in every chart), the fitted orders here.
    chart.legend = draw::Chart::Legend::none;
    chart.notes.pop_back();
    note_fitted_orders(chart, orders);
    charts.push_back(chart);
    if (legend.series.empty()) legend.series = chart.series;
  }

  const std::vector<AccuracyRun> knob_runs = spring_knob_runs(quick, repeats, csv);
  finish_methods_legend(legend);
  charts.push_back(legend);
  draw::Chart knobs = work_precision_chart("Spring, Box2D + stick-slip: iterations and sub-steps", "error (m)", knob_runs, false);
  knobs.series[0].colour = IM_COL32(0, 114, 178, 255);
  knobs.series[1].colour = IM_COL32(204, 121, 167, 255);
  knobs.notes = {"labels: velocity iterations at 240 Hz; sub-steps per 1/60 s frame"};
  charts.push_back(knobs);
  progress(1.0);

  out << "\nEvery benchmark problem at 240 Hz: error against the exact answer, and how a run failed (CSV: every rate, "
         "work_precision.csv)\n";
  print_table(out, table);
  out << "failed:";
  for (const auto& [failure, code] : failure_letters) out << ' ' << code << " = " << failure << (code[0] == 'W' ? "\n" : ",");
  out << "-: not a block on a line, so no 1-DOF model\n";
  if (rates.size() >= 3) {  // --quick runs two rates: too few to fit an order
    out << "\nOrder of convergence per problem: slope of log error against log step over the runs that did not fail and\n"
           "were not exact (-: fewer than three such runs)\n";
    print_table(out, order_table);
  }
  std::vector<std::pair<std::string, std::string>> files{{directory + "/work_precision.csv", csv.str()}};
  if (std::string png = charts_png(charts, 3, 2700, 3000, "problems.png", &out); !png.empty()) {
    files.emplace_back(directory + "/problems.png", std::move(png));
  }
  return files;
}

}  // namespace frictionlab
