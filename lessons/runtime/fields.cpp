// Reading a script's table arguments with errors a student can act on.
#include <cmath>
#include <cstring>
#include <sstream>

#include "lessons/runtime/build.h"
#include "physics/validation.h"

namespace frictionlab::lessons {

std::string caller(lua_State* state) {
  lua_Debug debug;
  if (lua_getstack(state, 1, &debug) && lua_getinfo(state, "Sl", &debug) && debug.currentline > 0) {
    // source is "@path" in full; short_src may have been cut short.
    return std::string(debug.source + 1) + ":" + std::to_string(debug.currentline);
  }
  return build_of(state).chunk_name;
}

Fields::Fields(lua_State* state, int index, std::string call, std::initializer_list<const char*> known)
    : Fields(state, index, std::move(call), std::span<const char* const>(known.begin(), known.size())) {}

Fields::Fields(lua_State* state, int index, std::string call, std::span<const char* const> known)
    : state_(state), index_(lua_absindex(state, index)), call_(std::move(call)), what_(call_) {
  if (!lua_istable(state_, index_)) {
    throw InvalidInput(call_ + " takes a table, as in " + call_ + "{ ... }; got " + describe(state_, index_));
  }
  // Named from the start, so that even a typo in a later field says which box it is in. A
  // pair's first entries are its two materials, not a name: it is named by them, as pair{}'s
  // own messages name it ("pair aluminium/wood").
  lua_rawgeti(state_, index_, 1);
  lua_rawgeti(state_, index_, 2);
  if (call_ == "pair") {
    if (lua_type(state_, -2) == LUA_TSTRING && lua_type(state_, -1) == LUA_TSTRING) {
      what_ = call_ + " " + lua_tostring(state_, -2) + "/" + lua_tostring(state_, -1);
    }
  } else if (lua_type(state_, -2) == LUA_TSTRING) {
    what_ = call_ + " '" + lua_tostring(state_, -2) + "'";
  }
  lua_pop(state_, 2);
  // Refuse fields the call does not know, listing the ones it does. The first unknown one in
  // alphabetical order is named, so the message is the same on every run (Lua's table order
  // is not).
  std::string unknown;
  lua_pushnil(state_);
  while (lua_next(state_, index_) != 0) {
    lua_pop(state_, 1);
    if (lua_type(state_, -1) == LUA_TSTRING) {
      const std::string key = lua_tostring(state_, -1);
      bool found = false;
      for (const char* name : known) found = found || key == name;
      if (!found && (unknown.empty() || key < unknown)) unknown = key;
    }
  }
  if (!unknown.empty()) {
    std::string list;
    for (const char* name : known) list += std::string(list.empty() ? "" : ", ") + name;
    throw InvalidInput(what_ + ": unknown field '" + unknown + "'; it takes " + list);
  }
}

std::string Fields::name() {
  lua_rawgeti(state_, index_, 1);
  if (lua_type(state_, -1) != LUA_TSTRING || lua_rawlen(state_, -1) == 0) {
    const std::string got = describe(state_, -1);
    lua_pop(state_, 1);
    throw InvalidInput(call_ + " needs a name first, as in " + call_ + "{ \"name\", ... }; got " + got);
  }
  std::size_t length = 0;
  const char* bytes = lua_tolstring(state_, -1, &length);
  std::string name(bytes, length);
  lua_pop(state_, 1);
  // Cut at the NUL by every C string it passes through, the name would no longer be itself.
  if (name.find('\0') != std::string::npos) {
    throw InvalidInput(call_ + " '" + name.substr(0, name.find('\0')) + "\\0...': a name cannot hold a NUL byte (\\0)");
  }
  what_ = call_ + " '" + name + "'";
  return name;
}

void Fields::wrong(const char* key, const std::string& expected, int value_index) {
  const std::string got = describe(state_, value_index);
  throw InvalidInput(what_ + ": " + key + " must be " + expected + ", got " + got);
}

bool Fields::has(const char* key) {
  lua_getfield(state_, index_, key);
  const bool present = !lua_isnil(state_, -1);
  lua_pop(state_, 1);
  return present;
}

double Fields::number(const char* key, const char* unit) {
  lua_getfield(state_, index_, key);
  if (lua_type(state_, -1) != LUA_TNUMBER) wrong(key, std::string("a number") + (*unit ? " (" : "") + unit + (*unit ? ")" : ""), -1);
  const double value = lua_tonumber(state_, -1);
  lua_pop(state_, 1);
  if (!std::isfinite(value)) throw InvalidInput(what_ + ": " + key + " must be finite");
  return value;
}

double Fields::number(const char* key, const char* unit, double fallback) {
  return has(key) ? number(key, unit) : fallback;
}

double Fields::number_in(const char* key, const char* unit, double low, double high, bool low_open) {
  const double value = number(key, unit);
  const std::string spaced = *unit ? std::string(" ") + unit : "";
  validation::require_in_range(what_ + ": " + key, value, low, high, low_open, spaced.c_str());
  return value;
}

double Fields::number_in(const char* key, const char* unit, double fallback, double low, double high,
                         bool low_open) {
  const double value = number(key, unit, fallback);
  const std::string spaced = *unit ? std::string(" ") + unit : "";
  validation::require_in_range(what_ + ": " + key, value, low, high, low_open, spaced.c_str());
  return value;
}

std::string Fields::text(const char* key, const std::string& fallback) {
  lua_getfield(state_, index_, key);
  if (lua_isnil(state_, -1)) {
    lua_pop(state_, 1);
    return fallback;
  }
  if (lua_type(state_, -1) != LUA_TSTRING) wrong(key, "text in quotes", -1);
  std::size_t length = 0;
  const char* bytes = lua_tolstring(state_, -1, &length);
  std::string value(bytes, length);
  lua_pop(state_, 1);
  if (value.find('\0') != std::string::npos) {
    throw InvalidInput(what_ + ": " + key + " cannot hold a NUL byte (\\0)");
  }
  return value;
}

std::optional<bool> Fields::flag(const char* key) {
  lua_getfield(state_, index_, key);
  std::optional<bool> value;
  if (lua_type(state_, -1) == LUA_TBOOLEAN) {
    value = lua_toboolean(state_, -1) != 0;
  } else if (!lua_isnil(state_, -1)) {
    wrong(key, "true or false", -1);
  }
  lua_pop(state_, 1);
  return value;
}

b2Vec2 Fields::point(const char* key, b2Vec2 fallback) {
  lua_getfield(state_, index_, key);
  if (lua_isnil(state_, -1)) {
    lua_pop(state_, 1);
    return fallback;
  }
  // Most points are places in m; a starting velocity, a constant force and a direction are not.
  const bool grows = std::strcmp(key, "grows") == 0;
  const bool force = std::strcmp(key, "force") == 0 || grows;
  const char* unit = std::strcmp(key, "velocity") == 0 ? "m/s"
                     : grows                            ? "N/s"
                     : force                            ? "N"
                     : std::strcmp(key, "along") == 0   ? ""
                                                        : "m";
  const std::string expected = std::string("a pair of numbers such as {0.5, 0}") + (*unit ? std::string(" (") + unit + ")" : "");
  if (!lua_istable(state_, -1)) wrong(key, expected, -1);
  double xy[2];
  for (int i = 0; i < 2; ++i) {
    lua_rawgeti(state_, -1 - i, i + 1);
    if (lua_type(state_, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(state_, -1))) wrong(key, expected, -1);
    xy[i] = lua_tonumber(state_, -1);
  }
  lua_pop(state_, 3);
  // Far beyond the scene (or a force beyond what the scene accepts) would turn the world to NaN.
  const double limit = force ? 1e9 : 1e4;
  if (std::abs(xy[0]) > limit || std::abs(xy[1]) > limit) {
    std::ostringstream message;
    message << what_ << ": " << key << " = {" << xy[0] << ", " << xy[1] << "} must be within ±" << limit
            << (*unit ? " " : "") << unit;
    throw InvalidInput(message.str());
  }
  return {static_cast<float>(xy[0]), static_cast<float>(xy[1])};
}

bool Fields::push_function(const char* key) {
  lua_getfield(state_, index_, key);
  if (lua_isfunction(state_, -1)) {
    require_script_function(state_, -1, what_ + ": " + key);
    return true;
  }
  lua_pop(state_, 1);
  return false;
}

void Fields::push(const char* key) { lua_getfield(state_, index_, key); }

}  // namespace frictionlab::lessons
