// The lesson part of the script API: what the lesson is and asks, its parameters, materials
// and pairs, probes, plots, expectations and every-step functions.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <sstream>
#include <set>
#include <span>
#include <vector>

#include "lessons/runtime/build.h"
#include "lessons/runtime/lesson.h"
#include "physics/friction_laws.h"
#include "physics/scenarios.h"
#include "physics/validation.h"

namespace frictionlab::lessons {
namespace {

// Things that make up the scene may be declared only while the script runs top to bottom.
void require_building(lua_State* state, const char* call) {
  require_top_level(state, std::string(call) + " declares part of the lesson");
}

// Applies a --set value to a freshly declared parameter. A bad value keeps the default and is
// reported once the build is over, as a command-line mistake rather than a script one.
void apply_override(LessonBuild& build, Parameter& parameter) {
  const auto found = build.overrides.find(parameter.name);
  if (found == build.overrides.end()) return;
  try {
    const GivenValue& given = found->second;
    parameter.value = given.number ? check_parameter_value(parameter, *given.number) : parse_parameter_value(parameter, given.text);
  } catch (const InvalidInput& error) {
    if (build.strict) {
      if (build.override_error.empty()) build.override_error = error.what();
    } else {
      // The script changed under a slider's value (a narrower range, a choice gone).
      build.warnings.push_back(parameter.declared_at + ": " + parameter.name + " was set to " + found->second.shown() +
                               ", which no longer fits; it is back to " + parameter.shown());
      build.overrides.erase(found);
    }
  }
}

void add_parameter(LessonBuild& build, Parameter parameter) {
  if (build.find_parameter(parameter.name) != nullptr) {
    throw InvalidInput("parameter '" + parameter.name + "' is declared twice (first at " +
                       build.find_parameter(parameter.name)->declared_at + ")");
  }
  apply_override(build, parameter);
  build.parameters.push_back(std::move(parameter));
}

void push_parameter_value(lua_State* state, const Parameter& parameter) {
  if (parameter.is_choice()) {
    lua_pushstring(state, parameter.choices[static_cast<size_t>(parameter.value)].c_str());
  } else {
    lua_pushnumber(state, parameter.value);
  }
}

int lesson(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "lesson");
    LessonBuild& build = build_of(state);
    // A second lesson{} would replace the first one's title but keep its duration: one only.
    if (!build.lesson_declared_at.empty()) {
      throw InvalidInput("lesson{} is given twice (first at " + build.lesson_declared_at +
                         "); a script is one lesson, so give its title, question and the rest once");
    }
    build.lesson_declared_at = caller(state);
    Fields fields(state, 1, "lesson", {"title", "question", "duration", "order", "moments", "velocity_iterations"});
    build.title = fields.text("title", "");
    build.question = fields.text("question", "");
    if (build.title.empty()) throw InvalidInput("lesson: title must be text, as in lesson{ title = \"...\" }");
    if (build.question.empty()) throw InvalidInput("lesson: question must be text: what does the lesson ask?");
    // A function may work the duration out from parameters a teacher changes while it runs.
    if (fields.push_function("duration")) {
      build.duration_function = luaL_ref(state, LUA_REGISTRYINDEX);
    } else {
      build.duration = fields.number_in("duration", "s", 10.0, 0.0, 86400.0, true);
    }
    // Where it comes among the built-in lessons: lessons/ is their list, in this order.
    if (fields.has("order")) build.order = fields.number_in("order", "", -1e6, 1e6);
    // A scene whose few contacts settle in fewer passes of the solver than the default 8 may
    // say so, and step faster (model no more than the scene needs).
    if (fields.has("velocity_iterations")) {
      const double count = fields.number_in("velocity_iterations", "", 1.0, 1000.0);
      if (count != std::floor(count)) {
        throw InvalidInput("lesson: velocity_iterations must be a whole number, from 1 to 1000");
      }
      build.scene->set_velocity_iterations(static_cast<int>(count));
    }
    fields.push("moments");
    if (!lua_isnil(state, -1)) read_moments(state, build);
    lua_pop(state, 1);
    return 0;
  });
}

int parameter(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "parameter");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "parameter", {"min", "max", "unit", "text", "choices"});
    Parameter declared;
    declared.name = fields.name();
    if (declared.name.find_first_of("= ,") != std::string::npos) {
      throw InvalidInput(fields.what() + ": a parameter's name cannot contain '=', ',' or spaces");
    }
    declared.unit = fields.text("unit", "");
    declared.text = fields.text("text", declared.name);
    declared.declared_at = caller(state);
    declared.structural = true;  // its value is handed to the script while it builds
    lua_rawgeti(state, 1, 2);
    fields.push("choices");
    if (!lua_isnil(state, -1)) {
      if (!lua_istable(state, -1) || lua_rawlen(state, -1) < 2) {
        throw InvalidInput(fields.what() + ": choices must be a list of at least two names, as in {\"aluminium\", \"plastic\"}");
      }
      for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(state, -1)); ++i) {
        lua_rawgeti(state, -1, i);
        if (lua_type(state, -1) != LUA_TSTRING) throw InvalidInput(fields.what() + ": every choice must be a name in quotes");
        declared.choices.emplace_back(lua_tostring(state, -1));
        lua_pop(state, 1);
      }
      // Checked here rather than by parse_parameter_value, whose message is worded for
      // --set NAME=VALUE ("block=: not one of ..." for a missing default).
      const std::string fallback = lua_type(state, -2) == LUA_TSTRING ? lua_tostring(state, -2) : "";
      const auto chosen = std::find(declared.choices.begin(), declared.choices.end(), fallback);
      if (lua_type(state, -2) != LUA_TSTRING || chosen == declared.choices.end()) {
        std::string list;
        for (const std::string& choice : declared.choices) list += (list.empty() ? "" : ", ") + choice;
        throw InvalidInput(fields.what() + ": its default comes second and must be one of the choices " + list +
                           ", as in parameter{ \"" + declared.name + "\", \"" + declared.choices[0] +
                           "\", choices = { ... } }; got " + describe(state, -2));
      }
      declared.value = static_cast<double>(chosen - declared.choices.begin());
    } else {
      if (lua_type(state, -2) != LUA_TNUMBER) {
        throw InvalidInput(fields.what() + ": its default value comes second, as in parameter{ \"mass\", 1.0, min = 0.1, "
                           "max = 10 }; got " + describe(state, -2));
      }
      declared.value = lua_tonumber(state, -2);
      declared.min = fields.number("min", declared.unit.c_str());
      declared.max = fields.number("max", declared.unit.c_str());
      if (!(declared.min < declared.max)) throw InvalidInput(fields.what() + ": min must be less than max");
      validation::require_in_range(fields.what() + ": default", declared.value, declared.min, declared.max, false,
                                   declared.unit.empty() ? "" : (" " + declared.unit).c_str());
    }
    lua_pop(state, 2);
    declared.default_value = declared.value;
    add_parameter(build, declared);
    push_parameter_value(state, build.parameters.back());
    return 1;
  });
}

