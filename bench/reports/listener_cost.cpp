// frictionlab bench: what the pair-table friction listener costs per step, against Box2D's own
// friction mixer, on piles of boxes of three sizes (listener_cost.csv).
// Figures are measured here and reported, never asserted: the machines are shared.
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/table.h"
#include "bench/reports/reports.h"
#include "bench/problems.h"
#include "physics/scenarios.h"

namespace frictionlab {
namespace {

// CPU seconds per step of both worlds, timed in alternating blocks so that a busy neighbour
// slows both alike.
struct PileCost {
  int boxes;
  double listener, plain;
};
PileCost time_pile(int rows, int steps, int repeats) {
  const StepSettings settings;
  Pyramid with = make_pyramid(rows, true, settings);
  Pyramid without = make_pyramid(rows, false, settings);
  const float h = static_cast<float>(1.0 / settings.hz);
  for (int i = 0; i < 30; ++i) {  // let the contacts form and the pile settle before timing
    with.scene->step();
    without.plain->Step(h, settings.velocity_iterations, settings.position_iterations);
  }
  std::vector<double> listener, plain;
  for (int r = 0; r < repeats; ++r) {
    double start = thread_cpu_seconds();
    for (int i = 0; i < steps; ++i) with.scene->step();
    listener.push_back((thread_cpu_seconds() - start) / steps);
    start = thread_cpu_seconds();
    for (int i = 0; i < steps; ++i) without.plain->Step(h, settings.velocity_iterations, settings.position_iterations);
    plain.push_back((thread_cpu_seconds() - start) / steps);
  }
  return {with.boxes, median(listener), median(plain)};
}

}  // namespace

std::string listener_cost(bool quick, std::ostream& out) {
  std::ostringstream csv;
  csv << "boxes,listener_ms_per_step,box2d_mixer_ms_per_step,ratio\n";
  std::vector<std::vector<std::string>> table{{"boxes", "with listener (ms/step)", "Box2D mixer (ms/step)", "ratio"}};
  for (int rows : {22, 44, 89}) {
    const int steps = quick ? 10 : (rows > 60 ? 60 : 200);
    const PileCost cost = time_pile(rows, steps, quick ? 1 : 5);
    csv << cost.boxes << ',' << cost.listener * 1e3 << ',' << cost.plain * 1e3 << ',' << cost.listener / cost.plain
        << '\n';
    table.push_back({std::to_string(cost.boxes), format_number(cost.listener * 1e3), format_number(cost.plain * 1e3),
                     format_number(cost.listener / cost.plain, 3)});
  }
  out << "Cost of the pair-table listener (pyramid of boxes, 240 Hz, 8 velocity iterations)\n";
  print_table(out, table);
  return csv.str();
}

}  // namespace frictionlab
