// frictionlab bench's charts of the spring problem: error against cost (work-precision), one
// curve per method, points labelled by step rate, the Pareto front, failures marked; and error
// against step with the order of convergence fitted per method.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "app/bench.h"
#include "ui/chart.h"
#include "ui/headless.h"

namespace frictionlab {
namespace {

// A colour per method, in the order they are first met.
ImU32 method_colour(std::size_t index) {
  static const ImU32 palette[] = {IM_COL32(0, 114, 178, 255),  IM_COL32(230, 159, 0, 255),  IM_COL32(0, 158, 115, 255),
                                  IM_COL32(204, 121, 167, 255), IM_COL32(86, 180, 233, 255), IM_COL32(213, 94, 0, 255),
                                  IM_COL32(120, 120, 120, 255), IM_COL32(240, 228, 66, 255)};
  return palette[index % (sizeof palette / sizeof palette[0])];
}

std::string short_name(const std::string& method) {
  std::string name = method;
  for (const char* prefix : {"Box2D treatment=", "reduced "}) {
    if (name.rfind(prefix, 0) == 0) name = (std::string(prefix) == "reduced " ? "1-DOF " : "Box2D ") + name.substr(std::string(prefix).size());
  }
  return name;
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

std::string charts_png(const std::vector<ui::Chart>& charts, int columns, int width, int height, const std::string& name,
                       std::ostream* out) {
  try {
    const std::vector<std::uint8_t> png = ui::encode_png(ui::render_charts(charts, columns, width, height));
    return std::string(png.begin(), png.end());
  } catch (const ui::HeadlessUnavailable& error) {
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

std::string work_precision_png(const std::vector<AccuracyRun>& runs) {
  ui::Chart work;
  work.title = "Spring stick-slip: error against cost";
  work.x_label = "CPU time per simulated second (s)";
  work.y_label = "max position error over 10 s (m)";
  work.log_x = work.log_y = true;
  ui::Chart convergence;
  convergence.title = "Convergence: error against step";
  convergence.x_label = "step h (s)";
  convergence.y_label = "max position error (m)";
  convergence.log_x = convergence.log_y = true;

  std::vector<std::string> order;  // methods, as met
  std::map<std::string, std::vector<const AccuracyRun*>> by_method;
  for (const AccuracyRun& run : runs) {
    if (run.hz <= 0.0) continue;  // the exact reference has no step and no error
    if (!by_method.count(run.method)) order.push_back(run.method);
    by_method[run.method].push_back(&run);
  }
  ui::ChartSeries failures{"fails (chatters, or not a number)", {}, IM_COL32(200, 30, 30, 255), false, ui::Marker::cross, {}};
  std::vector<std::pair<double, double>> sound;  // (cost, error) of the runs that did not fail
  for (std::size_t i = 0; i < order.size(); ++i) {
    const ImU32 colour = method_colour(i);
    ui::ChartSeries cost_curve{short_name(order[i]), {}, colour, true, ui::Marker::dot, {}};
    ui::ChartSeries step_curve{"", {}, colour, true, ui::Marker::dot, {}};
    std::vector<std::pair<double, double>> converging;
    for (const AccuracyRun* run : by_method[order[i]]) {
      if (!std::isfinite(run->error)) {
        // Not a number: crossed along the top of the chart, at its cost.
        failures.points.push_back({run->cost, 1.0});
        continue;
      }
      cost_curve.points.push_back({run->cost, run->error});
      cost_curve.labels.push_back(std::to_string(static_cast<int>(run->hz)));
      step_curve.points.push_back({1.0 / run->hz, run->error});
      if (!run->fails.empty()) {
        failures.points.push_back({run->cost, run->error});
      } else {
        sound.push_back({run->cost, run->error});
        converging.push_back({1.0 / run->hz, run->error});
      }
    }
    char name[160];
    const double fitted = fitted_order(converging);
    if (std::isfinite(fitted)) {
      std::snprintf(name, sizeof name, "%s: order %.1f", short_name(order[i]).c_str(), std::abs(fitted) < 0.05 ? 0.0 : fitted);
    } else {
      std::snprintf(name, sizeof name, "%s: fails", short_name(order[i]).c_str());
    }
    step_curve.name = name;
    work.series.push_back(cost_curve);
    convergence.series.push_back(step_curve);
  }
  work.series.push_back({"Pareto front", pareto_front(sound), IM_COL32(20, 20, 20, 255), true, ui::Marker::none, {}});
  if (!failures.points.empty()) work.series.push_back(failures);
  work.notes = {"points labelled by step rate (Hz); the exact event-driven solution is the reference (error 0)"};
  convergence.notes = {"order: slope of log error against log h over the runs that did not fail"};
  return charts_png({work, convergence}, 2, 1920, 1080, "work_precision.png", nullptr);
}

}  // namespace frictionlab
