// Plots' theory curves: the script's functions of x sampled across a plot's x range, with the
// ends of each branch and each jump found by bisection so that a branch stops where it stops
// and a jump is drawn as a jump. Samples are kept until the range or a parameter changes: a
// plot is drawn every frame, and the law it shows does not change with the frame.
#include <algorithm>
#include <cmath>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {
namespace {

// What a curve gave at one x: nothing (nil), a value, or a vertical segment low..high.
struct Sample {
  double x = 0.0;
  int count = 0;
  double y[2] = {0.0, 0.0};
};

struct SamplingJob {
  std::size_t plot = 0;
  double low = 0.0, high = 1.0;
  int count = 2;
  TheorySamples* out = nullptr;
};

// Raises a script error with `message` from inside a function the sandbox called: it ends the
// call with that message, as the script's own error() would.
int raise_script_error(lua_State* state, const std::string& message) {
  lua_pushstring(state, message.c_str());
  return lua_error(state);
}

Sample evaluate(lua_State* state, LessonBuild& build, std::size_t plot, std::size_t curve, double x) {
  const int reference = build.plot_functions[plot].curves[curve];
  lua_rawgeti(state, LUA_REGISTRYINDEX, reference);
  lua_pushnumber(state, x);
  lua_call(state, 1, 2);
  Sample sample;
  sample.x = x;
  std::string problem;
  if (lua_isnil(state, -2)) {
    sample.count = 0;
  } else if (lua_type(state, -2) == LUA_TNUMBER && (lua_isnil(state, -1) || lua_type(state, -1) == LUA_TNUMBER)) {
    sample.count = lua_isnil(state, -1) ? 1 : 2;
    sample.y[0] = lua_tonumber(state, -2);
    sample.y[1] = sample.count == 2 ? lua_tonumber(state, -1) : sample.y[0];
    if (!std::isfinite(sample.y[0]) || !std::isfinite(sample.y[1])) problem = "a number that is not finite";
  } else {
    problem = describe(state, lua_type(state, -2) == LUA_TNUMBER ? -1 : -2);
  }
  lua_pop(state, 2);
  if (!problem.empty()) {
    const Plot& declared = build.plots[plot];
    const std::string message = declared.theory[curve].declared_at + ": plot '" + declared.title + "': theory curve '" +
                                declared.theory[curve].label + "' gave " + problem + " at " +
                                (declared.kind == PlotKind::time ? "t" : declared.x) + " = " + number_text(x) +
                                "; it must give y (a number), two numbers (a vertical segment) or nil where it does not apply";
    raise_script_error(state, message);
  }
  return sample;
}

// Bisects between a and b (a.x < b.x), which differ (one is nil, or they jump apart), down to
// a hair's width; returns the two samples either side of where they change.
std::pair<Sample, Sample> narrow(lua_State* state, LessonBuild& build, std::size_t plot, std::size_t curve, Sample a,
                                 Sample b, double hair) {
  const auto gap = [](const Sample& left, const Sample& right) {
    if (left.count == 0 || right.count == 0) return left.count == right.count ? 0.0 : INFINITY;
    return std::abs(left.y[left.count - 1] - right.y[0]);
  };
  for (int i = 0; i < 60 && b.x - a.x > hair; ++i) {
    const Sample middle = evaluate(state, build, plot, curve, 0.5 * (a.x + b.x));
    if (gap(a, middle) >= gap(middle, b)) {
      b = middle;
    } else {
      a = middle;
    }
  }
  return {a, b};
}

void add_point(std::vector<TheoryPoint>& piece, const Sample& sample) {
  if (sample.count == 0) return;
  if (sample.count == 2) {
    // A vertical segment: from whichever end is nearer the line arriving, to the other.
    const bool upward = piece.empty() || std::abs(piece.back().y - sample.y[0]) <= std::abs(piece.back().y - sample.y[1]);
    piece.push_back({sample.x, upward ? sample.y[0] : sample.y[1]});
    piece.push_back({sample.x, upward ? sample.y[1] : sample.y[0]});
  } else {
    piece.push_back({sample.x, sample.y[0]});
  }
}

void sample_curve(lua_State* state, LessonBuild& build, const SamplingJob& job, std::size_t curve,
                  std::vector<std::vector<TheoryPoint>>& pieces) {
  std::vector<double> xs;
  for (int i = 0; i < job.count; ++i) xs.push_back(job.low + (job.high - job.low) * i / (job.count - 1));
  // x = 0 itself, where laws of velocity have their vertical segment.
  if (job.low < 0.0 && job.high > 0.0) xs.insert(std::upper_bound(xs.begin(), xs.end(), 0.0), 0.0);
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<Sample> samples;
  samples.reserve(xs.size());
  double y_low = INFINITY, y_high = -INFINITY;
  for (const double x : xs) {
    samples.push_back(evaluate(state, build, job.plot, curve, x));
    for (int k = 0; k < samples.back().count; ++k) {
      y_low = std::min(y_low, samples.back().y[k]);
      y_high = std::max(y_high, samples.back().y[k]);
    }
  }
  // A step bigger than a fiftieth of the curve's height between neighbours is looked into: a
  // smooth curve sampled this finely never steps that far.
  const double jump = y_high > y_low ? 0.02 * (y_high - y_low) : INFINITY;
  const double hair = 1e-9 * (job.high - job.low);
  std::vector<TheoryPoint> piece;
  const auto end_piece = [&] {
    if (!piece.empty()) pieces.push_back(std::move(piece));
    piece.clear();
  };
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Sample& here = samples[i];
    if (i > 0) {
      const Sample& before = samples[i - 1];
      if (before.count > 0 && here.count == 0) {
        const auto [last, after] = narrow(state, build, job.plot, curve, before, here, hair);
        if (last.x > before.x) add_point(piece, last);
        end_piece();
      } else if (before.count == 0 && here.count > 0) {
        const auto [after, first] = narrow(state, build, job.plot, curve, before, here, hair);
        if (first.x < here.x) add_point(piece, first);
      } else if (before.count > 0 && here.count > 0 && std::abs(before.y[before.count - 1] - here.y[0]) > jump) {
        const auto [left, right] = narrow(state, build, job.plot, curve, before, here, hair);
        if (left.x > before.x) add_point(piece, left);
        if (left.count == 0 || right.count == 0) end_piece();  // a gap between the two
        if (right.x < here.x) add_point(piece, right);
      }
    }
    if (here.count > 0) add_point(piece, here);
  }
  end_piece();
}

