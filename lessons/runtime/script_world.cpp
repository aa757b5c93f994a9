// The world part of the script API: ground, boxes, circles, polygons and inclines; springs,
// ropes over pulleys, applied forces and driven bodies; and what a script may read back
// (bodies, springs, forces, contacts) while the lesson runs.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>

#include "lessons/runtime/build.h"
#include "physics/validation.h"

namespace frictionlab::lessons {
namespace {

constexpr double degrees = std::numbers::pi / 180.0;
// The handle types a script holds, each with its own metatable.
enum HandleType { body_type, spring_type, force_type, contact_type };
const char* const type_names[] = {"frictionlab.body", "frictionlab.spring", "frictionlab.force", "frictionlab.contact"};

// A body as the script holds it. Ground and inclines also carry their surface, a line along
// which `on = ..., at = s` places things: origin, and the unit direction s grows in.
struct BodyHandle {
  b2Body* body;
  bool is_surface;
  b2Vec2 origin;
  b2Vec2 along;
};
struct SpringHandle {
  size_t index;
};
struct ForceHandle {
  size_t index;
};

void require_building(lua_State* state, const char* call) {
  if (!build_of(state).building) {
    throw InvalidInput(std::string(call) + " adds to the world; call it at the top level of the script, not from a "
                       "function that runs during the lesson");
  }
}

// b2Vec2's default constructor leaves it uninitialised: every default here is spelled out.
const b2Vec2 origin_point{0.0f, 0.0f};

void push_body(lua_State* state, b2Body* body, bool is_surface = false, b2Vec2 origin = origin_point,
               b2Vec2 along = {1.0f, 0.0f}) {
  auto* handle = static_cast<BodyHandle*>(lua_newuserdatauv(state, sizeof(BodyHandle), 0));
  *handle = {body, is_surface, origin, along};
  luaL_setmetatable(state, type_names[body_type]);
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

b2BodyType body_kind(Fields& fields, const char* fallback) {
  const std::string kind = fields.text("kind", fallback);
  if (kind == "dynamic") return b2_dynamicBody;
  if (kind == "static") return b2_staticBody;
  if (kind == "kinematic") return b2_kinematicBody;
  throw InvalidInput(fields.what() + ": kind must be \"dynamic\", \"static\" or \"kinematic\", got \"" + kind + "\"");
}

struct Placement {
  b2Vec2 position;
  float angle;
};

// Where a body goes: at x, y and angle (degrees), or resting on a surface, `at` metres along
// it, lifted by `lift` (its centre's height above the surface plus Box2D's resting gap).
Placement place(lua_State* state, Fields& fields, float lift) {
  float angle = static_cast<float>(fields.number("angle", "°", 0.0) * degrees);
  if (!fields.has("on")) {
    if (fields.has("at")) throw InvalidInput(fields.what() + ": at needs on, as in on = slope, at = 1.5");
    return {{static_cast<float>(fields.number("x", "m", 0.0)), static_cast<float>(fields.number("y", "m", 0.0))}, angle};
  }
  if (fields.has("x") || fields.has("y")) throw InvalidInput(fields.what() + ": give either on = ... or x and y, not both");
  fields.push("on");
  const BodyHandle* surface = body_handle(state, -1, fields.what() + ": on");
  if (!surface->is_surface) throw InvalidInput(fields.what() + ": on must be a ground{} or an incline{}");
  const b2Vec2 origin = surface->origin, along = surface->along;
  lua_pop(state, 1);
  const float at = static_cast<float>(fields.number("at", "m", 0.0));
  const b2Vec2 normal{-along.y, along.x};
  return {origin + at * along + lift * normal, angle + std::atan2(along.y, along.x)};
}

// What every body may also be given: a mass (instead of its material's density), a starting
// velocity and spin, and no rotation at all.
void finish_body(Fields& fields, b2Body* body, double area) {
  if (fields.has("mass")) {
    if (body->GetType() != b2_dynamicBody) throw InvalidInput(fields.what() + ": only a dynamic body has a mass to set");
    const double mass = fields.number_in("mass", "kg", 1.0, 0.0, 1e6, true);
    body->GetFixtureList()->SetDensity(static_cast<float>(mass / area));
    body->ResetMassData();
  }
  const b2Vec2 velocity = fields.point("velocity", origin_point);
  body->SetLinearVelocity(velocity);
  body->SetAngularVelocity(static_cast<float>(fields.number("spin", "rad/s", 0.0)));
  if (fields.flag("fixed_rotation").value_or(false)) body->SetFixedRotation(true);
}

std::string required_material(LessonBuild& build, Fields& fields) {
  const std::string material = fields.text("material", "");
  if (material.empty()) throw InvalidInput(fields.what() + ": material is missing, as in material = \"wood\"");
  build.use_material(material);
  return material;
}

int ground(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "ground");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "ground", {"material", "y"});
    lua_rawgeti(state, 1, 1);
    const std::string name = lua_type(state, -1) == LUA_TSTRING ? fields.name() : "ground";
    lua_pop(state, 1);
    const std::string material = required_material(build, fields);
    const float top = static_cast<float>(fields.number("y", "m", 0.0));
    constexpr float width = 400.0f, thickness = 1.0f;
    b2Body* body = build.scene->add_box(name, b2_staticBody, material, {0.0f, top - 0.5f * thickness}, width, thickness);
    push_body(state, body, true, {0.0f, top}, {1.0f, 0.0f});
    return 1;
  });
}

