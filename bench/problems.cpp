#include "bench/problems.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include <time.h>

#include "physics/closed_forms.h"
#include "physics/scenarios.h"

namespace frictionlab {
namespace {

// Judges a run of a block on a line against its problem's exact answer: the error from its
// frames, how it failed from its world steps (every sub-step). The time this takes is booked
// as judging, to be left out of the run's cost.
Outcome judge(const LineProblem& line, const std::vector<Sample>& frames, const std::vector<Sample>& steps) {
  const double start = thread_cpu_seconds();
  RunCheck check;
  for (const Sample& s : steps) check.add(s.t, s.x, s.v);
  double worst = 0.0;
  if (line.final_only) {
    worst = std::abs(frames.back().x - line.exact_position(frames.back().t));
  } else {
    for (const Sample& s : frames) worst = std::max(worst, std::abs(s.x - line.exact_position(s.t)));
  }
  Outcome outcome{std::isfinite(worst) ? worst : INFINITY, check.failure(line.expected)};
  outcome.judging = thread_cpu_seconds() - start;
  return outcome;
}

// A Box2D scene run to the problem's end, its block read along its line (position, velocity)
// after every frame and every world step; only the recording is part of the run.
Outcome follow(Scene& scene, const LineProblem& line, const std::function<Sample()>& read) {
  std::vector<Sample> frames{read()}, steps{frames};
  const auto count = static_cast<std::size_t>(line.t_end / scene.frame_step()) + 2;
  frames.reserve(count);
  steps.reserve(count * static_cast<std::size_t>(scene.settings().substeps));
  scene.set_after_substep([&](double t) {
    steps.push_back(read());
    steps.back().t = t;
  });
  while (scene.time() < line.t_end - 0.5 * scene.frame_step()) {
    scene.step();
    frames.push_back(read());
    frames.back().t = scene.time();
  }
  scene.set_after_substep(nullptr);
  return judge(line, frames, steps);
}

// The exact motion kept alive for the problem's lambdas, solved a little past the end so the
// last frame (which rounding can put just after it) has an answer.
LineProblem exact_line(const OneDofBlock& block, double t_end) {
  const auto exact = std::make_shared<Trajectory>(solve_exact(block, t_end + 1.0));
  return {block, t_end, [exact](double t) { return exact->position(t); }, false, expected_motion(*exact, t_end)};
}

LineProblem spring_line() { return exact_line(spring_pull_model(SpringPull{}), 10.0); }

// A block released at rest on the slope: gravity along it, the normal force across it.
LineProblem incline_line(double angle) {
  const Incline setup;
  OneDofBlock block;
  block.mass = setup.block.mass;
  block.pair = setup.block.pair;
  block.normal_force = block.mass * standard_gravity * std::cos(angle);
  block.constant_force = block.mass * standard_gravity * std::sin(angle);
  return exact_line(block, 2.0);
}

// A block launched at 3 m/s on flat ground, judged by where it comes to rest (closed forms
// with c or with b: the event solver's closed forms take no b).
LineProblem slide_line(const FrictionPair& pair) {
  const Slide setup;
  OneDofBlock block;
  block.mass = setup.block.mass;
  block.pair = pair;
  block.normal_force = block.mass * standard_gravity;
  block.v0 = setup.launch_speed;
  const theory::SlideToRest rest = theory::slide_to_rest(setup.launch_speed, block.mass, pair, standard_gravity);
  const double distance = rest.distance;
  return {block, 2.0, [distance](double) { return distance; }, true, {{rest.time}, true, std::max(distance, block.v0)}};
}

// A scene whose block moves along x: its distance from where it started, and its velocity.
Outcome follow_along_x(Scene& scene, const LineProblem& line) {
  const b2Body* block = scene.body("block");
  const double start = block->GetPosition().x;
  return follow(scene, line, [&] { return Sample{0.0, block->GetPosition().x - start, block->GetLinearVelocity().x}; });
}

Outcome spring_run(const LineProblem& line, const StepSettings& settings) {
  return follow_along_x(*make_spring_pull(SpringPull{}, settings), line);
}

Outcome slide_run(const LineProblem& line, const StepSettings& settings) {
  Slide setup;
  setup.block.pair = line.block.pair;
  return follow_along_x(*make_slide(setup, settings), line);
}

// The incline's own probes read the block down the slope; asked at every world step here.
Outcome incline_run(const LineProblem& line, double angle, const StepSettings& settings) {
  Incline setup;
  setup.angle = angle;
  auto scene = make_incline(setup, settings);
  const Probe& distance = scene->probe("distance");
  const Probe& speed = scene->probe("speed");
  return follow(*scene, line, [&] { return Sample{0.0, distance.measure(), speed.measure()}; });
}

// The two slopes a degree either side of the sticking angle of the scenarios' pair.
double sticking_angle() { return theory::sticking_angle(Incline{}.block.pair.mu_s); }
double above_angle() { return std::round(sticking_angle() * 180.0 / M_PI + 1.0) * M_PI / 180.0; }
double below_angle() { return std::round(sticking_angle() * 180.0 / M_PI - 1.0) * M_PI / 180.0; }

BenchmarkProblem line_problem(std::string name, std::string label, std::string question, LineProblem line,
                              std::function<Outcome(const LineProblem&, const StepSettings&)> run) {
  BenchmarkProblem problem{std::move(name), std::move(label), std::move(question), "m", line.t_end, {}, line};
  problem.run = [line = std::move(line), run = std::move(run)](const StepSettings& settings) { return run(line, settings); };
  return problem;
}

// A block released on a slope of `angle`, in Box2D and in the reduced models.
BenchmarkProblem incline_problem(std::string name, std::string label, std::string question, double angle) {
  return line_problem(std::move(name), std::move(label), std::move(question), incline_line(angle),
                      [angle](const LineProblem& line, const StepSettings& settings) { return incline_run(line, angle, settings); });
}

// A wrong answer (infinite error) is the only failure the other problems can show.
std::function<Outcome(const StepSettings&)> answered(std::function<double(const StepSettings&)> error) {
  return [error = std::move(error)](const StepSettings& settings) {
    const double e = error(settings);
    return Outcome{std::isnan(e) ? INFINITY : e, std::isfinite(e) ? "" : "wrong answer"};
  };
}

std::string degrees(double angle) {
  std::ostringstream text;
  text << std::lround(angle * 180.0 / M_PI) << "\u00b0";
  return text.str();
}

// The tipping box pushed low, at 0.3 m (below d/(2·mu_s) = 0.5 m), must slide when the push
// reaches mu_s·m·g = 49.05 N; pushed high, at 0.7 m, it must tip at m·g·d/(2·h) = 35.0 N. The
// larger error of the two, so that a treatment without mu_s (box2d slides at mu_k·m·g) does
// not pass on tipping alone; the wrong outcome at either height is a wrong answer.
double tipping_error(const StepSettings& settings) {
  double worst = 0.0;
  for (const double height : {0.3, 0.7}) {
    PushedBox setup;
    setup.push_height = height;
    const double mg = setup.block.mass * standard_gravity;
    const bool tips = height > theory::tip_height(setup.block.width, setup.block.pair.mu_s);
    const double expected = tips ? mg * setup.block.width / (2.0 * height) : setup.block.pair.mu_s * mg;
    const PushResult result = run_pushed_box(setup, settings, expected / setup.push_rate + 1.0);
    if (result.tipped != tips) return INFINITY;
    worst = std::max(worst, std::abs(result.force - expected));
  }
  return worst;
}

// The push height where the box stops sliding and starts to tip, found by bisection (12
// halvings of 0.2–0.9 m), against d/(2·mu_s) = 0.5 m.
double tipping_threshold_error(const StepSettings& settings, double* simulated) {
  PushedBox setup;
  const double mg = setup.block.mass * standard_gravity;
  double low = 0.2, high = 0.9;  // slides at low, tips at high
  bool tipped_once = false, slid_once = false;
  for (int i = 0; i < 12; ++i) {
    setup.push_height = 0.5 * (low + high);
    const double first = std::min(setup.block.pair.mu_s * mg, mg * setup.block.width / (2.0 * setup.push_height));
    const PushResult result = run_pushed_box(setup, settings, first / setup.push_rate + 1.0);
    const bool tipped = result.tipped;
    *simulated += result.force / setup.push_rate;  // each run stops once its outcome is decided
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
  std::vector<BenchmarkProblem> problems{spring_problem(), incline_slides_problem()};
  const double below = below_angle();
  problems.push_back(incline_problem("Incline " + degrees(below) + ": just below, it sticks", degrees(below) + " sticks",
                                     "a block released on a " + degrees(below) + " slope, a degree below its sticking angle: the largest "
                                     "distance it moved in 2 s (exact: it never moves)",
                                     below));
  problems.push_back(line_problem("Slide to rest with c", "slide, c",
                                  "slide to rest from 3 m/s with c = 2 N\u00b7s/m: where it stops, against the closed form",
                                  slide_line({0.6, 0.4, 2.0, 0.0}), slide_run));
  problems.push_back(line_problem("Slide to rest with b", "slide, b",
                                  "slide to rest from 3 m/s with b = 1 N\u00b7s\u00b2/m\u00b2: where it stops, against the closed form",
                                  slide_line({0.6, 0.4, 0.0, 1.0}), slide_run));
  problems.push_back(tipping_push_problem());
  problems.push_back({"Tipping threshold, by bisection", "tip height", "the push height where a box stops sliding and tips, by bisection, against d/(2\u00b7\u03bcs) = 0.5 m",
                      "m", 20.0,
                      [](const StepSettings& settings) {
                        double simulated = 0.0;
                        Outcome outcome = answered([&](const StepSettings& s) { return tipping_threshold_error(s, &simulated); })(settings);
                        outcome.simulated = simulated;
                        return outcome;
                      },
                      std::nullopt});
  problems.push_back({"Disk starts to roll", "disk rolls", "a disk launched sliding at 2 m/s: when it starts to roll, against v0/(3\u00b7\u03bck\u00b7g)", "s", 1.0,
                      answered(disk_rolling_error), std::nullopt});
  return problems;
}

BenchmarkProblem spring_problem() {
  return line_problem("Spring stick-slip", "spring",
                      "the spring-pulled block's largest position error over 10 s, against the exact stick-slip solution",
                      spring_line(), spring_run);
}

BenchmarkProblem incline_slides_problem() {
  const double above = above_angle();
  return incline_problem("Incline " + degrees(above) + ": just above, it slides", degrees(above) + " slides",
                         "the distance slid down a " + degrees(above) + " slope, a degree above its sticking angle: the largest "
                         "error over 2 s against \u00bd\u00b7a\u00b7t\u00b2",
                         above);
}

BenchmarkProblem tipping_push_problem() {
  return {"Tipping push", "tip push",
          "the push at which the box slides, pushed at 0.3 m (\u03bcs\u00b7m\u00b7g = 49.05 N), and tips, pushed at 0.7 m "
          "(m\u00b7g\u00b7d/(2\u00b7h) = 35.0 N): the larger error",
          "N", 6.2, answered(tipping_error), std::nullopt};
}

BenchmarkProblem incline_sticks_problem(double angle) {
  return incline_problem("Incline " + degrees(angle) + ": it sticks", degrees(angle) + " sticks",
                         "a block released on a " + degrees(angle) + " slope, below its sticking angle: the largest distance it "
                         "moved in 2 s (exact: it never moves)",
                         angle);
}

std::string reduced_method_name(ReducedMethod method) {
  switch (method) {
    case ReducedMethod::explicit_euler: return "1-DOF explicit Euler (regularized)";
    case ReducedMethod::semi_implicit_euler: return "1-DOF semi-implicit Euler (regularized)";
    case ReducedMethod::rk4: return "1-DOF RK4 (regularized)";
    case ReducedMethod::located_events: return "1-DOF RK4 (located events)";
  }
  return "";
}

Outcome run_reduced(const LineProblem& line, ReducedMethod method, double hz, double epsilon) {
  if (method == ReducedMethod::located_events) {
    const Trajectory located = solve_event_rk4(line.block, line.t_end, 1.0 / hz);
    // Its state is known between events: read every millisecond, as part of the judging.
    const double start = thread_cpu_seconds();
    std::vector<Sample> samples;
    const int count = static_cast<int>(std::lround(line.t_end * 1000.0));
    for (int i = 0; i <= count; ++i) {
      const double t = std::min(line.t_end, i * 1e-3);
      const BlockState state = located.state(t);
      samples.push_back({t, state.x, state.v});
    }
    const double reading = thread_cpu_seconds() - start;
    Outcome outcome = judge(line, samples, samples);
    outcome.judging += reading;
    return outcome;
  }
  const Integrator integrator = method == ReducedMethod::explicit_euler        ? Integrator::explicit_euler
                                : method == ReducedMethod::semi_implicit_euler ? Integrator::semi_implicit_euler
                                                                               : Integrator::rk4;
  const std::vector<Sample> samples = integrate_regularized(line.block, line.t_end, 1.0 / hz, epsilon, integrator);
  return judge(line, samples, samples);
}

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace frictionlab