int sample_plot(lua_State* state) {
  const auto* job = static_cast<const SamplingJob*>(lua_touserdata(state, 1));
  LessonBuild& build = build_of(state);
  job->out->curves.assign(build.plot_functions[job->plot].curves.size(), {});
  for (std::size_t curve = 0; curve < job->out->curves.size(); ++curve) {
    sample_curve(state, build, *job, curve, job->out->curves[curve]);
  }
  return 0;
}

// Calls each of a plot's functions kept in the registry (those set: not LUA_NOREF) with no
// argument, and hands its one result, on the stack's top, to `take` with the function's place
// in the list; `take` raises the script's error for a result that is no answer.
template <typename Take>
void call_each(lua_State* state, const std::vector<int>& functions, Take take) {
  for (std::size_t place = 0; place < functions.size(); ++place) {
    if (functions[place] == LUA_NOREF) continue;
    lua_rawgeti(state, LUA_REGISTRYINDEX, functions[place]);
    lua_call(state, 0, 1);
    take(place);
    lua_pop(state, 1);
  }
}

struct ActiveJob {
  std::size_t plot = 0;
  std::vector<int>* out = nullptr;
};

int ask_active(lua_State* state) {
  const auto* job = static_cast<const ActiveJob*>(lua_touserdata(state, 1));
  LessonBuild& build = build_of(state);
  call_each(state, build.plot_functions[job->plot].active, [&](std::size_t curve) {
    if (!lua_isboolean(state, -1)) {
      const Plot& declared = build.plots[job->plot];
      raise_script_error(state, declared.theory[curve].declared_at + ": plot '" + declared.title + "': theory curve '" +
                                    declared.theory[curve].label + "': active gave " + describe(state, -1) +
                                    "; it must give true (the branch applies now) or false");
    }
    (*job->out)[curve] = lua_toboolean(state, -1) ? 1 : 0;
  });
  return 0;
}

struct LevelsJob {
  std::size_t plot = 0;
  std::vector<double>* out = nullptr;
};