int box(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "box");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "box", {"material", "width", "height", "x", "y", "angle", "on", "at", "mass", "kind",
                                    "velocity", "spin", "fixed_rotation"});
    const std::string name = fields.name();
    const std::string material = required_material(build, fields);
    const double width = fields.number("width", "m"), height = fields.number("height", "m");
    const Placement where = place(state, fields, static_cast<float>(0.5 * height) + resting_gap);
    b2Body* body = build.scene->add_box(name, body_kind(fields, "dynamic"), material, where.position,
                                        static_cast<float>(width), static_cast<float>(height), where.angle);
    finish_body(fields, body, width * height);
    push_body(state, body);
    return 1;
  });
}

int circle(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "circle");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "circle", {"material", "radius", "x", "y", "angle", "on", "at", "mass", "kind", "velocity",
                                       "spin", "fixed_rotation"});
    const std::string name = fields.name();
    const std::string material = required_material(build, fields);
    const double radius = fields.number_in("radius", "m", 0.01, 1000.0);
    // A circle rests closer than a polygon: only the polygon has a skin.
    const Placement where = place(state, fields, static_cast<float>(radius) + b2_polygonRadius - b2_linearSlop);
    b2BodyDef definition;
    definition.type = body_kind(fields, "dynamic");
    definition.position = where.position;
    definition.angle = where.angle;
    b2Body* body = build.scene->add_body(name, definition);
    b2CircleShape shape;
    shape.m_radius = static_cast<float>(radius);
    build.scene->add_fixture(body, shape, material);
    finish_body(fields, body, std::numbers::pi * radius * radius);
    push_body(state, body);
    return 1;
  });
}

