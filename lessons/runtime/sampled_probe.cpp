// probe{ "name", samples = function(t) return list end, every = s, delay = d }: a model's
// values worked out once (a theory's lists) and read back after each step by the runtime,
// without a call into the script. Each call into Lua costs as much as a few dozen lines of it,
// and a lesson that reads six lists a step through functions spends most of its time there.
#include <cmath>
#include <memory>
#include <vector>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {
namespace {

struct SampledList {
  int function = LUA_NOREF;  // samples: function(t) returning the list
  // The list last returned, copied out of Lua: a probe reads two entries a step, and reading
  // them from a C++ array instead of the script's table costs a tenth as much (wedge reads six).
  std::vector<double> values;
  bool final = false;        // the function gave no longer list than before: held from then on
  double every = 0.0, delay = 0.0;
  std::string what;
};

// Asks the function for the list again, for a run that has reached `t`, and copies it out,
// each entry checked once here rather than at every read.
void refresh(LessonBuild& build, SampledList& list, double t) {
  lua_State* state = build.sandbox.state();
  build.call(list.function, {t}, 1);
  if (!lua_istable(state, -1) || lua_rawlen(state, -1) == 0) {
    const std::string got = describe(state, -1);
    lua_pop(state, 1);
    throw ScriptError(build.defined_at(list.function) + ": " + list.what + ": samples must return a list of numbers "
                      "(the values at t = 0, every, 2·every, ...); at t = " + number_text(t) + " s it returned " + got);
  }
  const auto length = static_cast<lua_Integer>(lua_rawlen(state, -1));
  list.final = length <= static_cast<lua_Integer>(list.values.size());
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(length));
  for (lua_Integer k = 1; k <= length; ++k) {
    lua_rawgeti(state, -1, k);
    const bool number = lua_type(state, -1) == LUA_TNUMBER;
    const double value = number ? lua_tonumber(state, -1) : NAN;
    if (!number || !std::isfinite(value)) {
      const std::string got = describe(state, -1);
      lua_pop(state, 2);
      throw ScriptError(build.defined_at(list.function) + ": " + list.what + ": entry " + std::to_string(k) +
                        " of the samples is " + got + "; each must be a finite number");
    }
    values.push_back(value);
    lua_pop(state, 1);
  }
  lua_pop(state, 1);
  list.values = std::move(values);
}

}  // namespace

std::function<double()> sampled_reading(LessonBuild& build, int function, double every, double delay, std::string what) {
  auto list = std::make_shared<SampledList>();
  list->function = function;
  list->every = every;
  list->delay = delay;
  list->what = std::move(what);
  LessonBuild* owner = &build;
  return [owner, list] {
    const double now = owner->scene->time();
    // Entry k is the value at t = k·every (from 0); between two, the straight line through them.
    const double place = std::max(now - list->delay, 0.0) / list->every;
    const std::vector<double>& values = list->values;
    if (!list->final && place > static_cast<double>(values.size()) - 1.0) refresh(*owner, *list, now);
    const auto below = static_cast<std::size_t>(std::floor(place));
    if (below + 1 >= values.size()) return values.back();  // past the end: the last value
    const double part = place - static_cast<double>(below);
    return part == 0.0 ? values[below] : values[below] + part * (values[below + 1] - values[below]);
  };
}

}  // namespace frictionlab::lessons
