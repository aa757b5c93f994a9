#include "draw/stability_chart.h"

#include <cstdio>

namespace frictionlab::draw {

Chart stability_map_chart(const std::string& title, const std::vector<StabilityCell>& cells, const FrictionPair& pair,
                          double gravity, Integrator integrator, const std::vector<double>& epsilons) {
  Chart map;
  map.title = title;
  map.x_label = "threshold speed \u03b5 (m/s)";
  map.y_label = "step h (s)";
  map.log_x = map.log_y = true;
  map.categories = {{"stable: settles", IM_COL32(150, 214, 170, 255)},
                    {"chattering: never settles", IM_COL32(240, 170, 120, 255)},
                    {"divergent", IM_COL32(200, 70, 70, 255)}};
  for (const StabilityCell& cell : cells) map.cells.push_back({cell.epsilon, cell.h, static_cast<int>(cell.behaviour)});
  char name[80];
  std::snprintf(name, sizeof name, "theory: h = %.4g\u00b7\u03b5/(\u03bcs\u00b7g)",
                theoretical_boundary(pair, gravity, 1.0, integrator) * pair.mu_s * gravity);
  ChartSeries theory{name, {}, IM_COL32(20, 20, 20, 255), true, Marker::none, {}};
  for (const double epsilon : epsilons) theory.points.push_back({epsilon, theoretical_boundary(pair, gravity, epsilon, integrator)});
  map.series = {theory};
  return map;
}

}  // namespace frictionlab::draw