// Box2D aborts on a degenerate polygon, so the script's points are checked first: 3 to 8 of
// them, in convex order, no two closer than 1 cm, enclosing some area.
std::vector<b2Vec2> convex_points(lua_State* state, Fields& fields) {
  const std::string expected = fields.what() + ": points must list 3 to " + std::to_string(b2_maxPolygonVertices) +
                               " corners, as in points = { {0, 0}, {2, 0}, {2, 1} }";
  fields.push("points");
  if (!lua_istable(state, -1)) throw InvalidInput(expected);
  const auto count = static_cast<int>(lua_rawlen(state, -1));
  if (count < 3 || count > b2_maxPolygonVertices) throw InvalidInput(expected);
  std::vector<b2Vec2> points;
  for (int i = 1; i <= count; ++i) {
    lua_rawgeti(state, -1, i);
    double xy[2] = {NAN, NAN};
    for (int j = 0; j < 2 && lua_istable(state, -1); ++j) {
      lua_rawgeti(state, -1, j + 1);
      if (lua_type(state, -1) == LUA_TNUMBER) xy[j] = lua_tonumber(state, -1);
      lua_pop(state, 1);
    }
    lua_pop(state, 1);
    if (!std::isfinite(xy[0]) || !std::isfinite(xy[1])) throw InvalidInput(expected + "; corner " + std::to_string(i) + " is not");
    points.push_back({static_cast<float>(xy[0]), static_cast<float>(xy[1])});
  }
  lua_pop(state, 1);
  double area = 0.0;
  int turning = 0;
  for (int i = 0; i < count; ++i) {
    const b2Vec2 a = points[i], b = points[(i + 1) % count], c = points[(i + 2) % count];
    if ((b - a).Length() < 0.01f) throw InvalidInput(fields.what() + ": corners " + std::to_string(i + 1) + " and " +
                                                     std::to_string((i + 1) % count + 1) + " are less than 1 cm apart");
    const double turn = b2Cross(b - a, c - b);
    turning += turn > 1e-9 ? 1 : turn < -1e-9 ? -1 : 0;
    area += 0.5 * b2Cross(a, b);
  }
  if (std::abs(turning) != count) {
    throw InvalidInput(fields.what() + ": the corners must go round a convex shape in order, with no three in a line");
  }
  if (std::abs(area) < 1e-4) throw InvalidInput(fields.what() + ": the shape encloses almost no area");
  return points;
}

int polygon(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "polygon");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "polygon", {"material", "points", "x", "y", "angle", "mass", "kind", "velocity", "spin",
                                        "fixed_rotation"});
    const std::string name = fields.name();
    const std::string material = required_material(build, fields);
    const std::vector<b2Vec2> points = convex_points(state, fields);
    const Placement where = place(state, fields, 0.0f);
    b2BodyDef definition;
    definition.type = body_kind(fields, "dynamic");
    definition.position = where.position;
    definition.angle = where.angle;
    b2Body* body = build.scene->add_body(name, definition);
    b2PolygonShape shape;
    shape.Set(points.data(), static_cast<int32>(points.size()));
    build.scene->add_fixture(body, shape, material);
    b2MassData unit;
    shape.ComputeMass(&unit, 1.0f);
    finish_body(fields, body, unit.mass);
    push_body(state, body);
    return 1;
  });
}

// A fixed wedge whose slope rises to the right from its foot; things placed on it with
// `at` sit that far up the slope.
int incline(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "incline");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "incline", {"material", "angle", "length", "foot"});
    const std::string name = fields.name();
    const std::string material = required_material(build, fields);
    const double angle = fields.number_in("angle", "°", 0.0, 80.0, true) * degrees;
    const double length = fields.number_in("length", "m", 4.0, 0.1, 1000.0);
    if (length * std::sin(angle) < 0.02) {
      throw InvalidInput(fields.what() + ": the wedge would be less than 2 cm high; make it steeper or longer");
    }
    const b2Vec2 foot = fields.point("foot", {0.0f, 0.0f});
    const b2Vec2 along{static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
    const float run = static_cast<float>(length) * along.x, rise = static_cast<float>(length) * along.y;
    const b2Vec2 corners[] = {{0.0f, 0.0f}, {run, 0.0f}, {run, rise}};
    b2BodyDef definition;
    definition.position = foot;
    b2Body* body = build.scene->add_body(name, definition);
    b2PolygonShape shape;
    shape.Set(corners, 3);
    build.scene->add_fixture(body, shape, material);
    push_body(state, body, true, foot, along);
    return 1;
  });
}

