// The built-in demonstration: each situation of the seed articles simulated through the
// friction listener at 240 Hz and compared with its closed form.
#include <cmath>
#include <ostream>

#include "app/modes.h"
#include "app/table.h"
#include "physics/closed_forms.h"

namespace frictionlab {

int run_demo(std::ostream& out) {
  const StepSettings settings;  // 240 Hz, 8 velocity iterations, stick-slip
  std::vector<Measurement> rows;

  const SpringPull spring;
  for (const Measurement& m : spring_pull_measurements(spring, settings, 10.0)) rows.push_back(m);

  const Block block;
  rows.push_back(measure_breakaway_force(block, settings));
  rows.push_back(measure_sliding_friction(block, settings));

  Incline incline;
  const double holding_angle = 0.98 * theory::sticking_angle(block.pair.mu_s);
  incline.angle = holding_angle;
  rows.push_back(measure_incline_creep(incline, settings, 3.0));
  incline.angle = 40.0 * M_PI / 180.0;
  rows.push_back(measure_incline_acceleration(incline, settings));

  Slide viscous;
  viscous.block.pair.c = 2.0;
  Measurement m = measure_slide_distance(viscous, settings);
  m.name += " (c = 2 N·s/m)";
  rows.push_back(m);
  Slide quadratic;
  quadratic.block.pair.b = 0.5;
  m = measure_slide_distance(quadratic, settings);
  m.name += " (b = 0.5 N·s²/m²)";
  rows.push_back(m);

  PushedBox box;
  const double tip = theory::tip_height(box.block.width, box.block.pair.mu_s);
  for (double height : {0.7 * tip, 1.3 * tip}) {
    box.push_height = height;
    const theory::PushOutcome predicted =
        theory::push_outcome(box.block.mass * standard_gravity, box.block.width, height, box.block.pair.mu_s);
    const PushResult seen = run_pushed_box(box, settings, 10.0);
    const std::string at = "box pushed at " + format_number(height, 3) + " m: ";
    rows.push_back({at + "tips (1) or slides (0)", "", predicted.tips ? 1.0 : 0.0, seen.tipped ? 1.0 : 0.0, 0.0});
    rows.push_back({at + "push when it goes", "N", predicted.force, seen.force, 0.01 * predicted.force});
  }

  out << "FrictionLab: theory beside simulation (Box2D, " << settings.hz << " Hz, " << settings.velocity_iterations
      << " velocity iterations, friction treatment " << treatment_name(settings.treatment) << ")\n\n";
  const int failed = print_measurements(out, rows);
  const double degrees = 180.0 / M_PI;
  const Block& b = block;
  out << "\nerror = measured - theory, in the row's unit; a row passes when |error| <= tolerance.\n"
      << "\nThe situations (g = " << standard_gravity << " m/s²):\n"
      << "  spring pull    a " << b.mass << " kg block, " << b.width << " m × " << b.height << " m, mu_s " << b.pair.mu_s
      << ", mu_k " << b.pair.mu_k << ", on flat ground, pulled by a " << spring.stiffness << " N/m spring whose far end moves at "
      << spring.pull_speed << " m/s, for 10 s (the spring article)\n"
      << "  pulled block   the same block pulled at its centre by a force growing at 0.5 N/s\n"
      << "  incline        the same block released at rest on a slope of " << format_number(holding_angle * degrees, 3)
      << "° (98 % of atan mu_s) for 3 s, then of 40°\n"
      << "  slide to rest  the same block launched along the ground at " << viscous.launch_speed << " m/s\n"
      << "  pushed box     a " << box.block.mass << " kg box, " << box.block.width << " m wide and " << box.block.height
      << " m tall, mu_s " << box.block.pair.mu_s << ", pushed on its side by a force growing at " << box.push_rate
      << " N/s; it tips first when pushed higher than d/(2 mu_s) = " << format_number(tip, 3)
      << " m (the tribology article)\n"
      << "\n" << rows.size() - failed << " of " << rows.size() << " within tolerance\n";
  return failed == 0 ? 0 : 1;
}

}  // namespace frictionlab
