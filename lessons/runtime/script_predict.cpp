// predict{}: what the class is asked to predict before the run. A prediction names one of the
// lesson's expect rows: the theory it is set beside and the measurement are that row's own,
// worked out once, so a prediction cannot drift from the table it is judged by.
#include <algorithm>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {
namespace {

const Expectation* find_expectation(const LessonBuild& build, const std::string& name) {
  for (const Expectation& expectation : build.expectations) {
    if (expectation.name == name) return &expectation;
  }
  return nullptr;
}

std::string listed(const std::vector<std::string>& words) {
  std::string list;
  for (const std::string& word : words) list += (list.empty() ? "\"" : ", \"") + word + "\"";
  return list;
}

// choices = { "tips", "slides" }: two or more different words.
std::vector<std::string> read_choices(lua_State* state, Fields& fields) {
  std::vector<std::string> choices;
  fields.push("choices");
  const bool is_list = lua_istable(state, -1) && lua_rawlen(state, -1) >= 2;
  if (is_list) {
    for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(state, -1)); ++i) {
      lua_rawgeti(state, -1, i);
      const bool word = lua_type(state, -1) == LUA_TSTRING && lua_rawlen(state, -1) > 0;
      if (word) choices.emplace_back(lua_tostring(state, -1));
      lua_pop(state, 1);
      if (!word) throw InvalidInput(fields.what() + ": every choice must be a word in quotes, as in choices = { \"tips\", \"slides\" }");
    }
  }
  lua_pop(state, 1);
  if (!is_list) {
    throw InvalidInput(fields.what() + ": choices must be a list of at least two words the class picks from, as in "
                       "choices = { \"tips\", \"slides\" }");
  }
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (std::find(choices.begin(), choices.begin() + static_cast<std::ptrdiff_t>(i), choices[i]) !=
        choices.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw InvalidInput(fields.what() + ": the choice \"" + choices[i] + "\" is given twice");
    }
  }
  return choices;
}

int predict(lua_State* state) {
  return guarded(state, [&] {
    require_top_level(state, "predict declares part of the lesson");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "predict", {"question", "unit", "choices"});
    Prediction declared;
    declared.expectation = fields.name();
    declared.declared_at = caller(state);
    const Expectation* row = find_expectation(build, declared.expectation);
    if (row == nullptr) {
      std::vector<std::string> names;
      for (const Expectation& expectation : build.expectations) names.push_back(expectation.name);
      throw InvalidInput(fields.what() + ": no expect row above it is named so; a prediction names the row whose theory "
                         "and measurement it is set beside (rows so far: " +
                         (names.empty() ? "none" : listed(names)) + ")");
    }
    for (const Prediction& earlier : build.predictions) {
      if (earlier.expectation == declared.expectation) {
        throw InvalidInput(fields.what() + ": the row is predicted twice (first at " + earlier.declared_at + ")");
      }
    }
    declared.question = fields.text("question", "");
    if (declared.question.empty()) {
      throw InvalidInput(fields.what() + ": question must be text: what the class is asked, as in question = "
                         "\"How hard will the spring pull when the block starts to move?\"");
    }
    declared.unit = row->unit;
    // The unit is the row's; writing it again is allowed for the reader, but must agree.
    if (fields.has("unit")) {
      const std::string given = fields.text("unit", "");
      if (given != row->unit) {
        throw InvalidInput(fields.what() + ": unit \"" + given + "\" is not its expect row's " +
                           (row->unit.empty() ? "(none: the row is answered in words)" : "\"" + row->unit + "\"") +
                           " (" + row->declared_at + "); leave unit out or give the row's");
      }
    }
    fields.push("choices");
    const bool has_choices = !lua_isnil(state, -1);
    lua_pop(state, 1);
    if (has_choices) declared.choices = read_choices(state, fields);
    if (has_choices && !row->unit.empty()) {
      throw InvalidInput(fields.what() + ": choices are for a row answered in words, and its expect row has the unit \"" +
                         row->unit + "\" (" + row->declared_at + ")");
    }
    build.predictions.push_back(std::move(declared));
    return 0;
  });
}

}  // namespace

void check_predictions(LessonBuild& build) {
  // With other values (--set, a slider, a coarser step) a row may rightly answer otherwise: "not
  // reached", "on the threshold: either", "jitters at this step". At the defaults it must answer
  // what its prediction asks.
  if (!build.at_the_defaults()) return;
  lua_State* state = build.sandbox.state();
  for (const Prediction& prediction : build.predictions) {
    const Expectation& row = *find_expectation(build, prediction.expectation);
    build.push_value(row.predicted);
    const int type = lua_type(state, -1);
    const std::string word = type == LUA_TSTRING ? lua_tostring(state, -1) : "";
    std::string got = describe(state, -1);
    if (type == LUA_TSTRING) got = '"' + word + '"';
    lua_pop(state, 1);
    const std::string where = prediction.declared_at + ": predict '" + prediction.expectation + "': ";
    if (!prediction.is_choice() && type != LUA_TNUMBER) {
      throw ScriptError(where + "the class types a number, but at the lesson's defaults its row's theory (" +
                        row.declared_at + ") gives " + got + "; give choices = { ... } for a row answered in words");
    }
    if (prediction.is_choice() &&
        (type != LUA_TSTRING ||
         std::find(prediction.choices.begin(), prediction.choices.end(), word) ==
             prediction.choices.end())) {
      throw ScriptError(where + "at the lesson's defaults its row's theory (" + row.declared_at + ") gives " + got +
                        ", which is not one of the choices " +
                        listed(prediction.choices) + "; the class must be able to pick the answer");
    }
  }
}

void register_predict_api(lua_State* state) {
  lua_pushcfunction(state, predict);
  lua_setglobal(state, "predict");
}

}  // namespace frictionlab::lessons
