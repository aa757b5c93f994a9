// A lesson's teaching moments, lesson{ moments = { { "sticking", at = 0.5, ... }, ... } }: read
// and checked while lesson{} runs, their parameters checked once the script has declared them.
#include <cctype>
#include <sstream>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {
namespace {

constexpr const char* moment_example = "{ \"sticking\", at = 0.5 }";

// A moment's name becomes part of a file name and of a test's name: letters, digits and _.
bool is_word(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

// set = { angle = 25, block = "plastic" }, the table on the stack top, as --set would give it.
std::map<std::string, std::string> read_set(lua_State* state, const std::string& what) {
  std::map<std::string, std::string> values;
  const std::string expected = what + ": set must be a table of parameter values, as in set = { angle = 25 }";
  if (!lua_istable(state, -1)) throw InvalidInput(expected + "; got " + describe(state, -1));
  const int table = lua_absindex(state, -1);
  lua_pushnil(state);
  while (lua_next(state, table) != 0) {
    if (lua_type(state, -2) != LUA_TSTRING) throw InvalidInput(expected + "; got a key that is " + describe(state, -2));
    const std::string name = lua_tostring(state, -2);
    const int type = lua_type(state, -1);
    if (type != LUA_TNUMBER && type != LUA_TSTRING) {
      throw InvalidInput(what + ": set " + name + " must be a number or a choice in quotes, got " + describe(state, -1));
    }
    lua_pushvalue(state, -1);  // a copy: lua_tostring turns a number into text in place
    values[name] = lua_tostring(state, -1);
    lua_pop(state, 2);
  }
  return values;
}

}  // namespace

void read_moments(lua_State* state, LessonBuild& build) {
  const int list = lua_absindex(state, -1);
  const std::string expected = "lesson: moments must be a list of moments, as in moments = { " +
                               std::string(moment_example) + " }";
  if (!lua_istable(state, list) || lua_rawlen(state, list) == 0) throw InvalidInput(expected + "; got " + describe(state, list));
  const std::string declared_at = caller(state);
  for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(state, list)); ++i) {
    lua_rawgeti(state, list, i);
    if (!lua_istable(state, -1)) {
      throw InvalidInput("lesson: moment " + std::to_string(i) + " must be a table such as " + moment_example + "; got " +
                         describe(state, -1));
    }
    lua_rawgeti(state, -1, 1);
    const bool named = lua_type(state, -1) == LUA_TSTRING;
    lua_pop(state, 1);
    if (!named) throw InvalidInput("lesson: moment " + std::to_string(i) + " needs a name first, as in " + moment_example);
    Fields fields(state, -1, "moment", {"at", "set", "theme", "shows", "readme"});
    Moment moment;
    moment.name = fields.name();
    moment.declared_at = declared_at;
    if (!is_word(moment.name)) {
      throw InvalidInput(fields.what() + ": a moment's name is one word of letters, digits and _, as in \"mid_slip\" "
                         "(it names the golden picture)");
    }
    for (const Moment& earlier : build.moments) {
      if (earlier.name == moment.name) throw InvalidInput(fields.what() + " is given twice");
    }
    moment.at = fields.number_in("at", "s", 0.0, 86400.0);
    moment.theme = fields.text("theme", "light");
    if (moment.theme != "light" && moment.theme != "dark") {
      throw InvalidInput(fields.what() + ": theme must be \"light\" or \"dark\", got \"" + moment.theme + "\"");
    }
    moment.readme = fields.flag("readme").value_or(false);
    if (moment.readme) {
      for (const Moment& earlier : build.moments) {
        if (earlier.readme) {
          throw InvalidInput(fields.what() + ": readme = true is given to moment '" + earlier.name +
                             "' already; a lesson has one README frame");
        }
      }
    }
    fields.push("set");
    if (!lua_isnil(state, -1)) moment.set = read_set(state, fields.what());
    lua_pop(state, 1);
    int shows = LUA_NOREF;
    if (fields.push_function("shows")) {
      shows = luaL_ref(state, LUA_REGISTRYINDEX);
    } else if (fields.has("shows")) {
      fields.push("shows");
      throw InvalidInput(fields.what() + ": shows must be a function that returns true when the moment shows what its "
                         "name says, as in shows = function() return value_at(\"slipping\", time()) == 1 end; got " +
                         describe(state, -1));
    }
    moment.has_shows = shows != LUA_NOREF;
    build.moments.push_back(std::move(moment));
    build.moment_shows.push_back(shows);
    lua_pop(state, 1);
  }
}

void check_moments(LessonBuild& build, std::optional<double> duration) {
  for (const Moment& moment : build.moments) {
    const std::string where = moment.declared_at + ": lesson: moment '" + moment.name + "': ";
    for (const auto& [name, value] : moment.set) {
      const Parameter* parameter = build.find_parameter(name);
      if (parameter == nullptr) {
        throw ScriptError(where + "set " + name + ": no such parameter; parameters: " + build.parameter_names());
      }
      try {
        parse_parameter_value(*parameter, value);
      } catch (const InvalidInput& error) {
        throw ScriptError(where + "set " + error.what());
      }
    }
    // With other values the lesson may last longer (or less): that is checked where the moment
    // is shown with them (tests/scenarios/test_snapshots.cpp). A moment is the author's picture,
    // not the lesson: a student who changes a default that shortens the run (push_rate 2 → 3
    // in push.lua) still gets the lesson, told that the picture is past its end; only
    // render --moment refuses it.
    if (duration && moment.set.empty() && moment.at > *duration) {
      std::ostringstream message;
      message << where << "at = " << moment.at << " s is after the run's end at " << *duration
              << " s with these values; the lesson runs as ever, without this moment's picture (for the README and "
                 "the tests); move its at earlier to keep it";
      build.warnings.push_back(message.str());
    }
  }
}

}  // namespace frictionlab::lessons
