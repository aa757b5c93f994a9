// view{}: what the camera shows. A lesson whose bodies are far apart or travel far says so
// here, rather than leaving a teacher with 25-pixel blocks.
#include <algorithm>
#include <cmath>

#include "lessons/runtime/build.h"
#include "lessons/runtime/handles.h"
#include "physics/validation.h"

namespace frictionlab::lessons {
namespace {

// Widths a view may span: a coin to a stadium.
constexpr double narrowest = 0.05, widest = 1000.0;

std::vector<std::string> lane_bodies(lua_State* state, Fields& fields) {
  fields.push("lanes");
  const int list = lua_gettop(state);
  if (!lua_istable(state, list) || handle_of(state, list, body_type) != nullptr) {
    throw InvalidInput(fields.what() + ": lanes must be a list of bodies, as in lanes = { coulomb, engineering }; got " +
                       describe(state, list));
  }
  std::vector<std::string> bodies;
  const lua_Integer count = luaL_len(state, list);
  for (lua_Integer i = 1; i <= count; ++i) {
    lua_rawgeti(state, list, i);
    const std::string which = fields.what() + ": lanes[" + std::to_string(i) + "]";
    const std::string body = body_name(state, body_handle(state, -1, which)->body);
    lua_pop(state, 1);
    if (std::find(bodies.begin(), bodies.end(), body) != bodies.end()) {
      throw InvalidInput(which + ": " + body + " already has a lane");
    }
    bodies.push_back(body);
  }
  lua_pop(state, 1);
  if (bodies.size() < 2 || bodies.size() > 6) {
    throw InvalidInput(fields.what() + ": lanes takes 2 to 6 bodies, one strip each; got " + std::to_string(bodies.size()));
  }
  return bodies;
}

std::vector<std::string> lane_titles(lua_State* state, Fields& fields, std::size_t lanes) {
  fields.push("titles");
  const int list = lua_gettop(state);
  const std::string example = "as in titles = { \"on a face\", \"on feet\" }";
  if (!lua_istable(state, list) || handle_of(state, list, body_type) != nullptr ||
      static_cast<std::size_t>(luaL_len(state, list)) != lanes) {
    throw InvalidInput(fields.what() + ": titles must be a list of " + std::to_string(lanes) + " words, one per lane, " +
                       example + "; got " + describe(state, list));
  }
  std::vector<std::string> titles;
  for (std::size_t i = 1; i <= lanes; ++i) {
    lua_rawgeti(state, list, static_cast<lua_Integer>(i));
    if (lua_type(state, -1) != LUA_TSTRING) {
      throw InvalidInput(fields.what() + ": titles[" + std::to_string(i) + "] must be text, " + example + "; got " +
                         describe(state, -1));
    }
    titles.emplace_back(lua_tostring(state, -1));
    lua_pop(state, 1);
  }
  lua_pop(state, 1);
  return titles;
}

void read_window(lua_State* state, Fields& fields, View& view) {
  fields.push("window");
  const int list = lua_gettop(state);
  const std::string which = fields.what() + ": window";
  const std::string example = "as in window = { -1, 0, 3, 1.5 } (left, bottom, right, top, in m)";
  if (!lua_istable(state, list) || handle_of(state, list, body_type) != nullptr || luaL_len(state, list) != 4) {
    throw InvalidInput(which + " takes four numbers, " + example + "; got " + describe(state, list));
  }
  double corner[4];
  for (int i = 0; i < 4; ++i) {
    lua_rawgeti(state, list, i + 1);
    if (lua_type(state, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(state, -1))) {
      throw InvalidInput(which + "[" + std::to_string(i + 1) + "] must be a number, " + example + "; got " +
                         describe(state, -1));
    }
    corner[i] = lua_tonumber(state, -1);
    lua_pop(state, 1);
  }
  lua_pop(state, 1);
  if (!(corner[0] < corner[2]) || !(corner[1] < corner[3])) {
    throw InvalidInput(which + ": left must be less than right and bottom less than top, " + example);
  }
  validation::require_in_range(which + " width", corner[2] - corner[0], narrowest, widest, false, " m");
  validation::require_in_range(which + " height", corner[3] - corner[1], narrowest, widest, false, " m");
  view.low = b2Vec2{static_cast<float>(corner[0]), static_cast<float>(corner[1])};
  view.high = b2Vec2{static_cast<float>(corner[2]), static_cast<float>(corner[3])};
}

int view(lua_State* state) {
  return guarded(state, [&] {
    require_top_level(state, "view sets what the lesson shows");
    LessonBuild& build = build_of(state);
    if (!build.view.declared_at.empty()) {
      throw InvalidInput("view: the lesson's view was already set at " + build.view.declared_at + "; a lesson has one view");
    }
    Fields fields(state, 1, "view", {"follow", "window", "lanes", "width", "titles"});
    const int kinds = (fields.has("follow") ? 1 : 0) + (fields.has("window") ? 1 : 0) + (fields.has("lanes") ? 1 : 0);
    const std::string kinds_wanted = "one of follow = body, window = { left, bottom, right, top } or lanes = { body, ... }";
    if (kinds == 0) {
      throw InvalidInput("view takes " + kinds_wanted + "; it got none (a field whose value is nil, such as a misspelt "
                         "variable, is not there)");
    }
    if (kinds > 1) throw InvalidInput("view takes " + kinds_wanted + ", only one; it got " + std::to_string(kinds));
    View made;
    made.declared_at = caller(state);
    if (fields.has("follow")) {
      made.kind = View::Kind::follow;
      fields.push("follow");
      made.bodies.push_back(body_name(state, body_handle(state, -1, fields.what() + ": follow")->body));
      lua_pop(state, 1);
    } else if (fields.has("lanes")) {
      made.kind = View::Kind::lanes;
      made.bodies = lane_bodies(state, fields);
    } else {
      made.kind = View::Kind::window;
      read_window(state, fields, made);
      if (fields.has("width")) throw InvalidInput(fields.what() + ": a window sets its own width; leave width out");
    }
    if (fields.has("width")) made.width = fields.number_in("width", "m", narrowest, widest);
    if (fields.has("titles")) {
      if (made.kind != View::Kind::lanes) throw InvalidInput(fields.what() + ": titles name lanes; this view has none");
      made.titles = lane_titles(state, fields, made.bodies.size());
    }
    build.view = std::move(made);
    return 0;
  });
}

}  // namespace

void register_view_api(lua_State* state) {
  lua_register(state, "view", view);
}

}  // namespace frictionlab::lessons