// param.NAME: the current value of any parameter, including a pair's coefficients.
int parameter_value(lua_State* state) {
  return guarded(state, [&] {
    LessonBuild& build = build_of(state);
    const char* name = lua_tostring(state, 2);
    Parameter* found = name ? build.find_parameter(name) : nullptr;
    if (found == nullptr) {
      throw InvalidInput("param." + std::string(name ? name : "?") + ": no such parameter; parameters: " +
                         build.parameter_names());
    }
    if (build.building) found->structural = true;
    push_parameter_value(state, *found);
    return 1;
  });
}

int refuse_parameter_write(lua_State* state) {
  return guarded(state, [&]() -> int {
    throw InvalidInput("param is read-only: parameters change from the sliders or with --set NAME=VALUE");
  });
}

// rawset(param, ...) would write past __newindex: a field that shadows the parameter for the
// script while the scene keeps the real value. rawset refuses param and does the rest.
int raw_set(lua_State* state) {
  if (lua_rawequal(state, 1, lua_upvalueindex(2))) {
    return luaL_error(state, "param is read-only, rawset included: parameters change from the sliders or with --set "
                      "NAME=VALUE");
  }
  lua_pushvalue(state, lua_upvalueindex(1));
  lua_insert(state, 1);
  lua_call(state, lua_gettop(state) - 1, 1);
  return 1;
}

int material(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "material");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "material", {"density", "note"});
    Material declared;
    declared.name = fields.name();
    declared.density = fields.number("density", "kg/m²");
    declared.note = fields.text("note", "");
    build.scene->pairs().add_material(declared);
    return 0;
  });
}

}  // namespace

FrictionPair declare_coefficients(LessonBuild& build, const std::string& a, const std::string& b, FrictionPair values,
                                  const std::string& prefix, const std::string& declared_at,
                                  const std::set<const PairCoefficient*>& only) {
  for (const PairCoefficient& coefficient : pair_coefficients) {
    if (!only.empty() && only.count(&coefficient) == 0) continue;  // the script keeps this one
    Parameter declared;
    declared.name = prefix + coefficient.name;
    declared.unit = coefficient.unit;
    declared.text = std::string(coefficient.meaning) + ", " + a + " on " + b;
    declared.value = declared.default_value = values.*coefficient.value;
    declared.min = 0.0;
    declared.max = coefficient.lesson_largest;
    declared.coefficient = &coefficient;
    declared.material_a = a;
    declared.material_b = b;
    declared.declared_at = declared_at;
    add_parameter(build, declared);
    values.*coefficient.value = build.parameters.back().value;
  }
  return values;
}

void declare_preset_pairs(LessonBuild& build) {
  PairTable& table = build.scene->pairs();
  bool first_pair = true;
  for (const Parameter& p : build.parameters) first_pair = first_pair && p.coefficient == nullptr;
  for (int a = 0; a < table.material_count(); ++a) {
    for (int b = a; b < table.material_count(); ++b) {
      const std::string& name_a = table.material(a).name;
      const std::string& name_b = table.material(b).name;
      bool declared = false;
      for (const Parameter& p : build.parameters) {
        declared = declared || (p.material_a == name_a && p.material_b == name_b) ||
                   (p.material_a == name_b && p.material_b == name_a);
      }
      for (const auto& [fixed_a, fixed_b] : build.fixed_pairs) {
        declared = declared || (fixed_a == name_a && fixed_b == name_b) || (fixed_a == name_b && fixed_b == name_a);
      }
      if (declared || !table.has_pair(a, b) || table.is_shared(a, b) || !build.scene->can_touch(name_a, name_b)) {
        continue;
      }
      const std::string prefix = first_pair ? "" : name_a + "_" + name_b + ".";
      first_pair = false;
      const FrictionPair values = declare_coefficients(build, name_a, name_b, table.pair(a, b), prefix,
                                                       build.chunk_name + ": the preset values for " + name_a +
                                                           " on " + name_b);
      for (std::string& warning : table.set_pair(name_a, name_b, values)) build.warnings.push_back(warning);
    }
  }
}

