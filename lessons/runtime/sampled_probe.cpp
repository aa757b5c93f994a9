// probe{ "name", samples = function(t) return list end, every = s, delay = d }: a model's
// values worked out once (a theory's lists) and read back after each step by the runtime,
// without a call into the script. Each call into Lua costs as much as a few dozen lines of it,
// and a lesson that reads six lists a step through functions spends most of its time there.
#include <cmath>
#include <memory>
#include <sstream>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {
namespace {

struct SampledList {
  int function = LUA_NOREF;  // samples: function(t) returning the list
  int slot = LUA_NOREF;      // the registry slot holding the list last returned
  lua_Integer length = 0;
  bool final = false;        // the function gave no longer list than before: held from then on
  double every = 0.0, delay = 0.0;
  std::string what;
};

std::string seconds(double t) {
  std::ostringstream text;
  text << t;
  return text.str();
}

// Asks the function for the list again, for a run that has reached `t`.
void refresh(LessonBuild& build, SampledList& list, double t) {
  lua_State* state = build.sandbox.state();
  build.call(list.function, {t}, 1);
  if (!lua_istable(state, -1) || lua_rawlen(state, -1) == 0) {
    const std::string got = describe(state, -1);
    lua_pop(state, 1);
    throw ScriptError(build.defined_at(list.function) + ": " + list.what + ": samples must return a list of numbers "
                      "(the values at t = 0, every, 2·every, ...); at t = " + seconds(t) + " s it returned " + got);
  }
  const auto length = static_cast<lua_Integer>(lua_rawlen(state, -1));
  list.final = length <= list.length;
  list.length = length;
  // Into a slot made at declaration: setting an existing key allocates nothing, so this cannot
  // fail outside a protected call.
  lua_rawseti(state, LUA_REGISTRYINDEX, list.slot);
}

double entry(LessonBuild& build, const SampledList& list, lua_Integer k) {
  lua_State* state = build.sandbox.state();
  lua_rawgeti(state, LUA_REGISTRYINDEX, list.slot);
  lua_rawgeti(state, -1, k);
  const bool number = lua_type(state, -1) == LUA_TNUMBER;
  const double value = number ? lua_tonumber(state, -1) : NAN;
  if (!number || !std::isfinite(value)) {
    const std::string got = describe(state, -1);
    lua_pop(state, 2);
    throw ScriptError(build.defined_at(list.function) + ": " + list.what + ": entry " + std::to_string(k) +
                      " of the samples is " + got + "; each must be a finite number");
  }
  lua_pop(state, 2);
  return value;
}

}  // namespace

std::function<double()> sampled_reading(LessonBuild& build, int function, double every, double delay, std::string what) {
  lua_State* state = build.sandbox.state();
  auto list = std::make_shared<SampledList>();
  list->function = function;
  lua_pushboolean(state, 0);
  list->slot = luaL_ref(state, LUA_REGISTRYINDEX);
  list->every = every;
  list->delay = delay;
  list->what = std::move(what);
  LessonBuild* owner = &build;
  return [owner, list] {
    const double now = owner->scene->time();
    // Entry k + 1 is the value at t = k·every; between two, the straight line through them.
    const double place = std::max(now - list->delay, 0.0) / list->every;
    if (!list->final && place > static_cast<double>(list->length - 1)) refresh(*owner, *list, now);
    const auto below = static_cast<lua_Integer>(std::floor(place));
    if (below + 1 >= list->length) return entry(*owner, *list, list->length);  // past the end: the last value
    const double part = place - static_cast<double>(below);
    const double first = entry(*owner, *list, below + 1);
    return part == 0.0 ? first : first + part * (entry(*owner, *list, below + 2) - first);
  };
}

}  // namespace frictionlab::lessons