// A function of time the script gave for a body, a hand or a force: called with t, it must
// return `count` numbers.
// Functions of time are taken to depend on t (and parameters) alone, so an answer for the
// same t is reused.
std::function<std::array<double, 2>(double)> function_of_time(LessonBuild& build, int reference, int count,
                                                              std::string what) {
  LessonBuild* owner = &build;
  auto memory = std::make_shared<RememberedValues>();
  build.remembered.push_back(memory);
  return [owner, reference, count, what, memory](double t) {
    for (int i = 0; i < memory->filled; ++i) {
      if (memory->times[i] == t) return memory->values[i];
    }
    owner->call(reference, {t}, count);
    std::array<double, 2> answer{0.0, 0.0};
    owner->numbers_returned(reference, count, what, answer.data());
    memory->times[memory->next] = t;
    memory->values[memory->next] = answer;
    memory->next ^= 1;
    memory->filled = std::min(memory->filled + 1, 2);
    return answer;
  };
}

int spring(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "spring");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "spring", {"from", "at", "to", "to_at", "k", "rest_length"});
    Spring made;
    made.name = fields.name();
    fields.push("from");
    made.body = body_handle(state, -1, fields.what() + ": from")->body;
    lua_pop(state, 1);
    made.local_point = fields.point("at", origin_point);
    fields.push("to");
    if (lua_isfunction(state, -1)) {
      const auto hand = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 2,
                                         fields.what() + ": the hand function (t -> x, y in m)");
      made.hand = [hand](double t) {
        const std::array<double, 2> xy = hand(t);
        return b2Vec2{static_cast<float>(xy[0]), static_cast<float>(xy[1])};
      };
      if (fields.has("to_at")) throw InvalidInput(fields.what() + ": to_at is for a spring between two bodies");
    } else if (lua_isnil(state, -1)) {
      throw InvalidInput(fields.what() + ": to is missing: a body, or a function(t) returning where the hand is");
    } else {
      made.other = body_handle(state, -1, fields.what() + ": to")->body;
      lua_pop(state, 1);
      made.other_local_point = fields.point("to_at", origin_point);
    }
    made.stiffness = fields.number("k", "N/m");
    const b2Vec2 far_end = made.other ? made.other->GetWorldPoint(made.other_local_point) : made.hand(0.0);
    const double length = (far_end - made.body->GetWorldPoint(made.local_point)).Length();
    made.rest_length = fields.number("rest_length", "m", length);  // unstretched at the start unless told
    build.scene->add_spring(made);
    auto* handle = static_cast<SpringHandle*>(lua_newuserdatauv(state, sizeof(SpringHandle), 0));
    handle->index = build.scene->springs().size() - 1;
    luaL_setmetatable(state, type_names[spring_type]);
    return 1;
  });
}

int rope(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "rope");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "rope", {"from", "at", "over", "to", "to_at"});
    const std::string name = fields.name();
    fields.push("from");
    b2Body* from = body_handle(state, -1, fields.what() + ": from")->body;
    fields.push("to");
    b2Body* to = body_handle(state, -1, fields.what() + ": to")->body;
    lua_pop(state, 2);
    if (!fields.has("over")) throw InvalidInput(fields.what() + ": over is missing: where the pulley is, as in over = {2, 1}");
    const b2Vec2 pulley = fields.point("over", origin_point);
    const b2Vec2 a = from->GetWorldPoint(fields.point("at", origin_point)), b = to->GetWorldPoint(fields.point("to_at", origin_point));
    for (const b2Vec2 end : {a, b}) {
      if ((end - pulley).Length() < 0.05f) throw InvalidInput(fields.what() + ": each end must start at least 5 cm from the pulley");
    }
    b2PulleyJointDef definition;
    definition.Initialize(from, to, pulley, pulley, a, b, 1.0f);
    build.ropes.push_back({name, build.scene->world().CreateJoint(&definition)});
    return 0;
  });
}