namespace {

// A pair's coefficient that is a function of time, and which of mu_s, mu_k, c, b it is.
struct TimedCoefficient {
  const PairCoefficient* which;
  std::function<std::array<double, 2>(double)> at;
  std::string declared_at;  // "path:line" its errors name: the function's, or the pair's for a schedule
};

// A coefficient's schedule, { { t0, v0 }, { t1, v1 }, ... }: from each time on, its value (the
// last one given for a time counts). A lubricated stretch as numbers: the runtime reads it each
// sub-step without calling the script, where a function costs a call into Lua every sub-step.
std::vector<std::array<double, 2>> read_schedule(lua_State* state, int index, const std::string& what, double max) {
  const std::string form = what + ": a schedule is a list of { time, value } pairs from time 0 on, as in "
                                  "{ { 0, 0.5 }, { 1, 0.1 }, { 2, 0.5 } }";
  std::vector<std::array<double, 2>> steps;
  const lua_Integer count = static_cast<lua_Integer>(lua_rawlen(state, index));
  if (count == 0 || count > 10000) throw InvalidInput(form + " (1 to 10000 of them); got " + describe(state, index));
  for (lua_Integer k = 1; k <= count; ++k) {
    lua_rawgeti(state, index, k);
    std::array<double, 2> step{NAN, NAN};
    const bool pair = lua_istable(state, -1) && lua_rawlen(state, -1) == 2;
    for (int i = 0; pair && i < 2; ++i) {
      lua_rawgeti(state, -1, i + 1);
      if (lua_type(state, -1) == LUA_TNUMBER) step[static_cast<std::size_t>(i)] = lua_tonumber(state, -1);
      lua_pop(state, 1);
    }
    const std::string got = pair ? "a pair that is not two finite numbers" : describe(state, -1);
    lua_pop(state, 1);
    const std::string entry = "; entry " + std::to_string(k);
    if (!std::isfinite(step[0]) || !std::isfinite(step[1])) {
      throw InvalidInput(form + entry + " must be two numbers, { time, value }; it is " + got);
    }
    if (k == 1 && step[0] != 0.0) throw InvalidInput(form + entry + " starts at t = " + number_text(step[0]) + " s, not 0");
    if (k > 1 && step[0] < steps.back()[0]) {
      throw InvalidInput(form + entry + " goes back in time, to " + number_text(step[0]) + " s after " +
                         number_text(steps.back()[0]) + " s");
    }
    if (step[0] > 86400.0) throw InvalidInput(form + entry + ": time " + number_text(step[0]) + " s is past a day (86400 s)");
    if (step[1] < 0.0 || step[1] > max) {
      throw InvalidInput(what + ": entry " + std::to_string(k) + " of the schedule is " + number_text(step[1]) +
                         "; it must be in [0, " + number_text(max) + "]");
    }
    steps.push_back(step);
  }
  return steps;
}

// The coefficient's value at t, within its slider's range, or an error placed at the function.
double timed_value(const TimedCoefficient& coefficient, const std::string& label, double t) {
  const double value = coefficient.at(t)[0];
  const PairCoefficient& which = *coefficient.which;
  if (value >= 0.0 && value <= which.lesson_largest) return value;
  std::ostringstream message;
  message << coefficient.declared_at << ": pair " << label << ": " << which.name << " returned " << value
          << " at t = " << t << " s; it must be in [0, " << which.lesson_largest << "]";
  throw ScriptError(message.str());
}

// Before every sub-step, the pair takes its timed coefficients' values at the sub-step's start
// (its other coefficients as they are, sliders included). A change wakes the bodies the scene
// put to rest: a block held by static friction may slide with the new values.
void follow_in_time(LessonBuild& build, const std::string& a, const std::string& b, const std::string& label,
                    std::vector<TimedCoefficient> timed) {
  Scene* scene = build.scene.get();
  auto earlier = std::move(build.before_substep);
  build.before_substep = [=](double t) {
    if (earlier) earlier(t);
    FrictionPair values = scene->pairs().pair(a, b);
    bool changed = false;
    for (const TimedCoefficient& coefficient : timed) {
      const double value = timed_value(coefficient, label, t);
      double& slot = values.*coefficient.which->value;
      changed = changed || value != slot;
      slot = value;
    }
    if (!changed) return;
    scene->pairs().set_pair(a, b, values);
    scene->wake();
  };
  scene->set_before_substep(build.before_substep);
}

// The two materials a pair names first, refused when the lesson has that pair already (with
// sliders or fixed, either way round).
std::array<std::string, 2> pair_materials(lua_State* state, const LessonBuild& build) {
  std::array<std::string, 2> names;
  for (int i = 0; i < 2; ++i) {
    lua_rawgeti(state, 1, i + 1);
    if (lua_type(state, -1) != LUA_TSTRING) {
      throw InvalidInput("pair names its two materials first, as in pair{ \"aluminium\", \"wood\", mu_s = 0.45, "
                         "mu_k = 0.35 }; got " + describe(state, -1));
    }
    names[i] = lua_tostring(state, -1);
    lua_pop(state, 1);
  }
  const std::string label = names[0] + "/" + names[1];
  for (const Parameter& declared : build.parameters) {
    const bool same = (declared.material_a == names[0] && declared.material_b == names[1]) ||
                      (declared.material_a == names[1] && declared.material_b == names[0]);
    if (same) throw InvalidInput("pair " + label + " is given twice (first at " + declared.declared_at + ")");
  }
  for (const auto& [fixed_a, fixed_b] : build.fixed_pairs) {
    if ((fixed_a == names[0] && fixed_b == names[1]) || (fixed_a == names[1] && fixed_b == names[0])) {
      throw InvalidInput("pair " + label + " is given twice");
    }
  }
  return names;
}

// like = { "a", "b" }: the pair whose values this one shares (none given: two empty names).
std::array<std::string, 2> shared_pair_named(lua_State* state, Fields& fields, const std::vector<const char*>& value_fields,
                                             const std::string& label) {
  std::array<std::string, 2> like;
  if (fields.has("like")) {
    // Every value; a shared pair may still have a treatment of its own.
    for (const char* key : value_fields) {
      if (fields.has(key)) {
        throw InvalidInput("pair " + label + ": like = takes every value from the other pair; give no " + key);
      }
    }
    fields.push("like");
    for (int i = 0; i < 2; ++i) {
      if (lua_istable(state, -1)) lua_rawgeti(state, -1, i + 1); else lua_pushnil(state);
      const bool named = lua_type(state, -1) == LUA_TSTRING;
      if (named) like[i] = lua_tostring(state, -1);
      lua_pop(state, 1);
      if (!named) {
        lua_pop(state, 1);
        throw InvalidInput("pair " + label + ": like names the pair whose values this one takes, as in "
                           "like = { \"block\", \"slope\" }");
      }
    }
    lua_pop(state, 1);
  }
  return like;
}

// The pair's coefficients read into `values` (left as they are where the script gives none),
// each in the same range as its slider, so the default a script gives can also be set back. A
// coefficient given as a function of time (a surface oiled now and then) is asked at the
// start of every sub-step instead, and has no slider: those are returned.
std::vector<TimedCoefficient> read_coefficients(lua_State* state, LessonBuild& build, Fields& fields, const std::string& label,
                                                FrictionPair& values) {
  std::vector<TimedCoefficient> timed;
  for (const PairCoefficient& coefficient : pair_coefficients) {
    const char* key = coefficient.name;
    double& slot = values.*coefficient.value;
    if (fields.push_function(key)) {  // (like = with any coefficient is refused before)
      const int reference = luaL_ref(state, LUA_REGISTRYINDEX);
      const std::string what = "pair " + label + ": " + key + " (t -> a number)";
      timed.push_back({&coefficient, function_of_time(build, reference, 1, what), build.defined_at(reference)});
      slot = timed_value(timed.back(), label, 0.0);
      continue;
    }
    fields.push(key);
    if (lua_istable(state, -1)) {
      auto steps = read_schedule(state, -1, "pair " + label + ": " + key, coefficient.lesson_largest);
      lua_pop(state, 1);
      const auto at = [steps = std::move(steps)](double t) {
        // The last entry whose time has come. A step starting at an entry's time, up to the
        // rounding of the step's start (frame · step, in doubles), counts as at it: 7.4 s at
        // 240 Hz starts step 1776, at 1776/240 = 7.3999999999999995 s, where the entry waited a
        // step more and lubricated's oil stayed a step past the instant its theory was given
        // (the block stopped 4.9 ms later, 3.9 mm further).
        const double come = t + 1e-12 * std::max(1.0, std::abs(t));
        std::size_t k = steps.size() - 1;
        while (k > 0 && steps[k][0] > come) --k;
        return std::array<double, 2>{steps[k][1], 0.0};
      };
      timed.push_back({&coefficient, at, caller(state)});
      slot = timed_value(timed.back(), label, 0.0);
      continue;
    }
    lua_pop(state, 1);
    slot = fields.number_in(key, coefficient.unit, slot, 0.0, coefficient.lesson_largest);
  }
  return timed;
}

// A pair's own treatment (the run's --friction and Simulation menu then leave it alone).
// Its epsilon is no slider of its own: a lesson that varies it passes one of its parameters.
struct PairTreatmentAsked {
  std::optional<FrictionTreatment> treatment;
  std::optional<double> epsilon;
};

PairTreatmentAsked pair_treatment(Fields& fields, const std::string& label) {
  PairTreatmentAsked asked;
  if (fields.has("treatment")) {
    const std::string name = fields.text("treatment", "");
    try {
      asked.treatment = parse_treatment(name);
    } catch (const InvalidInput& error) {
      throw InvalidInput("pair " + label + ": " + error.what());
    }
    if (fields.has("epsilon")) {
      if (!uses_epsilon(*asked.treatment)) {
        throw InvalidInput("pair " + label + ": epsilon is for the threshold and regularized treatments, not " + name);
      }
      asked.epsilon = fields.number_in("epsilon", "m/s", 0.0, 100.0, true);
    }
  } else if (fields.has("epsilon")) {
    throw InvalidInput("pair " + label + ": epsilon needs treatment = \"threshold\" or \"regularized\"");
  }
  return asked;
}

// sliders = false: the script fixes the values itself (from parameters of its own, say, when
// one slider must drive several pairs), so the pair makes no parameters. A list of
// coefficients makes sliders for those only (terrain's surfaces offer mu_s and mu_k, not
// the c and b its theory leaves out); the others keep the script's values.
// Whether the pair makes sliders, and for which coefficients in `only` (empty: all).
bool wants_sliders(lua_State* state, Fields& fields, const std::string& label, const std::vector<TimedCoefficient>& timed,
                   std::set<const PairCoefficient*>& only) {
  bool with_sliders = true;
  if (fields.has("sliders")) {
    fields.push("sliders");
    if (lua_istable(state, -1)) {
      const lua_Integer count = luaL_len(state, -1);
      for (lua_Integer i = 1; i <= count; ++i) {
        lua_rawgeti(state, -1, i);
        const char* key = lua_type(state, -1) == LUA_TSTRING ? lua_tostring(state, -1) : nullptr;
        const std::string word = key ? key : describe(state, -1);
        lua_pop(state, 1);
        const PairCoefficient* listed = key == nullptr ? nullptr : pair_coefficient(word);
        if (listed == nullptr) {
          lua_pop(state, 1);
          throw InvalidInput("pair " + label + ": sliders lists coefficients from " + pair_coefficient_names() +
                             ", as in sliders = { \"mu_s\", \"mu_k\" }; got " + word);
        }
        only.insert(listed);
      }
      lua_pop(state, 1);
      if (only.empty()) throw InvalidInput("pair " + label + ": sliders = {} makes no sliders; write sliders = false");
      for (const TimedCoefficient& coefficient : timed) {
        if (only.count(coefficient.which) > 0) {
          throw InvalidInput("pair " + label + ": " + coefficient.which->name +
                             " changes with time (a function or a schedule), which no slider can set; leave it out of sliders");
        }
      }
    } else {
      lua_pop(state, 1);
      with_sliders = fields.flag("sliders").value_or(true);
    }
  }
  return with_sliders;
}

int pair(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "pair");
    LessonBuild& build = build_of(state);
    // The fields that give the pair's values (the four coefficients, physics/materials.h, and
    // its sliders' prefix and list), then its treatment's and a shared pair's.
    std::vector<const char*> value_fields;
    for (const PairCoefficient& coefficient : pair_coefficients) value_fields.push_back(coefficient.name);
    value_fields.insert(value_fields.end(), {"name", "sliders"});
    std::vector<const char*> known = value_fields;
    known.insert(known.end(), {"treatment", "epsilon", "like"});
    Fields fields(state, 1, "pair", std::span<const char* const>(known));
    const std::array<std::string, 2> names = pair_materials(state, build);
    const std::string label = names[0] + "/" + names[1];
    for (const std::string& name : names) build.use_material(name);
    {
      PairTable& table = build.scene->pairs();
      const int a = table.find_material(names[0]), b = table.find_material(names[1]);
      if (a >= 0 && b >= 0 && table.is_shared(a, b)) throw InvalidInput("pair " + label + " is given twice");
    }
    const std::array<std::string, 2> like = shared_pair_named(state, fields, value_fields, label);
    FrictionPair values;
    if (!like[0].empty()) {
      // Values come from the other pair, now and at every slider change: no sliders here.
    } else if (fields.has(static_coefficient.name) || fields.has(kinetic_coefficient.name)) {
      if (!fields.has(static_coefficient.name) || !fields.has(kinetic_coefficient.name)) {
        throw InvalidInput("pair " + label + ": give both " + static_coefficient.name + " and " + kinetic_coefficient.name +
                           ", or neither for the preset values");
      }
    } else {
      const int a = build.presets.find_material(names[0]), b = build.presets.find_material(names[1]);
      if (a < 0 || b < 0 || !build.presets.has_pair(a, b)) {
        throw InvalidInput("pair " + label + ": there is no preset for this pair; give mu_s and mu_k");
      }
      values = build.presets.pair(a, b);
    }
    bool first_pair = true;
    for (const Parameter& p : build.parameters) first_pair = first_pair && p.coefficient == nullptr;
    const std::string prefix = fields.has("name") ? fields.text("name", "") + "." : first_pair ? "" : names[0] + "_" + names[1] + ".";
    std::vector<TimedCoefficient> timed = read_coefficients(state, build, fields, label, values);
    const auto [treatment, epsilon] = pair_treatment(fields, label);
    if (!like[0].empty()) {
      build.scene->pairs().share_pair(names[0], names[1], like[0], like[1]);
      if (treatment) build.scene->pairs().set_treatment(names[0], names[1], *treatment, epsilon);
      return 0;
    }
    std::set<const PairCoefficient*> only;
    bool with_sliders = wants_sliders(state, fields, label, timed, only);
    if (with_sliders && !timed.empty()) {
      // Sliders for the coefficients that are numbers only.
      if (only.empty()) {
        for (const PairCoefficient& coefficient : pair_coefficients) only.insert(&coefficient);
      }
      for (const TimedCoefficient& coefficient : timed) only.erase(coefficient.which);
      with_sliders = !only.empty();
      if (!with_sliders) {
        if (fields.has("name")) throw InvalidInput("pair " + label + ": name prefixes its sliders' names; with every coefficient changing with time it has none");
        build.fixed_pairs.emplace_back(names[0], names[1]);
      }
    }
    if (with_sliders) {
      values = declare_coefficients(build, names[0], names[1], values, prefix, caller(state), only);
    } else {
      if (fields.has("name")) throw InvalidInput("pair " + label + ": name prefixes its sliders' names; with sliders = false it has none");
      build.fixed_pairs.emplace_back(names[0], names[1]);
    }
    for (std::string& warning : build.scene->pairs().set_pair(names[0], names[1], values)) {
      build.warnings.push_back(caller(state) + ": " + warning);
    }
    if (treatment) build.scene->pairs().set_treatment(names[0], names[1], *treatment, epsilon);
    if (!timed.empty()) follow_in_time(build, names[0], names[1], label, std::move(timed));
    return 0;
  });
}

