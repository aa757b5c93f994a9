// frictionlab bench, where the methods fail: the regularized law's stability map for explicit
// Euler, semi-implicit Euler and RK4 over (step, threshold), with linear theory's boundary on
// it; the creep a large threshold causes on a slope; the viscous term applied explicitly
// against the project's exact step. A CSV of every cell and one picture of the charts.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bench/reports/reports.h"
#include "app/table.h"
#include "draw/chart.h"
#include "draw/stability_chart.h"
#include "physics/stability.h"

namespace frictionlab {
namespace {

constexpr double g = 9.81;
const FrictionPair wood_on_wood{0.5, 0.4, 0.0, 0.0};

struct Method {
  Integrator integrator;
  const char* name;
};
constexpr Method methods[] = {{Integrator::explicit_euler, "explicit Euler"},
                              {Integrator::semi_implicit_euler, "semi-implicit Euler"},
                              {Integrator::rk4, "RK4"}};

const ImU32 theory_colour = IM_COL32(20, 20, 20, 255), measured_colour = IM_COL32(0, 90, 200, 255),
            explicit_colour = IM_COL32(240, 170, 120, 255);

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> stability_files(bool quick, const std::string& directory, std::ostream& out,
                                                                  const Progress& progress) {
  const std::vector<double> steps = logarithmic_range(1e-4, 1e-1, quick ? 13 : 31);
  const std::vector<double> epsilons = logarithmic_range(1e-4, 1e-1, quick ? 10 : 25);
  std::ostringstream csv;
  csv << "integrator,h_s,epsilon_m_per_s,behaviour,theoretical_boundary_h_s\n";
  std::vector<draw::Chart> charts;
  std::vector<std::vector<std::string>> table{{"method", "epsilon", "boundary h, theory", "measured", "measured / theory"}};
  for (const Method& method : methods) {
    // The maps are most of the work: a third each.
    progress(static_cast<double>(&method - methods) / 3.0);
    const std::vector<StabilityCell> cells = stability_map(wood_on_wood, g, method.integrator, steps, epsilons);
    for (const StabilityCell& cell : cells) {
      csv << method.name << ',' << cell.h << ',' << cell.epsilon << ',' << behaviour_name(cell.behaviour) << ','
          << theoretical_boundary(wood_on_wood, g, cell.epsilon, method.integrator) << '\n';
    }
    draw::Chart map = draw::stability_map_chart(std::string("Regularized friction, ") + method.name, cells, wood_on_wood, g,
                                            method.integrator, epsilons);
    draw::ChartSeries measured{"measured boundary", {}, measured_colour, false, draw::Marker::dot, {}};
    for (const double epsilon : {1e-3, 1e-2, 1e-1}) {
      const double expected = theoretical_boundary(wood_on_wood, g, epsilon, method.integrator);
      const double found = measured_boundary(wood_on_wood, g, epsilon, method.integrator);
      measured.points.push_back({epsilon, found});
      table.push_back({method.name, number(epsilon) + " m/s", number(expected) + " s", number(found) + " s",
                       number(found / expected)});
    }
    map.series.push_back(measured);
    map.notes = {"a block launched at 1 m/s on flat ground, \u03bcs = 0.5, \u03bck = 0.4"};
    charts.push_back(map);
  }

  // Creep on a 20° slope, where Coulomb's block sticks (tan 20° = 0.36 < 0.5).
  const double angle = 20.0 * M_PI / 180.0;
  draw::Chart creep;
  creep.title = "Creep on a 20\u00b0 slope, \u03bcs 0.5: it should hold";
  creep.x_label = "threshold speed \u03b5 (m/s)";
  creep.y_label = "creep speed (m/s)";
  creep.log_x = creep.log_y = true;
  draw::ChartSeries creep_theory{"theory: \u03b5\u00b7tan\u03b8/\u03bcs", {}, theory_colour, true, draw::Marker::none, {}};
  draw::ChartSeries creep_measured{"measured, h = boundary/5", {}, measured_colour, false,
                                 draw::Marker::dot, {}};
  double worst_creep = 0.0;
  for (const double epsilon : logarithmic_range(1e-3, 0.3, quick ? 6 : 12)) {
    const double h = 0.2 * theoretical_boundary(wood_on_wood, g, epsilon, Integrator::semi_implicit_euler);
    const double measured = creep_speed(wood_on_wood, g, angle, epsilon, h, Integrator::semi_implicit_euler);
    const double expected = theoretical_creep_speed(wood_on_wood, angle, epsilon);
    worst_creep = std::max(worst_creep, std::abs(measured / expected - 1.0));
    creep_theory.points.push_back({epsilon, expected});
    creep_measured.points.push_back({epsilon, measured});
  }
  creep.series = {creep_theory, creep_measured};
  creep.notes = {"semi-implicit Euler; at \u03b5 = 0.1 m/s it slides 0.73 m in 10 s"};
  charts.push_back(creep);

  // The viscous term: what one step does to the velocity.
  draw::Chart viscous;
  viscous.title = "Viscous term: one step's factor on v";
  viscous.x_label = "h\u00b7c/m";
  viscous.y_label = "v after / v before";
  draw::ChartSeries explicit_step{"explicit force: 1 \u2212 h\u00b7c/m", {}, explicit_colour, true, draw::Marker::none, {}};
  draw::ChartSeries exact_step{"FrictionLab (exact): e^(\u2212h\u00b7c/m)", {}, measured_colour, true, draw::Marker::none, {}};
  draw::ChartSeries bound_high{"|factor| = 1: stability", {}, theory_colour, true, draw::Marker::none, {}};
  draw::ChartSeries bound_low{"", {}, theory_colour, true, draw::Marker::none, {}};
  for (double ratio = 0.0; ratio <= 3.0 + 1e-9; ratio += 0.05) {
    explicit_step.points.push_back({ratio, viscous_explicit(ratio, 1)[1]});
    exact_step.points.push_back({ratio, viscous_exact(ratio, 1)[1]});
  }
  bound_high.points = {{0.0, 1.0}, {3.0, 1.0}};
  bound_low.points = {{0.0, -1.0}, {3.0, -1.0}};
  viscous.series = {bound_high, bound_low, explicit_step, exact_step};
  viscous.notes = {"explicit: reverses v past 1, grows past 2"};
  charts.push_back(viscous);

  out << "\nWhere methods fail: regularized friction's stability boundary (block on flat ground, mu_s = 0.5)\n";
  print_table(out, table);
  out << "Creep on a 20 degree slope: within " << number(100.0 * worst_creep) << " % of epsilon*tan(theta)/mu_s\n";

  std::vector<std::pair<std::string, std::string>> files{{directory + "/stability_map.csv", csv.str()}};
  if (std::string png = charts_png(charts, 3, 1920, 1080, "stability.png", &out); !png.empty()) {
    files.emplace_back(directory + "/stability.png", std::move(png));
  }
  return files;
}

}  // namespace frictionlab
