// Reading a described theory function's arguments and handing back its answer (see
// theory_binding.h), written once for every theory.* function that a description covers.

#include "lessons/runtime/theory_binding.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "physics/scenarios.h"

namespace frictionlab::lessons {

TheoryArgument needed(const char* key, const char* unit) { return {.key = key, .unit = unit}; }

TheoryArgument needed_in(const char* key, const char* unit, double low, double high, bool low_open) {
  return {.key = key, .unit = unit, .range = TheoryArgument::Range{low, high, low_open}};
}

TheoryArgument defaulted(const char* key, const char* unit, double fallback) {
  return {.key = key, .unit = unit, .missing = TheoryArgument::Missing::constant, .fallback = fallback};
}

TheoryArgument defaulted_in(const char* key, const char* unit, double fallback, double low, double high) {
  TheoryArgument argument = defaulted(key, unit, fallback);
  argument.range = TheoryArgument::Range{low, high, false};
  return argument;
}

TheoryArgument same_as(const char* key, const char* unit, const char* other) {
  return {.key = key, .unit = unit, .missing = TheoryArgument::Missing::same_as, .same_as = other};
}

TheoryArgument computed(const char* key, const char* unit, double (*of)(TheoryValues&)) {
  return {.key = key, .unit = unit, .missing = TheoryArgument::Missing::computed, .computed = of};
}

TheoryArgument slope_angle() {
  TheoryArgument angle = needed_in("angle", "°", 0.0, 90.0);
  angle.in_degrees = true;
  return angle;
}

TheoryArgument gravity() { return defaulted("g", "m/s²", standard_gravity); }

TheoryValues::TheoryValues(Fields& fields, const std::vector<TheoryArgument>& arguments)
    : fields_(fields), arguments_(arguments), values_(arguments.size()) {}

double TheoryValues::operator[](const char* key) {
  for (std::size_t i = 0; i < arguments_.size(); ++i) {
    if (std::strcmp(arguments_[i].key, key) != 0) continue;
    if (!values_[i]) values_[i] = read(arguments_[i]);
    return *values_[i];
  }
  throw std::logic_error(fields_.what() + ": the description has no argument '" + key + "'");
}

double TheoryValues::read(const TheoryArgument& argument) {
  using Missing = TheoryArgument::Missing;
  double value = 0.0;
  if (argument.missing == Missing::required) {
    value = argument.range ? fields_.number_in(argument.key, argument.unit, argument.range->low, argument.range->high,
                                               argument.range->low_open)
                           : fields_.number(argument.key, argument.unit);
  } else {
    // The default first, as the hand-written reads did: an argument it depends on is read
    // (and refused, if it is bad) before this one.
    const double fallback = argument.missing == Missing::constant  ? argument.fallback
                            : argument.missing == Missing::same_as ? (*this)[argument.same_as]
                                                                   : argument.computed(*this);
    value = argument.range ? fields_.number_in(argument.key, argument.unit, fallback, argument.range->low,
                                               argument.range->high, argument.range->low_open)
                           : fields_.number(argument.key, argument.unit, fallback);
  }
  return argument.in_degrees ? value * degrees : value;
}

TheoryFunction described(const char* name, std::vector<TheoryArgument> arguments, TheoryAnswer (*answer)(TheoryValues&)) {
  return {.name = name, .arguments = std::move(arguments), .answer = answer};
}

TheoryFunction written_out(const char* name, lua_CFunction function) { return {.name = name, .written = function}; }

void set_number(lua_State* state, const char* key, double value) {
  lua_pushnumber(state, value);
  lua_setfield(state, -2, key);
}

void set_flag(lua_State* state, const char* key, bool value) {
  lua_pushboolean(state, value);
  lua_setfield(state, -2, key);
}

int call_described(lua_State* state) {
  const auto& function = *static_cast<const TheoryFunction*>(lua_touserdata(state, lua_upvalueindex(1)));
  return guarded(state, [&] {
    std::vector<const char*> known;
    for (const TheoryArgument& argument : function.arguments) known.push_back(argument.key);
    Fields fields(state, 1, std::string("theory.") + function.name, known);
    TheoryValues values(fields, function.arguments);
    // Every argument is read, so a bad one is refused even where this answer does not use it.
    for (const TheoryArgument& argument : function.arguments) values[argument.key];
    const TheoryAnswer answer = function.answer(values);
    if (const double* number = std::get_if<double>(&answer)) {
      lua_pushnumber(state, *number);
      return 1;
    }
    const auto& entries = std::get<std::vector<TheoryEntry>>(answer);
    lua_createtable(state, 0, static_cast<int>(entries.size()));
    for (const TheoryEntry& entry : entries) {
      if (const double* number = std::get_if<double>(&entry.value)) {
        lua_pushnumber(state, *number);
      } else if (const bool* flag = std::get_if<bool>(&entry.value)) {
        lua_pushboolean(state, *flag);
      } else {
        lua_pushstring(state, std::get<const char*>(entry.value));
      }
      lua_setfield(state, -2, entry.key);
    }
    return 1;
  });
}

}  // namespace frictionlab::lessons