int probe(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "probe");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "probe", {"unit", "read", "samples", "every", "delay", "label", "force", "like"});
    const std::string name = fields.name();
    if (name == "time" || name == "t") throw InvalidInput(fields.what() + ": the name is taken by the time itself");
    const std::string unit = fields.text("unit", "");
    const std::string label = fields.text("label", "");
    // force = "friction": the kind of force a probe the runtime cannot see into (a function, a
    // sampled model) measures, so that plots draw it in that force's arrows' colour.
    std::optional<ForceKind> stated_force;
    if (fields.has("force")) {
      const std::string word = fields.text("force", "");
      std::string allowed;
      for (int kind = 0; kind < force_kind_count; ++kind) {
        const std::string_view kind_word = force_kind_name(static_cast<ForceKind>(kind));
        if (word == kind_word) stated_force = static_cast<ForceKind>(kind);
        allowed += (kind == 0 ? "" : ", ") + std::string(kind_word);
      }
      if (!stated_force) throw InvalidInput(fields.what() + ": force = \"" + word + "\" is no kind of force; give one of " + allowed);
    }
    // like = "grass": drawn in a material's colour, a curve the class matches to a surface.
    const std::string like = fields.text("like", "");
    if (fields.has("like") && build.scene->pairs().find_material(like) < 0) {
      const std::string known = build.scene->pairs().material_names();
      throw InvalidInput(fields.what() + ": like = \"" + like + "\" is no material of this lesson (yet); its materials: " +
                         (known.empty() ? "none" : known));
    }
    if (fields.has("like") && stated_force) {
      throw InvalidInput(fields.what() + ": a force is drawn in its arrows' colour; give force or like, not both");
    }
    const size_t index = build.probes.size();
    lua_rawgeti(state, 1, 2);
    const bool has_function = !lua_isnil(state, -1);
    lua_pop(state, 1);
    if (fields.has("read") + fields.has("samples") + has_function > 1) {
      throw InvalidInput(fields.what() + ": give one of read = { ... }, samples = function(t) ... end or a function, "
                         "not two");
    }
    if (!fields.has("samples") && (fields.has("every") || fields.has("delay"))) {
      throw InvalidInput(fields.what() + ": every and delay go with samples = function(t) return list end");
    }
    if (fields.has("samples")) {
      if (!fields.push_function("samples")) {
        fields.push("samples");
        throw InvalidInput(fields.what() + ": samples must be a function(t) returning a list of values, as in samples = "
                           "function(t) return model.slide end; got " + describe(state, -1));
      }
      const int reference = luaL_ref(state, LUA_REGISTRYINDEX);
      const double every = fields.number_in("every", "s", 0.0, 1e6, true);
      const double delay = fields.number_in("delay", "s", 0.0, 0.0, 1e6);
      build.scene->add_probe(name, sampled_reading(build, reference, every, delay, fields.what()));
      build.probes.push_back({name, unit, LUA_NOREF, "", 0.0, label, stated_force, like});
      return 0;
    }
    if (fields.has("read")) {
      if (stated_force) throw InvalidInput(fields.what() + ": a read = { ... } probe's force is known from what it reads; leave force out");
      fields.push("read");
      std::optional<ForceKind> force;
      build.scene->add_probe(name, reading(state, -1, fields.what(), &force));
      lua_pop(state, 1);
      if (force && !like.empty()) {
        throw InvalidInput(fields.what() + ": a force is drawn in its arrows' colour; leave like out");
      }
      build.probes.push_back({name, unit, LUA_NOREF, "", 0.0, label, force, like});
      return 0;
    }
    lua_rawgeti(state, 1, 2);
    if (!lua_isfunction(state, -1)) {
      throw InvalidInput(fields.what() + ": give it a function second, as in probe{ \"" + name +
                         "\", unit = \"N\", function() return ... end }, or read = { handle, \"field\" }; got " +
                         describe(state, -1));
    }
    require_script_function(state, -1, fields.what());
    const int reference = luaL_ref(state, LUA_REGISTRYINDEX);
    LessonBuild* owner = &build;
    build.scene->add_probe(name, [owner, index] { return owner->probes[index].value; });
    build.probes.push_back({name, unit, reference, "probe '" + name + "'", 0.0, label, stated_force, like});
    build.lua_probes = true;
    return 0;
  });
}