int force(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "force");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "force", {"on", "at", "force"});
    AppliedForce made;
    made.name = fields.name();
    fields.push("on");
    made.body = body_handle(state, -1, fields.what() + ": on")->body;
    lua_pop(state, 1);
    made.local_point = fields.point("at", origin_point);
    if (fields.push_function("force")) {
      const auto push = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 2,
                                         fields.what() + ": the force function (t -> fx, fy in N)");
      made.force = [push](double t) {
        const std::array<double, 2> f = push(t);
        return b2Vec2{static_cast<float>(f[0]), static_cast<float>(f[1])};
      };
    } else {
      if (!fields.has("force")) throw InvalidInput(fields.what() + ": force is missing: {fx, fy} in N, or a function(t)");
      const b2Vec2 constant = fields.point("force", origin_point);
      made.force = [constant](double) { return constant; };
    }
    build.scene->add_applied_force(made);
    auto* handle = static_cast<ForceHandle*>(lua_newuserdatauv(state, sizeof(ForceHandle), 0));
    handle->index = build.scene->applied_forces().size() - 1;
    luaL_setmetatable(state, type_names[force_type]);
    return 1;
  });
}

int drive(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "drive");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "drive", {"position", "angle"});
    lua_rawgeti(state, 1, 1);
    b2Body* body = body_handle(state, -1, "drive's first entry (the body to move, as in drive{ belt, position = ... })")->body;
    lua_pop(state, 1);
    const std::string what = "drive '" + body_name(state, body) + "'";
    if (body->GetType() != b2_kinematicBody) throw InvalidInput(what + ": only a body of kind = \"kinematic\" can be driven");
    VectorOfTime position;
    ScalarOfTime angle;
    if (fields.push_function("position")) {
      const auto path = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 2, what + ": position (t -> x, y in m)");
      position = [path](double t) {
        const std::array<double, 2> xy = path(t);
        return b2Vec2{static_cast<float>(xy[0]), static_cast<float>(xy[1])};
      };
    } else {
      const b2Vec2 fixed = body->GetPosition();
      position = [fixed](double) { return fixed; };
    }
    if (fields.push_function("angle")) {
      const auto turn = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 1, what + ": angle (t -> degrees)");
      angle = [turn](double t) { return turn(t)[0] * degrees; };
    } else {
      const double fixed = body->GetAngle();
      angle = [fixed](double) { return fixed; };
    }
    build.scene->drive(body, position, angle);
    return 0;
  });
}

// contact(a, b): a view of what the friction listener recorded for the touching pair, read
// when a field is read. A view rather than a table of copies: probes ask every step, and
// building sixteen fields to read one was most of a lesson's script time.
struct ContactHandle {
  const b2Body* a;
  const b2Body* b;
};

int contact(lua_State* state) {
  return guarded(state, [&] {
    const b2Body* a = body_handle(state, 1, "contact's first argument")->body;
    const b2Body* b = body_handle(state, 2, "contact's second argument")->body;
    auto* handle = static_cast<ContactHandle*>(lua_newuserdatauv(state, sizeof(ContactHandle), 0));
    *handle = {a, b};
    luaL_setmetatable(state, type_names[contact_type]);
    return 1;
  });
}

// What a script can read from a handle. One table serves both `block.vx` in Lua and
// probe{ read = { block, "vx" } }, which the runtime reads itself every step without Lua.
enum class Field { x, y, angle, vx, vy, omega, mass, force_x, force_y, length, tension, fx, fy, friction, normal, nx,
                   ny, drag, drag_x, drag_y, sliding_speed, points, load1, load2 };
