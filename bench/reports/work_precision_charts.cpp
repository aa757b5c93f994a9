// frictionlab bench's charts: error against cost (work-precision), one curve per method, points
// labelled by step rate, the Pareto front, failures marked; and, for the spring problem, error
// against step with the order of convergence fitted per method.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "bench/reports/reports.h"
#include "draw/chart.h"
#include "draw/headless.h"
#include "draw/headless_render.h"

namespace frictionlab {
namespace {

// Exact answers (a block that should not move and does not) are drawn at this floor.
constexpr double error_floor = 1e-12;

// A colour per method, the same in every chart: the Box2D treatments in the lesson plots'
// blue, orange, greens (the regularized law, darker for a smaller epsilon) and pink; the
// reduced 1-DOF models in vermilion, grey, sky blue and purple.
ImU32 method_colour(const std::string& method) {
  // The reduced models first: their names say "regularized" too.
  const std::pair<const char*, ImU32> colours[] = {
      {"explicit Euler", IM_COL32(213, 94, 0, 255)},
      {"semi-implicit", IM_COL32(120, 120, 120, 255)},
      {"located", IM_COL32(110, 60, 160, 255)},
      {"RK4", IM_COL32(86, 180, 233, 255)},
      {"stick-slip", IM_COL32(0, 114, 178, 255)},
      {"threshold", IM_COL32(230, 159, 0, 255)},
      {"regularized \u03b5=0.1", IM_COL32(120, 200, 160, 255)},
      {"regularized \u03b5=0.001", IM_COL32(0, 90, 60, 255)},
      {"regularized", IM_COL32(0, 158, 115, 255)},
      {"box2d", IM_COL32(204, 121, 167, 255)}};
  for (const auto& [part, colour] : colours) {
    if (method.find(part) != std::string::npos) return colour;
  }
  return IM_COL32(40, 40, 40, 255);
}

// Least-squares slope of log(error) against log(h): the order of convergence.
double fitted_order(const std::vector<std::pair<double, double>>& step_and_error) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [h, error] : step_and_error) {
    const double x = std::log(h), y = std::log(error);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return n < 2 ? NAN : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

std::string charts_png(const std::vector<draw::Chart>& charts, int columns, int width, int height, const std::string& name,
                       std::ostream* out) {
  try {
    const std::vector<std::uint8_t> png = draw::encode_png(draw::render_charts(charts, columns, width, height));
    return std::string(png.begin(), png.end());
  } catch (const draw::HeadlessUnavailable& error) {
    if (out) *out << name << ": not drawn, " << error.what() << '\n';
    return "";
  }
}

std::vector<std::pair<double, double>> pareto_front(std::vector<std::pair<double, double>> points) {
  std::sort(points.begin(), points.end());
  std::vector<std::pair<double, double>> front;
  for (const auto& point : points) {
    if (front.empty() || point.second < front.back().second) front.push_back(point);
  }
  return front;
}

std::pair<draw::ChartSeries, draw::ChartSeries> failure_marks() {
  return {{"failed run (chatter, wrong stops, creep, slide)", {}, IM_COL32(200, 30, 30, 255), false, draw::Marker::cross, {}},
          {"wrong answer (no error to draw), along the top", {}, IM_COL32(120, 0, 0, 255), false, draw::Marker::cross, {}}};
}

draw::Chart work_precision_chart(const std::string& title, const std::string& y_label, const std::vector<AccuracyRun>& runs,
                               bool fit_orders, std::vector<std::pair<std::string, double>>* orders) {
  draw::Chart chart;
  chart.title = title;
  chart.x_label = "CPU time per simulated second (s)";
  chart.y_label = y_label;
  chart.log_x = chart.log_y = true;
  std::vector<std::string> order;  // methods, as met
  std::map<std::string, std::vector<const AccuracyRun*>> by_method;
  for (const AccuracyRun& run : runs) {
    if (run.hz <= 0.0) continue;  // an exact reference has no step and no error
    if (!by_method.count(run.method)) order.push_back(run.method);
    by_method[run.method].push_back(&run);
  }
  auto [failed, wrong] = failure_marks();
  std::vector<double> wrong_costs;
  std::vector<std::pair<double, double>> sound;  // (cost, error) of the runs that did not fail
  int exact = 0;
  for (const std::string& method : order) {
    draw::ChartSeries curve{method, {}, method_colour(method), true, draw::Marker::dot, {}};
    std::vector<std::pair<double, double>> converging;
    for (const AccuracyRun* run : by_method[method]) {
      if (!std::isfinite(run->error)) {
        wrong_costs.push_back(run->cost);
        continue;
      }
      exact += run->error < error_floor;
      const double shown = std::max(run->error, error_floor);
      curve.points.push_back({run->cost, shown});
      curve.labels.push_back(std::to_string(static_cast<int>(run->hz)));
      if (!run->fails.empty()) {
        failed.points.push_back({run->cost, shown});
      } else {
        sound.push_back({run->cost, shown});
        if (run->error >= error_floor) converging.push_back({1.0 / run->hz, run->error});
      }
    }
    const double order_fitted = fit_orders && converging.size() >= 3 ? fitted_order(converging) : NAN;
    if (std::isfinite(order_fitted)) {
      if (orders) orders->push_back({method, std::abs(order_fitted) < 0.05 ? 0.0 : order_fitted});
      char name[200];
      std::snprintf(name, sizeof name, "%s (order %.1f)", method.c_str(), std::abs(order_fitted) < 0.05 ? 0.0 : order_fitted);
      curve.name = name;
    }
    chart.series.push_back(curve);
  }
  chart.series.push_back({"Pareto front", pareto_front(sound), IM_COL32(20, 20, 20, 255), true, draw::Marker::none, {}});
  if (!failed.points.empty()) chart.series.push_back(failed);
  if (!wrong_costs.empty()) {
    // A wrong answer has no error to draw: it is crossed along the top, at its cost.
    double top = error_floor;
    for (const auto& point : sound) top = std::max(top, point.second);
    for (const auto& point : failed.points) top = std::max(top, point.second);
    for (const double cost : wrong_costs) wrong.points.push_back({cost, 3.0 * top});
    chart.series.push_back(wrong);
  }
  if (exact > 0) chart.notes.push_back(std::to_string(exact) + " runs exact (error 0), drawn at 10\u207b\u00b9\u00b2");
  if (fit_orders) {
    chart.notes.push_back("points labelled by step rate (Hz); order: slope of log error against log step, over the runs that did not fail");
  }
  return chart;
}

std::string work_precision_png(const std::vector<AccuracyRun>& runs) {
  draw::Chart work = work_precision_chart("Spring stick-slip: error against cost", "max position error over 10 s (m)", runs);
  work.notes.back() = "points labelled by step rate (Hz); the exact event-driven solution is the reference (error 0)";
  draw::Chart convergence;
  convergence.title = "Convergence: error against step";
  convergence.x_label = "step h (s)";
  convergence.y_label = "max position error (m)";
  convergence.log_x = convergence.log_y = true;
  std::vector<std::string> order;
  std::map<std::string, std::vector<const AccuracyRun*>> by_method;
  for (const AccuracyRun& run : runs) {
    if (run.hz <= 0.0 || !std::isfinite(run.error)) continue;
    if (!by_method.count(run.method)) order.push_back(run.method);
    by_method[run.method].push_back(&run);
  }
  for (const std::string& method : order) {
    draw::ChartSeries step_curve{"", {}, method_colour(method), true, draw::Marker::dot, {}};
    std::vector<std::pair<double, double>> converging;
    for (const AccuracyRun* run : by_method[method]) {
      step_curve.points.push_back({1.0 / run->hz, run->error});
      if (run->fails.empty()) converging.push_back({1.0 / run->hz, run->error});
    }
    char name[200];
    const double fitted = fitted_order(converging);
    if (std::isfinite(fitted)) {
      std::snprintf(name, sizeof name, "%s: order %.1f", method.c_str(), std::abs(fitted) < 0.05 ? 0.0 : fitted);
    } else {
      std::snprintf(name, sizeof name, "%s: fails", method.c_str());
    }
    step_curve.name = name;
    convergence.series.push_back(step_curve);
  }
  convergence.notes = {"order: slope of log error against log h over the runs that did not fail"};
  return charts_png({work, convergence}, 2, 1920, 1080, "work_precision.png", nullptr);
}

}  // namespace frictionlab