// What a plot's list of labelled functions ({ "label", function ... end }, ...: theory's curves,
// the levels) is called in its messages, and what else an entry may hold.
struct LabelledList {
  const char* field;           // "theory"
  const char* entries;         // "curves": the field must be a list of them
  const char* entry;           // "theory curve": entry 1, entry 'label'
  std::string example;         // the whole field, as the guide writes it
  std::string shape;           // an entry that is not a table: what one must be
  std::string label_first;     // an entry without its label first: why it needs one, with an example
  const char* also = nullptr;  // the one named field an entry may hold besides ("active"), or none
  std::string holds;           // a misspelt field: what an entry holds
  std::string function_words;  // no function second: of what it is, and what it gives
};

// One entry as read: its table on the stack (for the field `also`), its label, its name in
// messages, where its function was written, and the function kept in the registry.
struct LabelledFunction {
  int entry = 0;
  std::string label, named, declared_at;
  int function = LUA_NOREF;
};

// Reads the field `words.field` of a plot{} as a list of labelled functions, handing each entry
// to `each` in order; nil is no list. Refuses, in `words`' terms, anything else.
void read_labelled_list(lua_State* state, Fields& fields, const LabelledList& words,
                        const std::function<void(const LabelledFunction&)>& each) {
  fields.push(words.field);
  if (lua_isnil(state, -1)) {
    lua_pop(state, 1);
    return;
  }
  if (!lua_istable(state, -1) || lua_rawlen(state, -1) == 0) {
    throw InvalidInput(fields.what() + ": " + words.field + " must be a list of " + words.entries + ", " + words.example +
                       "; got " + describe(state, -1));
  }
  const int list = lua_gettop(state);
  for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(state, list)); ++i) {
    const std::string which = fields.what() + ": " + words.entry + " " + std::to_string(i);
    lua_rawgeti(state, list, i);
    LabelledFunction read;
    read.entry = lua_gettop(state);
    if (!lua_istable(state, read.entry)) throw InvalidInput(which + words.shape + "; got " + describe(state, read.entry));
    lua_rawgeti(state, read.entry, 1);
    if (lua_type(state, -1) != LUA_TSTRING || lua_rawlen(state, -1) == 0) {
      throw InvalidInput(which + " needs its label first " + words.label_first + "; got " + describe(state, -1));
    }
    read.label = lua_tostring(state, -1);
    lua_pop(state, 1);
    read.named = fields.what() + ": " + words.entry + " '" + read.label + "'";
    // Only the label, the function and `also`: a misspelt field is said, not ignored.
    lua_pushnil(state);
    while (lua_next(state, read.entry) != 0) {
      lua_pop(state, 1);
      const bool position = lua_isinteger(state, -1) && (lua_tointeger(state, -1) == 1 || lua_tointeger(state, -1) == 2);
      const bool also = words.also != nullptr && lua_type(state, -1) == LUA_TSTRING && std::string(lua_tostring(state, -1)) == words.also;
      if (!position && !also) {
        const std::string key = lua_type(state, -1) == LUA_TSTRING ? "'" + std::string(lua_tostring(state, -1)) + "'" : describe(state, -1);
        throw InvalidInput(read.named + ": unknown field " + key + "; " + words.holds);
      }
    }
    lua_rawgeti(state, read.entry, 2);
    if (!lua_isfunction(state, -1)) {
      throw InvalidInput(read.named + " needs a function " + words.function_words + "; got " + describe(state, -1));
    }
    require_script_function(state, -1, read.named);
    lua_Debug debug;
    lua_pushvalue(state, -1);
    lua_getinfo(state, ">S", &debug);
    read.declared_at = std::string(debug.source[0] == '@' ? debug.source + 1 : debug.source) + ":" + std::to_string(debug.linedefined);
    read.function = luaL_ref(state, LUA_REGISTRYINDEX);
    each(read);
    lua_settop(state, list);
  }
  lua_pop(state, 1);
}

