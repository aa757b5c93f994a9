#include "physics/recommend.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#include <time.h>
#include <sstream>

#include "physics/closed_forms.h"
#include "physics/scenarios.h"

namespace frictionlab {
namespace {

// A block released on a 40° slope (above atan 0.6 = 31°, so it slides): the distance it has
// gone against ½·g·(sin θ − μk·cos θ)·t², at every step of 2 s.
double incline_error(const StepSettings& settings) {
  Incline setup;
  setup.angle = 40.0 * M_PI / 180.0;
  auto scene = make_incline(setup, settings);
  const double a = theory::incline_sliding_acceleration(setup.angle, setup.block.pair.mu_k, standard_gravity);
  double worst = 0.0;
  while (scene->time() < 2.0 - 0.5 * scene->frame_step()) {
    scene->step();
    const double exact = 0.5 * a * scene->time() * scene->time();
    worst = std::max(worst, std::abs(scene->probe("distance").history.back() - exact));
  }
  return worst;
}

// The tipping box pushed at 0.7 m (above d/(2·μs) = 0.5 m): it must tip, at the push
// m·g·d/(2·h); a box that slides instead has the answer wrong altogether.
double tipping_error(const StepSettings& settings) {
  PushedBox setup;
  setup.push_height = 0.7;
  const double mg = setup.block.mass * standard_gravity;
  const double tipping_push = mg * setup.block.width / (2.0 * setup.push_height);
  const PushResult result = run_pushed_box(setup, settings, tipping_push / setup.push_rate + 1.0);
  return result.tipped ? std::abs(result.force - tipping_push) : INFINITY;
}

// On a 25° slope (tan 25° = 0.47 < mu_s = 0.6) Coulomb's block never moves: the error is how
// far it went anyway, the largest over 2 s.
double incline_below_error(const StepSettings& settings) {
  Incline setup;
  setup.angle = 25.0 * M_PI / 180.0;
  auto scene = make_incline(setup, settings);
  double worst = 0.0;
  while (scene->time() < 2.0 - 0.5 * scene->frame_step()) {
    scene->step();
    worst = std::max(worst, std::abs(scene->probe("distance").history.back()));
  }
  return worst;
}

// A block launched at 3 m/s slides to rest; the distance against the closed form with drag.
double slide_error(const StepSettings& settings, const FrictionPair& pair) {
  Slide setup;
  setup.block.pair = pair;
  const Measurement slid = measure_slide_distance(setup, settings);
  return std::abs(slid.error());
}

// The push height where the box stops sliding and starts to tip, found by bisection (12
// halvings of 0.2–0.9 m), against d/(2·mu_s) = 0.5 m.
double tipping_threshold_error(const StepSettings& settings) {
  PushedBox setup;
  const double mg = setup.block.mass * standard_gravity;
  double low = 0.2, high = 0.9;  // slides at low, tips at high
  bool tipped_once = false, slid_once = false;
  for (int i = 0; i < 12; ++i) {
    setup.push_height = 0.5 * (low + high);
    const double first = std::min(setup.block.pair.mu_s * mg, mg * setup.block.width / (2.0 * setup.push_height));
    const bool tipped = run_pushed_box(setup, settings, first / setup.push_rate + 1.0).tipped;
    (tipped ? high : low) = setup.push_height;
    (tipped ? tipped_once : slid_once) = true;
  }
  // Never one outcome or the other: no threshold inside the range, the answer is wrong.
  if (!tipped_once || !slid_once) return INFINITY;
  return std::abs(0.5 * (low + high) - theory::tip_height(setup.block.width, setup.block.pair.mu_s));
}

// A disk (1 kg, radius 0.1 m) launched sliding at 2 m/s with no spin: kinetic friction slows it
// and spins it up until v = omega·r, at v0/(3·mu_k·g) for a uniform disk.
double disk_rolling_error(const StepSettings& settings) {
  const double radius = 0.1, v0 = 2.0;
  Block material{1.0, M_PI * radius * radius, 1.0, {0.6, 0.4, 0.0, 0.0}};  // density for 1 kg
  Scene scene(block_on_ground(material), settings);
  scene.add_box("ground", b2_staticBody, "ground", {0.0f, -0.5f}, 400.0f, 1.0f);
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  definition.position = {0.0f, static_cast<float>(radius) + b2_polygonRadius};
  b2Body* disk = scene.add_body("disk", definition);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(radius);
  scene.add_fixture(disk, circle, "block");
  disk->SetLinearVelocity({static_cast<float>(v0), 0.0f});
  const theory::RollStart exact = theory::disk_starts_rolling(v0, disk->GetMass(), radius, disk->GetInertia(), 0.4,
                                                              standard_gravity);
  // Rolling to +x turns clockwise: the contact slides at v + omega·r, which friction drives
  // to zero. It starts to roll where that crosses zero, placed between the two steps around it.
  double slip_before = v0;
  while (scene.time() < 2.0 * exact.time + 0.5) {
    scene.step();
    const double slip = disk->GetLinearVelocity().x + disk->GetAngularVelocity() * radius;
    if (slip <= 1e-6 * v0) {
      const double fraction = slip_before / (slip_before - slip);
      return std::abs(scene.time() - (1.0 - fraction) * scene.frame_step() - exact.time);
    }
    slip_before = slip;
  }
  return INFINITY;  // never rolled: the answer is wrong altogether
}

}  // namespace

std::vector<BenchmarkProblem> benchmark_problems() {
  std::vector<BenchmarkProblem> problems{lesson_problem("spring_pull"), lesson_problem("incline")};
  problems.push_back({"Incline 25\u00b0: it sticks", "", "a block on a 25\u00b0 slope, below its sticking angle: the largest distance it moved in 2 s (exact: 0)",
                      "m", 2.0, incline_below_error});
  problems.push_back({"Slide to rest with c", "", "slide to rest from 3 m/s with c = 2 N\u00b7s/m: the distance against the closed form", "m", 1.5,
                      [](const StepSettings& settings) { return slide_error(settings, {0.6, 0.4, 2.0, 0.0}); }});
  problems.push_back({"Slide to rest with b", "", "slide to rest from 3 m/s with b = 1 N\u00b7s\u00b2/m\u00b2: the distance against the closed form", "m",
                      1.5, [](const StepSettings& settings) { return slide_error(settings, {0.6, 0.4, 0.0, 1.0}); }});
  problems.push_back(lesson_problem("tipping_box"));
  problems.push_back({"Tipping threshold, by bisection", "", "the push height where a box stops sliding and tips, by bisection, against d/(2\u00b7\u03bcs) = 0.5 m",
                      "m", 40.0, tipping_threshold_error});
  problems.push_back({"Disk starts to roll", "", "a disk launched sliding at 2 m/s: when it starts to roll, against v0/(3\u00b7\u03bck\u00b7g)", "s", 1.0,
                      disk_rolling_error});
  return problems;
}

BenchmarkProblem lesson_problem(const std::string& lesson) {
  if (lesson == "spring_pull") {
    return {"Spring stick-slip", lesson, "the spring-pulled block's largest position error over 10 s, against the exact stick-slip solution",
            "m", 10.0, [](const StepSettings& settings) { return spring_pull_max_error(SpringPull{}, settings, 10.0); }};
  }
  if (lesson == "incline") {
    return {"Incline 40\u00b0: it slides", lesson, "the distance slid down a 40\u00b0 slope, largest error over 2 s against \u00bd\u00b7a\u00b7t\u00b2", "m", 2.0,
            incline_error};
  }
  if (lesson == "tipping_box") {
    return {"Tipping push", lesson, "the push at which the box pushed at 0.7 m tips, against m\u00b7g\u00b7d/(2\u00b7h) = 35.0 N", "N", 2.75,
            tipping_error};
  }
  throw InvalidInput("no benchmark problem for '" + lesson + "'; there is one for spring_pull, incline and tipping_box");
}

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

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

Trial measure_setting(const BenchmarkProblem& problem, const StepSettings& settings, int repeats, double tolerance) {
  Trial trial;
  trial.settings = settings;
  std::vector<double> costs;
  // The error is the same each time (the step is fixed); the cost is the median of the repeats.
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const double start = thread_cpu_seconds();
    trial.error = problem.error(settings);
    costs.push_back((thread_cpu_seconds() - start) / problem.simulated);
  }
  std::sort(costs.begin(), costs.end());
  trial.cost = costs[costs.size() / 2];
  trial.meets = trial.error <= tolerance;
  return trial;
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