struct FieldName {
  const char* name;
  Field field;
};
const std::vector<FieldName>& field_names(HandleType type) {
  static const std::vector<FieldName> body = {{"x", Field::x},   {"y", Field::y},         {"angle", Field::angle},
                                              {"vx", Field::vx}, {"vy", Field::vy},       {"omega", Field::omega},
                                              {"mass", Field::mass}};
  static const std::vector<FieldName> spring = {{"force_x", Field::force_x}, {"force_y", Field::force_y},
                                                {"length", Field::length}, {"tension", Field::tension}};
  static const std::vector<FieldName> force = {{"fx", Field::fx}, {"fy", Field::fy}};
  static const std::vector<FieldName> contact = {
      {"friction", Field::friction}, {"fx", Field::fx},         {"fy", Field::fy},
      {"normal", Field::normal},     {"nx", Field::nx},         {"ny", Field::ny},
      {"drag", Field::drag},         {"drag_x", Field::drag_x}, {"drag_y", Field::drag_y},
      {"sliding_speed", Field::sliding_speed}, {"points", Field::points}, {"load1", Field::load1},
      {"load2", Field::load2}};
  switch (type) {
    case body_type: return body;
    case spring_type: return spring;
    case force_type: return force;
    case contact_type: break;
  }
  return contact;
}

// A handle copied out of its userdata, so the runtime can keep reading it.
struct Handle {
  HandleType type;
  const b2Body* body = nullptr;   // a body
  size_t index = 0;               // a spring or a force
  ContactHandle contact{nullptr, nullptr};
};

std::optional<Handle> any_handle(lua_State* state, int index) {
  for (const HandleType type : {body_type, spring_type, force_type, contact_type}) {
    const void* data = handle_of(state, index, type);
    if (data == nullptr) continue;
    Handle handle{type};
    if (type == body_type) handle.body = static_cast<const BodyHandle*>(data)->body;
    if (type == spring_type) handle.index = static_cast<const SpringHandle*>(data)->index;
    if (type == force_type) handle.index = static_cast<const ForceHandle*>(data)->index;
    if (type == contact_type) handle.contact = *static_cast<const ContactHandle*>(data);
    return handle;
  }
  return std::nullopt;
}

std::optional<Field> find_field(HandleType type, const char* key) {
  for (const FieldName& known : field_names(type)) {
    if (std::strcmp(known.name, key) == 0) return known.field;
  }
  return std::nullopt;
}

double read_field(const Scene& scene, const Handle& handle, Field field) {
  const b2Body* body = handle.body;
  switch (field) {
    case Field::x: return body->GetPosition().x;
    case Field::y: return body->GetPosition().y;
    case Field::angle: return body->GetAngle() / degrees;
    case Field::vx: return body->GetLinearVelocity().x;
    case Field::vy: return body->GetLinearVelocity().y;
    case Field::omega: return body->GetAngularVelocity();
    case Field::mass: return body->GetMass();
    default: break;
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
    const b2Vec2 now = scene.applied_forces()[handle.index].force(scene.time());
    return field == Field::fx ? now.x : now.y;
  }
  const b2Body* a = handle.contact.a;
  const ContactRecord* record = scene.friction().find(a, handle.contact.b);
  if (record == nullptr) return 0.0;
  const b2Vec2 drag = record->side(a) * static_cast<float>(record->damping_force) * record->tangent();
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
    case Field::sliding_speed: return std::abs(record->sliding_velocity);
    case Field::points: return record->point_count;
    case Field::load1: return record->point_normal_force[0];
    case Field::load2: return record->point_normal_force[1];
    default: return 0.0;
  }
}

std::string field_list(HandleType type) {
  std::string list;
  for (const FieldName& known : field_names(type)) list += (list.empty() ? "" : ", ") + std::string(known.name);
  return list;
}

const char* const handle_words[] = {"a body", "a spring", "a force", "a contact"};

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