// theory = { { "label", function(x) ... end, active = function() ... end }, ... }: the
// curves kept in the registry beside the plot, in the build's plot_functions.
void read_theory(lua_State* state, Fields& fields, Plot& declared, PlotFunctions& functions) {
  LabelledList words{"theory", "curves", "theory curve",
                     "as in theory = { { \"sliding: f = \u2212\u03bck\u00b7N\", function(F) return -param.mu_k * N end } }",
                     " must be { \"label\", function(x) return y end }",
                     "(the legend names it), as in { \"sticking: f = \u2212F\", function(F) ... end }", "active",
                     "a curve is a label, a function and perhaps active = function() ... end",
                     std::string("of ") + (declared.kind == PlotKind::time ? "t" : "x (" + declared.x + ")") +
                         " second, returning y or nil where it does not apply"};
  read_labelled_list(state, fields, words, [&](const LabelledFunction& read) {
    TheoryCurve theory;
    theory.label = read.label;
    theory.declared_at = read.declared_at;
    functions.curves.push_back(read.function);
    lua_getfield(state, read.entry, "active");
    if (lua_isnil(state, -1)) {
      lua_pop(state, 1);
      functions.active.push_back(LUA_NOREF);
    } else {
      if (!lua_isfunction(state, -1)) {
        throw InvalidInput(read.named + ": active must be a function saying whether this branch applies now, as in "
                           "active = function() return touch.state == \"slipping\" end; got " + describe(state, -1));
      }
      require_script_function(state, -1, read.named + ": active");
      functions.active.push_back(luaL_ref(state, LUA_REGISTRYINDEX));
      theory.says_when_active = true;
    }
    declared.theory.push_back(std::move(theory));
  });
}

// levels = { { "label", function() ... end }, ... }: the levels the plot marks across its data,
// their functions kept in the registry beside the plot, in the build's plot_functions.
void read_levels_field(lua_State* state, Fields& fields, Plot& declared, PlotFunctions& functions) {
  const std::string example = "as in levels = { { \"−μs·N\", function() return -param.mu_s * N end } }";
  LabelledList words{"levels", "levels", "level", example, " must be { \"label\", function() return y end }",
                     "(the plot writes it beside the line), " + example, nullptr, "a level is a label and a function",
                     "second, of no argument, giving the level's y (or nil for none now)"};
  read_labelled_list(state, fields, words, [&](const LabelledFunction& read) {
    PlotLevel level;
    level.label = read.label;
    level.declared_at = read.declared_at;
    functions.levels.push_back(read.function);
    declared.levels.push_back(std::move(level));
  });
}

