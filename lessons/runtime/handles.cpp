// The handles a script holds and what it may read from them: body.x, spring.tension,
// push.fx, contact(a, b).state, and probe{ read = { handle, "field" } }.
#include "lessons/runtime/handles.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include "physics/validation.h"

namespace frictionlab::lessons {

const char* const type_names[5] = {"frictionlab.body", "frictionlab.spring", "frictionlab.force",
                                   "frictionlab.contact", "frictionlab.rope"};

namespace {

// contact(a, b): a view of what the friction listener recorded for the touching pair, read
// when a field is read. A view rather than a table of copies: probes ask every step, and
// building sixteen fields to read one was most of a lesson's script time.
int contact(lua_State* state) {
  return guarded(state, [&] {
    const b2Body* a = body_handle(state, 1, "contact's first argument")->body;
    const b2Body* b = body_handle(state, 2, "contact's second argument")->body;
    if (a == b) throw InvalidInput("contact needs two different bodies, as in contact(block, floor)");
    // contact(a, b, k): the k-th foot from the left of whichever of the two stands on feet.
    const b2Fixture* foot = nullptr;
    if (!lua_isnoneornil(state, 3)) {
      const LessonBuild& build = build_of(state);
      auto feet = build.feet.find(a);
      if (feet == build.feet.end()) feet = build.feet.find(b);
      if (feet == build.feet.end()) {
        throw InvalidInput("contact(a, b, k) reads one foot of a body on feet (box{ ..., feet = n }); neither of these "
                           "has feet");
      }
      const lua_Integer count = static_cast<lua_Integer>(feet->second.size());
      if (!lua_isinteger(state, 3) || lua_tointeger(state, 3) < 1 || lua_tointeger(state, 3) > count) {
        throw InvalidInput("contact(a, b, k): k is a foot's number from the left, 1 to " + std::to_string(count) + "; got " +
                           describe(state, 3));
      }
      foot = feet->second[static_cast<size_t>(lua_tointeger(state, 3) - 1)];
      if (feet->first == b) std::swap(a, b);  // read from the body on feet
    }
    auto* handle = static_cast<ContactHandle*>(lua_newuserdatauv(state, sizeof(ContactHandle), 0));
    *handle = {a, b, foot};
    luaL_setmetatable(state, type_names[contact_type]);
    return 1;
  });
}

// What a script can read from a handle. One table serves both `block.vx` in Lua and
// probe{ read = { block, "vx" } }, which the runtime reads itself every step without Lua.
enum class Field { x, y, angle, vx, vy, omega, mass, distance, speed, acceleration, torque, force_x, force_y, length, tension, fx, fy,
                   friction, normal, nx, ny, drag, drag_x, drag_y, sliding_speed, slipping, points, load1, load2,
                   load_left, load_right };
struct FieldName {
  const char* name;
  Field field;
};
// A body's fields that mean something only along a direction, and so only in a probe.
bool directed_field(Field field) {
  return field == Field::distance || field == Field::speed || field == Field::acceleration;
}
const std::vector<FieldName>& field_names(HandleType type) {
  static const std::vector<FieldName> body = {{"x", Field::x},   {"y", Field::y},         {"angle", Field::angle},
                                              {"vx", Field::vx}, {"vy", Field::vy},       {"omega", Field::omega},
                                              {"mass", Field::mass}, {"distance", Field::distance},
                                              {"speed", Field::speed}, {"acceleration", Field::acceleration}};
  static const std::vector<FieldName> spring = {{"force_x", Field::force_x}, {"force_y", Field::force_y},
                                                {"length", Field::length}, {"tension", Field::tension}};
  static const std::vector<FieldName> force = {{"fx", Field::fx}, {"fy", Field::fy}, {"torque", Field::torque}};
  static const std::vector<FieldName> rope = {{"tension", Field::tension}};
  static const std::vector<FieldName> contact = {
      {"friction", Field::friction}, {"fx", Field::fx},         {"fy", Field::fy},
      {"normal", Field::normal},     {"nx", Field::nx},         {"ny", Field::ny},
      {"drag", Field::drag},         {"drag_x", Field::drag_x}, {"drag_y", Field::drag_y},
      {"sliding_speed", Field::sliding_speed}, {"slipping", Field::slipping}, {"points", Field::points},
      {"load1", Field::load1}, {"load2", Field::load2}, {"load_left", Field::load_left},
      {"load_right", Field::load_right}};
  switch (type) {
    case body_type: return body;
    case spring_type: return spring;
    case force_type: return force;
    case rope_type: return rope;
    case contact_type: break;
  }
  return contact;
}

// A handle copied out of its userdata, so the runtime can keep reading it.
struct Handle {
  HandleType type;
  const b2Body* body = nullptr;   // a body
  size_t index = 0;               // a spring, a force or a rope
  ContactHandle contact{nullptr, nullptr, nullptr};
  // How a probe reads a body: at which of its points, along which unit direction (distance
  // and speed), from where that point started (distance), and times what (scale).
  bool at_point = false;  // without one, x and y are the body's origin and vx, vy its centre's
  b2Vec2 point{0.0f, 0.0f};
  b2Vec2 along{1.0f, 0.0f};
  b2Vec2 start{0.0f, 0.0f};
  double scale = 1.0;
  // Positions in another body's own axes (x, y and distance): where a block is along a plank
  // that moves and turns, read without a line of script.
  const b2Body* frame = nullptr;
};

Handle copy_handle(const void* data, HandleType type) {
  Handle handle{type};
  if (type == body_type) handle.body = static_cast<const BodyHandle*>(data)->body;
  if (type == spring_type) handle.index = static_cast<const SpringHandle*>(data)->index;
  if (type == force_type) handle.index = static_cast<const ForceHandle*>(data)->index;
  if (type == contact_type) handle.contact = *static_cast<const ContactHandle*>(data);
  if (type == rope_type) handle.index = static_cast<const RopeHandle*>(data)->index;
  return handle;
}

// Whatever handle is at `index`, found by its metatable.
std::optional<Handle> any_handle(lua_State* state, int index) {
  for (const HandleType type : {body_type, spring_type, force_type, contact_type, rope_type}) {
    if (const void* data = handle_of(state, index, type)) return copy_handle(data, type);
  }
  return std::nullopt;
}

std::optional<Field> find_field(HandleType type, const char* key) {
  for (const FieldName& known : field_names(type)) {
    if (std::strcmp(known.name, key) == 0) return known.field;
  }
  return std::nullopt;
}

// The record of a and b's contact while their shapes still touch where the bodies are now:
// a block that has just left the floor reads "none" and 0 in the very step it leaves, not a
// step later when Box2D notices (Scene::touching_now).
const ContactRecord* touching_record(const Scene& scene, const b2Body* a, const b2Body* b) {
  // One walk of a's contacts: the record is the first touching one's that has a record, as
  // FrictionListener::find gives it; a probe reads it every step, four on stacked_blocks.
  const ContactRecord* record = nullptr;
  bool touching = false;
  for (const b2ContactEdge* edge = a->GetContactList(); edge != nullptr; edge = edge->next) {
    if (edge->other != b || !edge->contact->IsTouching()) continue;
    if (record == nullptr) record = scene.friction().record(edge->contact);
    touching = touching || scene.touching_now(edge->contact);
    if (record != nullptr && touching) return record;
  }
  return nullptr;
}

// The record a contact view reads: of the two bodies' touch, or of one foot's (touching where
// the bodies are now, as touching_record).
const ContactRecord* find_record(const Scene& scene, const ContactHandle& view) {
  if (view.foot == nullptr) return touching_record(scene, view.a, view.b);
  for (const b2ContactEdge* edge = view.a->GetContactList(); edge != nullptr; edge = edge->next) {
    b2Contact* touch = edge->contact;
    if (edge->other != view.b || !touch->IsTouching()) continue;
    if (touch->GetFixtureA() != view.foot && touch->GetFixtureB() != view.foot) continue;
    if (!scene.touching_now(touch)) return nullptr;
    return scene.friction().record(touch);
  }
  return nullptr;
}

double read_field(const Scene& scene, const Handle& handle, Field field) {
  if (handle.type == rope_type) return scene.rope_tension(handle.index);
  const b2Body* body = handle.body;
  if (handle.type == body_type) {
    // As in the CSV: a body's x, y are its origin and its vx, vy its centre of mass's velocity.
    b2Vec2 p = handle.at_point ? body->GetWorldPoint(handle.point) : body->GetPosition();
    if (handle.frame != nullptr) p = handle.frame->GetLocalPoint(p);
    const b2Vec2 v = handle.at_point ? body->GetLinearVelocityFromLocalPoint(handle.point) : body->GetLinearVelocity();
    switch (field) {
      case Field::x: return p.x;
      case Field::y: return p.y;
      case Field::angle: return body->GetAngle() / degrees;
      case Field::vx: return v.x;
      case Field::vy: return v.y;
      case Field::omega: return body->GetAngularVelocity();
      case Field::mass: return body->GetMass();
      case Field::distance: return b2Dot(p - handle.start, handle.along);
      case Field::speed: return b2Dot(v, handle.along);
      default: return 0.0;
    }
  }
  if (handle.type == spring_type) {
    const Spring& spring = scene.springs()[handle.index];
    if (field == Field::force_x || field == Field::force_y) {
      const b2Vec2 force = scene.spring_force(spring);
      return field == Field::force_x ? force.x : force.y;
    }
    const double length = (scene.hand_position(spring) - spring.body->GetWorldPoint(spring.local_point)).Length();
    return field == Field::length ? length : spring.stiffness * (length - spring.rest_length);
  }
  if (handle.type == force_type) {
    const AppliedForce& applied = scene.applied_forces()[handle.index];
    if (field == Field::torque) return applied.torque ? applied.torque(scene.time()) : 0.0;
    const b2Vec2 now = applied.force(scene.time());
    return field == Field::fx ? now.x : now.y;
  }
  const b2Body* a = handle.contact.a;
  const ContactRecord* record = find_record(scene, handle.contact);
  if (record == nullptr) return 0.0;
  const b2Vec2 drag = record->side(a) * static_cast<float>(record->solver.damping_force) * record->tangent();
  // Friction here is all the surface does along itself: the dry part and the drag.
  const b2Vec2 friction = record->friction_on(a) + drag;
  const b2Vec2 normal = record->normal_on(a);
  switch (field) {
    case Field::friction: return friction.Length();
    case Field::fx: return friction.x;
    case Field::fy: return friction.y;
    case Field::normal: return normal.Length();
    case Field::nx: return normal.x;
    case Field::ny: return normal.y;
    case Field::drag: return drag.Length();
    case Field::drag_x: return drag.x;
    case Field::drag_y: return drag.y;
    case Field::sliding_speed: return std::abs(record->solver.sliding_velocity);
    case Field::points: return record->solver.point_count;
    case Field::slipping: return record->seen_slipping() ? 1.0 : 0.0;
    case Field::load1: return record->solver.point_normal_force[0];
    case Field::load2: return record->solver.point_normal_force[1];
    case Field::load_left:
    case Field::load_right: {
      // With one point, it is on the side of body a's centre it lies on.
      const b2Vec2* points = record->solver.world_points;
      const float middle = record->solver.point_count == 2 ? 0.5f * (points[0].x + points[1].x) : a->GetPosition().x;
      double load = 0.0;
      for (int i = 0; i < record->solver.point_count; ++i) {
        const bool left = record->solver.world_points[i].x < middle;
        if (left == (field == Field::load_left)) load += record->solver.point_normal_force[i];
      }
      return load;
    }
    default: return 0.0;
  }
}

// `in_lua`: the fields a script reads with a dot; distance, speed and acceleration need a
// probe's direction.
std::string field_list(HandleType type, bool in_lua = false) {
  std::string list;
  for (const FieldName& known : field_names(type)) {
    if (in_lua && directed_field(known.field)) continue;
    list += (list.empty() ? "" : ", ") + std::string(known.name);
  }
  return list;
}

const char* const handle_words[] = {"a body", "a spring", "a force", "a contact", "a rope"};

int world_point(lua_State* state) {
  return guarded(state, [&] {
    const b2Body* of = body_handle(state, 1, "world_point's body (call it as body:world_point(x, y))")->body;
    const b2Vec2 local{static_cast<float>(luaL_optnumber(state, 2, 0.0)), static_cast<float>(luaL_optnumber(state, 3, 0.0))};
    const b2Vec2 world = of->GetWorldPoint(local);
    lua_pushnumber(state, world.x);
    lua_pushnumber(state, world.y);
    return 2;
  });
}

// block:set_velocity(vx, vy) and block:scale_velocity(factor), as a game changes a body's
// velocity between frames. Only from an every_step function: there the frame is over, so the
// next step starts from the new velocity, the record (and a replay) holds it, and the ledger
// books the kinetic energy it gives or takes.
// These run every step in a lesson such as terrain's: the names in their messages are built
// only when a message is given.
b2Body* velocity_body(lua_State* state, const char* call) {
  auto* handle = static_cast<BodyHandle*>(handle_of(state, 1, body_type));
  if (handle == nullptr) handle = body_handle(state, 1, std::string(call) + "'s body (call it as block:" + call + "(...))");
  if (!build_of(state).in_every_step) {
    throw InvalidInput(std::string(call) + " works only inside an every_step function, between frames; a body's "
                       "starting velocity is given where it is made, as in velocity = { 2, 0 }");
  }
  return handle->body;
}

double velocity_argument(lua_State* state, int index, const char* call, const char* what, double limit,
                         const char* unit) {
  if (lua_type(state, index) != LUA_TNUMBER) {
    throw InvalidInput(std::string(call) + ": " + what + " must be a number, got " + describe(state, index));
  }
  const double value = lua_tonumber(state, index);
  if (!validation::in_range(value, -limit, limit, false)) {
    validation::require_in_range(std::string(call) + ": " + what, value, -limit, limit, false, unit);
  }
  return value;
}

void set_and_forget(lua_State* state, b2Body* body, double vx, double vy) {
  LessonBuild& build = build_of(state);
  for (const auto& [part, value] : {std::pair{"x", vx}, std::pair{"y", vy}}) {
    if (!validation::in_range(value, -1e4, 1e4, false)) {
      validation::require_in_range("body '" + body_name(state, body) + "': velocity " + part, value, -1e4, 1e4, false, " m/s");
    }
  }
  build.scene->set_velocity(body, {static_cast<float>(vx), static_cast<float>(vy)});
  for (const auto& memory : build.force_memories) memory->filled = 0;
}

int set_velocity(lua_State* state) {
  return guarded(state, [&] {
    b2Body* body = velocity_body(state, "set_velocity");
    const double vx = velocity_argument(state, 2, "set_velocity", "vx", 1e4, " m/s");
    const double vy = velocity_argument(state, 3, "set_velocity", "vy", 1e4, " m/s");
    set_and_forget(state, body, vx, vy);
    return 0;
  });
}

int scale_velocity(lua_State* state) {
  return guarded(state, [&] {
    b2Body* body = velocity_body(state, "scale_velocity");
    const double factor = velocity_argument(state, 2, "scale_velocity", "factor", 1e4, "");
    const b2Vec2 v = body->GetLinearVelocity();
    set_and_forget(state, body, factor * v.x, factor * v.y);
    return 0;
  });
}

std::string handle_name(lua_State* state, const Handle& handle) {
  const Scene& scene = *build_of(state).scene;
  switch (handle.type) {
    case body_type: return body_name(state, handle.body);
    case spring_type: return scene.springs()[handle.index].name;
    case force_type: return scene.applied_forces()[handle.index].name;
    case rope_type: return scene.ropes()[handle.index].name;
    case contact_type: break;
  }
  return "";
}

// __index of every handle type: its name (or a contact's state), a method, or a number.
// The type comes as the closure's upvalue, and Lua calls a metatable's __index only for values
// that carry it (the metatables are hidden from scripts), so the handle needs no checking here:
// field reads are the commonest thing a lesson's functions do.
std::optional<Handle> handle_at(lua_State* state, int index, HandleType type) {
  const void* data = lua_touserdata(state, index);
  if (data == nullptr) return std::nullopt;
  return copy_handle(data, type);
}

int handle_index(lua_State* state) {
  return guarded(state, [&] {
    const auto type = static_cast<HandleType>(lua_tointeger(state, lua_upvalueindex(1)));
    const std::optional<Handle> handle = handle_at(state, 1, type);
    if (!handle) throw InvalidInput("read a handle's fields with a dot, as in block.x");
    const char* key = lua_type(state, 2) == LUA_TSTRING ? lua_tostring(state, 2) : "?";
    const Scene& scene = *build_of(state).scene;
    if (std::strcmp(key, "state") == 0 && handle->type == contact_type) {  // asked every step: first
      const ContactRecord* record = find_record(scene, handle->contact);
      lua_pushstring(state, record == nullptr             ? "none"
                            : record->solver.frictionless       ? "frictionless"
                            : record->friction.state == ContactState::sticking ? "sticking"
                                                                      : "slipping");
    } else if (std::strcmp(key, "scale_velocity") == 0 && handle->type == body_type) {  // every step in terrain
      lua_pushcfunction(state, scale_velocity);
    } else if (const std::optional<Field> field = find_field(handle->type, key)) {
      if (directed_field(*field)) {
        throw InvalidInput(std::string("a body's ") + key + " needs a direction: read it in a probe, as in read = { block, \"" +
                           key + "\", along = { 1, 0 } }, or work it out from x, y, vx and vy");
      }
      lua_pushnumber(state, read_field(scene, *handle, *field));
    } else if (std::strcmp(key, "name") == 0 && handle->type != contact_type) {
      lua_pushstring(state, handle_name(state, *handle).c_str());
    } else if (std::strcmp(key, "world_point") == 0 && handle->type == body_type) {
      lua_pushcfunction(state, world_point);
    } else if (std::strcmp(key, "set_velocity") == 0 && handle->type == body_type) {
      lua_pushcfunction(state, set_velocity);
    } else {
      const std::string extra = handle->type == body_type      ? "name, world_point(x, y), set_velocity(vx, vy), "
                                                                 "scale_velocity(factor), "
                                : handle->type == contact_type ? "state, "
                                                               : "name, ";
      throw InvalidInput(std::string(handle_words[handle->type]) + " has no field '" +
                         (lua_type(state, 2) == LUA_TSTRING ? std::string(key) : describe(state, 2)) + "'; it has " +
                         extra + field_list(handle->type, true) +
                         (handle->type == body_type ? " (and, in a probe's read, distance, speed and acceleration)" : ""));
    }
    return 1;
  });
}

// print(block) and the like: what the handle is, by name.
int handle_text(lua_State* state) {
  const std::optional<Handle> handle = any_handle(state, 1);
  if (!handle) return 0;
  const Scene& scene = *build_of(state).scene;
  switch (handle->type) {
    case body_type: lua_pushfstring(state, "body '%s'", body_name(state, handle->body).c_str()); break;
    case spring_type: lua_pushfstring(state, "spring '%s'", scene.springs()[handle->index].name.c_str()); break;
    case force_type: lua_pushfstring(state, "force '%s'", scene.applied_forces()[handle->index].name.c_str()); break;
    case rope_type: lua_pushfstring(state, "rope '%s'", handle_name(state, *handle).c_str()); break;
    case contact_type:
      lua_pushfstring(state, "contact of '%s' and '%s'", body_name(state, handle->contact.a).c_str(),
                      body_name(state, handle->contact.b).c_str());
      break;
  }
  return 1;
}

int refuse_write(lua_State* state) {
  return guarded(state, [&]() -> int {
    throw InvalidInput("handles are read-only: a body moves by forces, springs and drive{} (or block:set_velocity(vx, vy) in "
                       "an every_step function), and its setup is given "
                       "where it is made");
  });
}

}  // namespace

void push_body(lua_State* state, b2Body* body, bool is_surface, b2Vec2 origin, b2Vec2 along, float length) {
  auto* handle = static_cast<BodyHandle*>(lua_newuserdatauv(state, sizeof(BodyHandle), 0));
  *handle = {body, is_surface, origin, along, length};
  luaL_setmetatable(state, type_names[body_type]);
}

void push_indexed(lua_State* state, HandleType type, size_t index) {
  auto* handle = static_cast<size_t*>(lua_newuserdatauv(state, sizeof(size_t), 0));
  *handle = index;
  luaL_setmetatable(state, type_names[type]);
}

// The userdata at `index` when its metatable is `type`'s. Probes call this every step, so the
// metatable is compared by address rather than looked up by name (luaL_testudata).
void* handle_of(lua_State* state, int index, HandleType type) {
  void* data = lua_touserdata(state, index);
  if (data == nullptr || !lua_getmetatable(state, index)) return nullptr;
  const void* metatable = lua_topointer(state, -1);
  lua_pop(state, 1);
  return metatable == build_of(state).metatables[type] ? data : nullptr;
}

// `what` is a plain C string so that the common case, a body, builds no message.
BodyHandle* body_handle(lua_State* state, int index, const char* what) {
  auto* handle = static_cast<BodyHandle*>(handle_of(state, index, body_type));
  if (handle == nullptr) {
    throw InvalidInput(std::string(what) + " must be a body (what box{}, circle{}, ground{} and the others return), got " +
                       describe(state, index));
  }
  return handle;
}

BodyHandle* body_handle(lua_State* state, int index, const std::string& what) { return body_handle(state, index, what.c_str()); }

std::string body_name(lua_State* state, const b2Body* body) {
  for (const auto& [name, known] : build_of(state).scene->bodies()) {
    if (known == body) return name;
  }
  return "?";
}

namespace {

// A body's acceleration along a direction, as a probe samples it after each frame: the change
// of its speed between two samples over the time between their velocities. Box2D's velocity
// after a (sub-)step is the one the step moved the body with, the middle of that step's time
// (lessons/reference/reading.md, section 8), so the velocity a sample reads belongs to t − h_sub/2. The first
// one's predecessor is the velocity the body was given at t = 0, or, for a body at rest then,
// which the scene takes to have been held until then, its 0 at −h_sub/2 (Scene::start). The
// reading is the acceleration at the middle of the two velocities' instants (t − h after the
// first frame, with one sub-step), exact for a constant acceleration and O(h²) otherwise. A
// probe is made anew each time the lesson is built, so a replay from t = 0 starts it afresh.
std::function<double()> acceleration_reading(const Scene& scene, const Handle& handle) {
  struct Sample {
    double speed, at;
  };
  const b2Vec2 start = handle.at_point ? handle.body->GetLinearVelocityFromLocalPoint(handle.point)
                                       : handle.body->GetLinearVelocity();
  const bool at_rest = handle.body->GetLinearVelocity().LengthSquared() == 0.0f && handle.body->GetAngularVelocity() == 0.0f;
  const double held_until = at_rest ? -0.5 * scene.frame_step() / scene.settings().substeps : 0.0;
  auto last = std::make_shared<Sample>(Sample{b2Dot(start, handle.along), held_until});
  return [&scene, h = handle, last] {
    const b2Vec2 v = h.at_point ? h.body->GetLinearVelocityFromLocalPoint(h.point) : h.body->GetLinearVelocity();
    const double speed = b2Dot(v, h.along);
    const double at = scene.time() - 0.5 * scene.frame_step() / scene.settings().substeps;
    const double acceleration = at > last->at ? (speed - last->speed) / (at - last->at) : 0.0;
    *last = {speed, at};
    return h.scale * acceleration;
  };
}

// The kind of force a handle's field is, if it is one.
std::optional<ForceKind> force_kind_of(HandleType type, Field field) {
  switch (type) {
    case force_type:
      if (field == Field::fx || field == Field::fy) return ForceKind::applied;
      return std::nullopt;  // a torque
    case spring_type:
      if (field == Field::force_x || field == Field::force_y || field == Field::tension) return ForceKind::spring;
      return std::nullopt;  // a length
    case rope_type: return ForceKind::tension;
    case contact_type:
      switch (field) {
        case Field::friction: case Field::fx: case Field::fy: return ForceKind::friction;
        case Field::normal: case Field::nx: case Field::ny: case Field::load1: case Field::load2:
        case Field::load_left: case Field::load_right: return ForceKind::normal;
        case Field::drag: case Field::drag_x: case Field::drag_y: return ForceKind::drag;
        default: return std::nullopt;  // a sliding speed, a state, a count of points
      }
    case body_type: break;
  }
  return std::nullopt;
}

}  // namespace

std::function<double()> reading(lua_State* state, int index, const std::string& what, std::optional<ForceKind>* force) {
  index = lua_absindex(state, index);
  const std::string expected = what + ": read must name a handle and one of its numbers, as in read = { block, \"vx\" }";
  if (!lua_istable(state, index)) throw InvalidInput(expected + "; got " + describe(state, index));
  Fields options(state, index, what + ": read", {"at", "along", "scale", "relative_to"});
  lua_rawgeti(state, index, 1);
  std::optional<Handle> handle = any_handle(state, -1);
  lua_rawgeti(state, index, 2);
  const char* key = lua_type(state, -1) == LUA_TSTRING ? lua_tostring(state, -1) : nullptr;
  const std::optional<Field> field = handle && key ? find_field(handle->type, key) : std::nullopt;
  if (!field) {
    const std::string fields = handle ? "; " + std::string(handle_words[handle->type]) + " has " + field_list(handle->type) : "";
    lua_pop(state, 2);
    throw InvalidInput(expected + fields);
  }
  lua_pop(state, 2);
  const bool directed = directed_field(*field);
  const bool pointwise = *field == Field::x || *field == Field::y || *field == Field::vx || *field == Field::vy || directed;
  if (options.has("at") && !pointwise) {
    throw InvalidInput(what + ": at is for a body's x, y, vx, vy, distance, speed and acceleration");
  }
  if (directed != options.has("along")) {
    throw InvalidInput(what + (directed ? ": " + std::string(key) + " needs along = { dx, dy }, the direction it is measured in"
                                        : ": along is only for a body's distance, speed and acceleration"));
  }
  handle->at_point = options.has("at");
  handle->point = options.point("at", origin_point);
  if (options.has("relative_to")) {
    if (handle->type != body_type || (*field != Field::x && *field != Field::y && *field != Field::distance)) {
      throw InvalidInput(what + ": relative_to is for a body's x, y and distance (positions in the other body's axes)");
    }
    options.push("relative_to");
    handle->frame = body_handle(state, -1, what + ": relative_to")->body;
    lua_pop(state, 1);
    if (handle->frame == handle->body) throw InvalidInput(what + ": relative_to names the body read; name another body");
  }
  if (directed) {
    const b2Vec2 along = options.point("along", origin_point);
    if (along.Length() < 1e-6f) throw InvalidInput(what + ": along must be a direction, not {0, 0}");
    handle->along = (1.0f / along.Length()) * along;
    // Distance counts from where the point starts (in the other body's axes with relative_to).
    handle->start = handle->body->GetWorldPoint(handle->point);
    if (handle->frame != nullptr) handle->start = handle->frame->GetLocalPoint(handle->start);
  }
  handle->scale = options.number("scale", "", 1.0);
  if (force) *force = force_kind_of(handle->type, *field);
  const Scene* scene = build_of(state).scene.get();
  if (*field == Field::acceleration) return acceleration_reading(*scene, *handle);
  return [scene, h = *handle, f = *field] { return h.scale * read_field(*scene, h, f); };
}

void register_handles(lua_State* state) {
  lua_pushcfunction(state, contact);
  lua_setglobal(state, "contact");
  for (const HandleType type : {body_type, spring_type, force_type, contact_type, rope_type}) {
    luaL_newmetatable(state, type_names[type]);
    build_of(state).metatables[type] = lua_topointer(state, -1);
    lua_pushinteger(state, type);
    lua_pushcclosure(state, handle_index, 1);
    lua_setfield(state, -2, "__index");
    const luaL_Reg methods[] = {{"__newindex", refuse_write}, {"__tostring", handle_text}, {nullptr, nullptr}};
    luaL_setfuncs(state, methods, 0);
    // Hidden from getmetatable: a __gc a script added here would be given to every handle made
    // afterwards, and Lua runs finalizers where the sandbox's budgets cannot stop them.
    lua_pushliteral(state, "frictionlab handle");
    lua_setfield(state, -2, "__metatable");
    lua_pop(state, 1);
  }
}

}  // namespace frictionlab::lessons