// __index of every handle type: its name (or a contact's state), a method, or a number.
int handle_index(lua_State* state) {
  return guarded(state, [&] {
    const std::optional<Handle> handle = any_handle(state, 1);
    if (!handle) throw InvalidInput("read a handle's fields with a dot, as in block.x");
    const char* key = lua_type(state, 2) == LUA_TSTRING ? lua_tostring(state, 2) : "?";
    const Scene& scene = *build_of(state).scene;
    if (std::strcmp(key, "state") == 0 && handle->type == contact_type) {  // asked every step: first
      const ContactRecord* record = scene.friction().find(handle->contact.a, handle->contact.b);
      lua_pushstring(state, record == nullptr ? "none" : record->state == ContactState::sticking ? "sticking" : "slipping");
    } else if (const std::optional<Field> field = find_field(handle->type, key)) {
      lua_pushnumber(state, read_field(scene, *handle, *field));
    } else if (std::strcmp(key, "name") == 0 && handle->type != contact_type) {
      const std::string name = handle->type == body_type     ? body_name(state, handle->body)
                               : handle->type == spring_type ? scene.springs()[handle->index].name
                                                             : scene.applied_forces()[handle->index].name;
      lua_pushstring(state, name.c_str());
    } else if (std::strcmp(key, "world_point") == 0 && handle->type == body_type) {
      lua_pushcfunction(state, world_point);
    } else {
      const std::string extra = handle->type == body_type      ? "name, world_point(x, y), "
                                : handle->type == contact_type ? "state, "
                                                               : "name, ";
      throw InvalidInput(std::string(handle_words[handle->type]) + " has no field '" +
                         (lua_type(state, 2) == LUA_TSTRING ? std::string(key) : describe(state, 2)) + "'; it has " +
                         extra + field_list(handle->type));
    }
    return 1;
  });
}

int body_text(lua_State* state) {
  lua_pushfstring(state, "body '%s'", body_name(state, static_cast<BodyHandle*>(lua_touserdata(state, 1))->body).c_str());
  return 1;
}

void add_type(lua_State* state, HandleType type, lua_CFunction index) {
  luaL_newmetatable(state, type_names[type]);
  build_of(state).metatables[type] = lua_topointer(state, -1);
  lua_pushcfunction(state, index);
  lua_setfield(state, -2, "__index");
  lua_pop(state, 1);
}

}  // namespace

std::function<double()> reading(lua_State* state, int index, const std::string& what) {
  index = lua_absindex(state, index);
  const std::string expected = what + ": read must name a handle and one of its numbers, as in read = { block, \"vx\" }";
  if (!lua_istable(state, index)) throw InvalidInput(expected + "; got " + describe(state, index));
  lua_rawgeti(state, index, 1);
  const std::optional<Handle> handle = any_handle(state, -1);
  lua_rawgeti(state, index, 2);
  const char* key = lua_type(state, -1) == LUA_TSTRING ? lua_tostring(state, -1) : nullptr;
  const std::optional<Field> field = handle && key ? find_field(handle->type, key) : std::nullopt;
  if (!field) {
    const std::string fields = handle ? "; " + std::string(handle_words[handle->type]) + " has " + field_list(handle->type) : "";
    lua_pop(state, 2);
    throw InvalidInput(expected + fields);
  }
  lua_pop(state, 2);
  const Scene* scene = build_of(state).scene.get();
  return [scene, h = *handle, f = *field] { return read_field(*scene, h, f); };
}

b2Body* body_argument(lua_State* state, int index, const std::string& what) {
  return body_handle(state, index, what)->body;
}

void register_world_api(lua_State* state) {
  const luaL_Reg functions[] = {{"ground", ground}, {"box", box},       {"circle", circle}, {"polygon", polygon},
                                {"incline", incline}, {"spring", spring}, {"rope", rope},     {"force", force},
                                {"drive", drive},   {"contact", contact}, {nullptr, nullptr}};
  lua_pushglobaltable(state);
  luaL_setfuncs(state, functions, 0);
  lua_pop(state, 1);
  add_type(state, body_type, handle_index);
  luaL_getmetatable(state, type_names[body_type]);
  lua_pushcfunction(state, body_text);
  lua_setfield(state, -2, "__tostring");
  lua_pop(state, 1);
  add_type(state, spring_type, handle_index);
  add_type(state, force_type, handle_index);
  add_type(state, contact_type, handle_index);
}

}  // namespace frictionlab::lessons