int plot(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "plot");
    Fields fields(state, 1, "plot", {"kind", "x", "y", "theory", "levels", "shade", "answer"});
    Plot declared;
    declared.title = fields.name();
    declared.answer = fields.text("answer", "");
    declared.declared_at = caller(state);
    // Without a kind the old form still reads as before: no x, a time series; an x, y against it.
    const std::string kind = fields.text("kind", fields.has("x") ? "xy" : "time");
    if (kind != "time" && kind != "xy") {
      throw InvalidInput(fields.what() + ": kind must be \"time\" (probes against time) or \"xy\" (probes against the "
                         "probe x); got \"" + kind + "\"");
    }
    declared.kind = kind == "time" ? PlotKind::time : PlotKind::xy;
    if (declared.kind == PlotKind::xy) {
      if (!fields.has("x")) {
        throw InvalidInput(fields.what() + ": kind = \"xy\" needs x, the probe along the bottom, as in x = \"push\"");
      }
      fields.push("x");
      if (lua_istable(state, -1)) {
        for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(state, -1)); ++i) {
          lua_rawgeti(state, -1, i);
          if (lua_type(state, -1) != LUA_TSTRING) throw InvalidInput(fields.what() + ": x must list probe names");
          declared.xs.emplace_back(lua_tostring(state, -1));
          lua_pop(state, 1);
        }
        if (declared.xs.empty()) throw InvalidInput(fields.what() + ": x must be a probe's name or a list of them");
        declared.x = declared.xs.front();
      } else {
        declared.x = fields.text("x", "");
      }
      lua_pop(state, 1);
      if (declared.x == "time") {
        throw InvalidInput(fields.what() + ": x = \"time\" is a time plot; say kind = \"time\" and leave x out");
      }
    } else {
      if (fields.has("x") && fields.text("x", "") != "time") {
        throw InvalidInput(fields.what() + ": a time plot's x is the time; leave x out, or say kind = \"xy\" to plot against " +
                           fields.text("x", ""));
      }
      declared.x = "time";
    }
    fields.push("y");
    if (lua_type(state, -1) == LUA_TSTRING) {
      declared.y.emplace_back(lua_tostring(state, -1));
    } else if (lua_istable(state, -1) && lua_rawlen(state, -1) > 0) {
      for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(state, -1)); ++i) {
        lua_rawgeti(state, -1, i);
        if (lua_type(state, -1) != LUA_TSTRING) throw InvalidInput(fields.what() + ": y must list probe names");
        declared.y.emplace_back(lua_tostring(state, -1));
        lua_pop(state, 1);
      }
    } else {
      throw InvalidInput(fields.what() + ": y must be a probe's name or a list of them, as in y = { \"spring_force\" }");
    }
    lua_pop(state, 1);
    if (!declared.xs.empty() && declared.xs.size() != declared.y.size()) {
      throw InvalidInput(fields.what() + ": x lists " + std::to_string(declared.xs.size()) + " probes and y " +
                         std::to_string(declared.y.size()) + "; a list of x pairs each y with its own x, so give as many");
    }
    if (fields.has("shade")) {
      fields.push("shade");
      if (lua_type(state, -1) != LUA_TSTRING || lua_rawlen(state, -1) == 0) {
        throw InvalidInput(fields.what() + ": shade must be a probe's name, as in shade = \"top_slipping\"; got " +
                           describe(state, -1));
      }
      declared.shade = lua_tostring(state, -1);
      lua_pop(state, 1);
      if (declared.kind != PlotKind::time) {
        throw InvalidInput(fields.what() + ": shade marks stretches of time; an X–Y plot colours its line by whether a "
                           "contact slips instead, so leave shade out");
      }
    }
    LessonBuild& build = build_of(state);
    PlotFunctions functions;
    read_theory(state, fields, declared, functions);
    read_levels_field(state, fields, declared, functions);
    build.plots.push_back(std::move(declared));
    build.plot_functions.push_back(std::move(functions));
    return 0;
  });
}

int expect(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "expect");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "expect", {"unit", "predicted", "measured", "tolerance"});
    Expectation declared;
    declared.name = fields.name();
    declared.unit = fields.text("unit", "");
    declared.declared_at = caller(state);
    for (const char* key : {"predicted", "measured"}) {
      if (!fields.has(key)) throw InvalidInput(fields.what() + ": " + key + " is missing (a value or a function)");
    }
    fields.push("predicted");
    declared.predicted = luaL_ref(state, LUA_REGISTRYINDEX);
    fields.push("measured");
    declared.measured = luaL_ref(state, LUA_REGISTRYINDEX);
    fields.push("tolerance");
    declared.tolerance = luaL_ref(state, LUA_REGISTRYINDEX);
    build.expectations.push_back(std::move(declared));
    return 0;
  });
}

int every_step(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "every_step");
    if (!lua_isfunction(state, 1)) {
      throw InvalidInput("every_step takes a function, as in every_step(function(t) ... end); got " + describe(state, 1));
    }
    require_script_function(state, 1, "every_step");
    lua_settop(state, 1);
    build_of(state).every_step.push_back(luaL_ref(state, LUA_REGISTRYINDEX));
    return 0;
  });
}

// history("name"): what a probe recorded, one value a step (history("time"): the times), for
// measuring after the run instead of in a function run every step. A view of the record, not
// a copy: a long run's record would not fit in the script's memory many times over.
struct HistoryView {
  int probe;  // index in the scene's probes; -1 for the times
};

const std::vector<double>& recorded(const Scene& scene, int probe) {
  return probe < 0 ? scene.times() : scene.probes()[static_cast<size_t>(probe)].history;
}

