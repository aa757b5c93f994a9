#include "bench/lesson_problem.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {
namespace {

// What the reference run (the lesson's default setting) fixes for judging the others.
struct Reference {
  std::vector<double> tolerances;  // per row, as at the default setting
  double scale = 1.0;              // the largest |position| and |velocity| of any body, m and m/s
};

struct Watch {
  double largest = 0.0;
  bool finite = true;
  bool chatters = false;
  std::vector<b2Vec2> last_velocity;
  std::vector<int> reversals;  // consecutive world steps with a reversal, per body
};

void watch_step(const Scene& scene, Watch& watch) {
  const auto& bodies = scene.bodies();
  watch.last_velocity.resize(bodies.size(), b2Vec2(0.0f, 0.0f));
  watch.reversals.resize(bodies.size(), 0);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const b2Body* body = bodies[i].second;
    if (body->GetType() != b2_dynamicBody) continue;
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y)) {
      watch.finite = false;
      continue;
    }
    watch.largest = std::max({watch.largest, static_cast<double>(p.Length()), static_cast<double>(v.Length())});
    // A reversal counts only above a millimetre per second, so rest noise is not chatter.
    const b2Vec2 before = watch.last_velocity[i];
    const bool reversed = b2Dot(before, v) < 0.0f && before.Length() > 1e-3f && v.Length() > 1e-3f;
    watch.reversals[i] = reversed ? watch.reversals[i] + 1 : 0;
    if (watch.reversals[i] >= 8) watch.chatters = true;
    watch.last_velocity[i] = v;
  }
}

struct Run {
  std::vector<ExpectationResult> rows;
  Watch watch;
};

Run run_lesson(const std::string& path, const std::map<std::string, std::string>& overrides, const StepSettings& settings) {
  Lesson lesson(path, overrides, settings);
  Run run;
  const double end = lesson.duration();
  while (lesson.scene().time() + 0.5 * lesson.scene().frame_step() < end && !lesson.failed()) {
    lesson.step();
    watch_step(lesson.scene(), run.watch);
  }
  run.rows = lesson.expectations();
  return run;
}

Outcome judge(const Run& run, const Reference& reference) {
  Outcome outcome;
  const double infinite = std::numeric_limits<double>::infinity();
  bool wrong = run.rows.size() != reference.tolerances.size();
  bool not_a_number = !run.watch.finite;
  for (std::size_t i = 0; !wrong && i < run.rows.size(); ++i) {
    const ExpectationResult& row = run.rows[i];
    if (!row.measured_yet) {
      wrong = true;
    } else if (!row.numeric) {
      wrong = wrong || row.measured_text != row.predicted_text;
    } else if (!std::isfinite(row.measured)) {
      not_a_number = true;
    } else {
      outcome.error = std::max(outcome.error, std::abs(row.error()) / reference.tolerances[i]);
    }
  }
  if (wrong || not_a_number) outcome.error = infinite;
  if (not_a_number) {
    outcome.fails = "not a number";
  } else if (run.watch.largest > 100.0 * reference.scale) {
    outcome.fails = "blew up";
  } else if (run.watch.chatters) {
    outcome.fails = "chatters";
  }
  return outcome;
}

}  // namespace

BenchmarkProblem lesson_problem(const std::string& name, const std::map<std::string, std::string>& overrides) {
  const std::string path = resolve_lesson(name);
  const Run defaults = run_lesson(path, overrides, StepSettings{});
  auto reference = std::make_shared<Reference>();
  for (const ExpectationResult& row : defaults.rows) {
    // A word row has no tolerance; a numeric row with none is judged against a tiny one.
    reference->tolerances.push_back(row.numeric && row.tolerance > 0.0 ? row.tolerance : 1e-12);
  }
  if (reference->tolerances.empty()) throw InvalidInput(path + ": the lesson has no expectation to judge a run by");
  reference->scale = std::max(defaults.watch.largest, 1e-3);

  const Lesson about(path, overrides);
  BenchmarkProblem problem;
  problem.name = name;
  problem.label = name;
  problem.question = about.question();
  problem.unit = "× the lesson's tolerances";
  problem.simulated = about.duration();
  problem.run = [path, overrides, reference](const StepSettings& settings) {
    const Run run = run_lesson(path, overrides, settings);
    const double start = thread_cpu_seconds();
    Outcome outcome = judge(run, *reference);
    outcome.judging = thread_cpu_seconds() - start;
    return outcome;
  };
  return problem;
}

std::map<std::string, std::string> parameter_values(const Lesson& lesson) {
  std::map<std::string, std::string> values;
  for (const Parameter& parameter : lesson.parameters()) {
    if (parameter.is_choice()) {
      values[parameter.name] = parameter.shown();
    } else {
      char text[40];
      std::snprintf(text, sizeof text, "%.17g", parameter.value);
      values[parameter.name] = text;
    }
  }
  return values;
}

}  // namespace frictionlab::lessons