int evaluate_levels(lua_State* state) {
  const auto* job = static_cast<const LevelsJob*>(lua_touserdata(state, 1));
  LessonBuild& build = build_of(state);
  const PlotFunctions& functions = build.plot_functions[job->plot];
  job->out->assign(functions.levels.size(), NAN);
  call_each(state, functions.levels, [&](std::size_t level) {
    const bool number = lua_type(state, -1) == LUA_TNUMBER && std::isfinite(lua_tonumber(state, -1));
    if (!number && !lua_isnil(state, -1)) {
      const Plot& declared = build.plots[job->plot];
      raise_script_error(state, declared.levels[level].declared_at + ": plot '" + declared.title + "': level '" +
                                    declared.levels[level].label + "' gave " +
                                    (lua_type(state, -1) == LUA_TNUMBER ? "a number that is not finite" : describe(state, -1)) +
                                    "; it must give y (a number) or nil when there is no such level now");
    }
    if (number) (*job->out)[level] = lua_tonumber(state, -1);
  });
  return 0;
}

// Runs `function` in the sandbox with `job` as its one argument, in one budget. With `error`, a
// script error it raises is kept there (Lesson::theory_error says it) before it is thrown on,
// and a run without one clears it.
void run_job(LessonBuild& build, lua_CFunction function, void* job, std::string* error = nullptr) {
  lua_State* state = build.sandbox.state();
  lua_pushcfunction(state, function);
  lua_pushlightuserdata(state, job);
  try {
    build.sandbox.call(1, 0);
  } catch (const ScriptError& raised) {
    if (error != nullptr) *error = raised.what();
    throw;
  }
  if (error != nullptr) error->clear();
}

}  // namespace

std::vector<double> Lesson::plot_levels(std::size_t plot) {
  LessonBuild& build = *current_;
  PlotFunctions& functions = build.plot_functions.at(plot);
  std::vector<double> levels;
  if (functions.levels.empty()) return levels;
  LevelsJob job{plot, &levels};
  run_job(build, evaluate_levels, &job, &functions.levels_error);
  return levels;
}

void try_theory_curves(LessonBuild& build) {
  for (std::size_t plot = 0; plot < build.plots.size(); ++plot) {
    if (!build.plot_functions[plot].levels.empty()) {
      // The levels too, so that a level that fails fails when the lesson loads.
      std::vector<double> levels;
      LevelsJob reading{plot, &levels};
      run_job(build, evaluate_levels, &reading);
    }
    if (build.plot_functions[plot].curves.empty()) continue;
    TheorySamples samples;
    SamplingJob job{plot, 0.0, 1.0, 3, &samples};
    run_job(build, sample_plot, &job);
    std::vector<int> active(build.plot_functions[plot].curves.size(), -1);
    ActiveJob asking{plot, &active};
    run_job(build, ask_active, &asking);
  }
}

std::string Lesson::theory_error() const {
  for (const PlotFunctions& functions : current_->plot_functions) {
    if (!functions.samples_error.empty()) return functions.samples_error;
    if (!functions.active_error.empty()) return functions.active_error;
    if (!functions.levels_error.empty()) return functions.levels_error;
  }
  return "";
}

const TheorySamples& Lesson::theory_samples(std::size_t plot, double x_low, double x_high, int count) {
  LessonBuild& build = *current_;
  PlotFunctions& functions = build.plot_functions.at(plot);
  std::vector<double> parameters;
  for (const Parameter& parameter : build.parameters) parameters.push_back(parameter.value);
  count = std::max(count, 2);
  if (!(x_high > x_low)) x_high = x_low + 1.0;
  if (functions.samples.x_low == x_low && functions.samples.x_high == x_high && functions.sample_count == count &&
      functions.sampled_with == parameters) {
    functions.samples_error.clear();  // the samples kept are those of the values now, which drew
    return functions.samples;
  }
  TheorySamples fresh;
  fresh.x_low = x_low;
  fresh.x_high = x_high;
  if (!functions.curves.empty()) {
    SamplingJob job{plot, x_low, x_high, count, &fresh};
    run_job(build, sample_plot, &job, &functions.samples_error);  // one budget for the whole plot
  }
  functions.samples_error.clear();
  functions.samples = std::move(fresh);
  functions.sample_count = count;
  functions.sampled_with = std::move(parameters);
  return functions.samples;
}

std::vector<int> Lesson::theory_active(std::size_t plot) {
  LessonBuild& build = *current_;
  const PlotFunctions& functions = build.plot_functions.at(plot);
  std::vector<int> active(functions.curves.size(), -1);
  if (std::none_of(functions.active.begin(), functions.active.end(), [](int f) { return f != LUA_NOREF; })) return active;
  ActiveJob job{plot, &active};
  run_job(build, ask_active, &job, &build.plot_functions.at(plot).active_error);
  return active;
}

}  // namespace frictionlab::lessons