int find_probe(const Scene& scene, const char* name) {
  if (std::string(name) == "time") return -1;
  scene.probe(name);  // throws, listing the probes, when there is no such probe
  for (size_t i = 0; i < scene.probes().size(); ++i) {
    if (scene.probes()[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int history(lua_State* state) {
  return guarded(state, [&] {
    const int probe = find_probe(*build_of(state).scene, luaL_checkstring(state, 1));
    static_cast<HistoryView*>(lua_newuserdatauv(state, sizeof(HistoryView), 0))->probe = probe;
    luaL_setmetatable(state, "frictionlab.history");
    return 1;
  });
}

// h[i]: the value recorded at step i (nil past the end). Lua calls this only for values that
// carry the metatable, which scripts cannot reach, so the view needs no checking.
int history_index(lua_State* state) {
  return guarded(state, [&] {
    const auto* view = static_cast<const HistoryView*>(lua_touserdata(state, 1));
    if (!lua_isinteger(state, 2)) {
      throw InvalidInput("a history is read by step number, as in h[1] to h[#h]; got " + describe(state, 2));
    }
    const std::vector<double>& values = recorded(*build_of(state).scene, view->probe);
    const lua_Integer i = lua_tointeger(state, 2);
    if (i >= 1 && static_cast<size_t>(i) <= values.size()) {
      lua_pushnumber(state, values[static_cast<size_t>(i - 1)]);
    } else {
      lua_pushnil(state);
    }
    return 1;
  });
}

int history_length(lua_State* state) {
  const auto* view = static_cast<const HistoryView*>(lua_touserdata(state, 1));
  lua_pushinteger(state, static_cast<lua_Integer>(recorded(*build_of(state).scene, view->probe).size()));
  return 1;
}

// value_at("name", t): a probe's value (or the time) at the recorded step nearest t, or nil
// before the run has got there.
int value_at(lua_State* state) {
  return guarded(state, [&] {
    const Scene& scene = *build_of(state).scene;
    const std::vector<double>& values = recorded(scene, find_probe(scene, luaL_checkstring(state, 1)));
    const double t = luaL_checknumber(state, 2);
    if (!std::isfinite(t)) throw InvalidInput("value_at: the time must be a finite number of seconds");
    const std::vector<double>& times = scene.times();
    if (values.empty() || t > times.back() + 0.5 * scene.frame_step()) {
      lua_pushnil(state);
      return 1;
    }
    const auto later = std::lower_bound(times.begin(), times.end(), t);
    size_t i = static_cast<size_t>(later - times.begin());
    if (i == times.size() || (i > 0 && t - times[i - 1] < times[i] - t)) i = i == 0 ? 0 : i - 1;
    lua_pushnumber(state, values[i]);
    return 1;
  });
}

int time_now(lua_State* state) {
  lua_pushnumber(state, build_of(state).scene->time());
  return 1;
}

int step_length(lua_State* state) {
  lua_pushnumber(state, build_of(state).scene->frame_step());
  return 1;
}

// reached(t): whether the run has got to time t, the step nearest t (the earlier of two as near)
// taken or a later one. The same rule as the window's end of a run and the rows kept at the
// lesson's end (Lesson::step_reaches), so a row read "at the end" is read in the step the run
// ends with, whatever the step rate: time() >= t would wait a step more when t falls between
// two steps, and time() >= t - step_length() would read one step early.
int reached(lua_State* state) {
  return guarded(state, [&] {
    const double t = luaL_checknumber(state, 1);
    if (!std::isfinite(t)) throw InvalidInput("reached: the time must be a finite number of seconds");
    const Scene& scene = *build_of(state).scene;
    lua_pushboolean(state, Lesson::step_reaches(scene.time(), scene.frame_step(), t));
    return 1;
  });
}

// The length of one world step: the frame's over the run's sub-steps. Functions of time (a
// pair's coefficients) are asked at the start of each.
int substep_length(lua_State* state) {
  const Scene& scene = *build_of(state).scene;
  lua_pushnumber(state, scene.frame_step() / scene.settings().substeps);
  return 1;
}

}  // namespace

double check_parameter_value(const Parameter& parameter, double value) {
  if (parameter.is_choice()) {
    // A choice's place in its list, as Parameter::value holds it.
    const double last = static_cast<double>(parameter.choices.size() - 1);
    if (!(value >= 0.0 && value <= last && value == std::floor(value))) {
      std::string list;
      for (const std::string& choice : parameter.choices) list += (list.empty() ? "" : ", ") + choice;
      throw InvalidInput(parameter.name + " = " + validation::exact_text(value) + ": not the place of one of the choices " + list +
                         " (0 to " + validation::exact_text(last) + ")");
    }
    return value;
  }
  const std::string unit = parameter.unit.empty() ? "" : " " + parameter.unit;
  validation::require_in_range(parameter.name, value, parameter.min, parameter.max, false, unit.c_str());
  return value;
}

double parse_parameter_value(const Parameter& parameter, const std::string& text) {
  if (parameter.is_choice()) {
    for (size_t i = 0; i < parameter.choices.size(); ++i) {
      if (parameter.choices[i] == text) return static_cast<double>(i);
    }
    std::string list;
    for (const std::string& choice : parameter.choices) list += (list.empty() ? "" : ", ") + choice;
    throw InvalidInput(parameter.name + "=" + text + ": not one of the choices " + list);
  }
  // Read as the command line's numbers are (--hz, --duration): decimal only.
  std::string why;
  const std::optional<double> value = validation::parse_decimal(text, why);
  if (!value) {
    if (!why.empty()) throw InvalidInput(parameter.name + "=" + text + ": " + why);
    // A decimal comma is what many classrooms write: say what is wanted instead.
    const bool comma = text.find(',') != std::string::npos;
    throw InvalidInput(parameter.name + "=" + text + ": not a number" + (comma ? "; write decimals with a point, as in 0.5" : ""));
  }
  return check_parameter_value(parameter, *value);
}

std::string parameter_text(const Parameter& parameter) {
  if (parameter.is_choice()) return parameter.choices[static_cast<std::size_t>(parameter.value)];
  return validation::exact_text(parameter.value);
}

std::string GivenValue::shown() const { return number ? validation::exact_text(*number) : text; }

void register_lesson_api(lua_State* state) {
  const luaL_Reg functions[] = {{"lesson", lesson},       {"parameter", parameter}, {"material", material},
                                {"pair", pair},           {"probe", probe},         {"plot", plot},
                                {"expect", expect},       {"every_step", every_step}, {"time", time_now},
                                {"step_length", step_length}, {"reached", reached}, {"substep_length", substep_length}, {"history", history}, {"value_at", value_at}, {nullptr, nullptr}};
  lua_pushglobaltable(state);
  luaL_setfuncs(state, functions, 0);
  lua_pop(state, 1);
  lua_pushnumber(state, standard_gravity);
  lua_setglobal(state, "g");
  // A script's bodies rest with their surfaces touching (physics/scene.h, true_skin): no gap.
  // Kept, as 0, for scripts written when they rested 15 mm apart.
  lua_pushnumber(state, 0.0);
  lua_setglobal(state, "resting_gap");
  // The share past mu·N the stick-slip treatment lets the solver hold a stuck contact for a
  // step (physics/friction_laws.h): a theory of the stepped world, such as the wedge's rocking
  // test, must allow for it, and reads it here rather than keep a copy that could drift.
  lua_pushnumber(state, stick_slip_hold_band);
  lua_setglobal(state, "stick_slip_hold_band");
  // Box2D's linear slop (b2_linearSlop): how far two touching shapes may overlap before its
  // position solver pushes them apart. A theory of the stepped world reads it here (wedge's
  // contact lost to the turning surface's drift, stacked_blocks' tilt a contact's sink allows).
  // Box2D keeps it as a float; the script reads the decimal it is written as, which the docs
  // print, and which is Box2D's to the float's precision.
  constexpr double linear_slop = 0.005;
  static_assert(static_cast<float>(linear_slop) == b2_linearSlop, "linear_slop is Box2D's b2_linearSlop");
  lua_pushnumber(state, linear_slop);
  lua_setglobal(state, "linear_slop");
  // param: a read-only view of the parameters' current values.
  lua_newtable(state);
  lua_newtable(state);
  lua_pushcfunction(state, parameter_value);
  lua_setfield(state, -2, "__index");
  lua_pushcfunction(state, refuse_parameter_write);
  lua_setfield(state, -2, "__newindex");
  lua_setmetatable(state, -2);
  lua_getglobal(state, "rawset");
  lua_pushvalue(state, -2);
  lua_pushcclosure(state, raw_set, 2);
  lua_setglobal(state, "rawset");
  lua_setglobal(state, "param");
  luaL_newmetatable(state, "frictionlab.history");
  const luaL_Reg history_methods[] = {{"__index", history_index}, {"__len", history_length}, {nullptr, nullptr}};
  luaL_setfuncs(state, history_methods, 0);
  lua_pushboolean(state, false);
  lua_setfield(state, -2, "__metatable");  // hidden, so a script cannot call __index on anything else
  lua_pop(state, 1);
}

}  // namespace frictionlab::lessons
