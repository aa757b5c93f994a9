// The world part of the script API: ground, boxes, circles, polygons and inclines; springs,
// ropes over pulleys, applied forces and driven bodies. What a script reads back from them is
// in handles.cpp.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "lessons/runtime/handles.h"
#include "physics/validation.h"

namespace frictionlab::lessons {
namespace {

void require_building(lua_State* state, const char* call) {
  require_top_level(state, std::string(call) + " adds to the world");
}

// What a script may build. Box2D looks at every pair of shapes whose boxes overlap, so a pile
// of n bodies on one spot costs about n² contacts a step: 2 000 boxes there took minutes for a
// dozen steps, where no budget of the script's own looks. The built-in lessons use at most a
// dozen bodies and a few dozen shapes; these limits leave room for ten times that, and keep a
// step of the worst pile (every body on one spot) to milliseconds.
constexpr int most_bodies = 100;
constexpr int most_shapes = 200;

// Called once a body is built (a failed build is thrown away whole, so it need not be undone).
void require_room(const Scene& scene, const std::string& what) {
  const b2World& world = scene.world();
  if (world.GetBodyCount() > most_bodies) {
    throw InvalidInput(what + ": a lesson builds at most " + std::to_string(most_bodies) +
                       " bodies (a pile of more would make every step slow); this is one too many");
  }
  int shapes = 0;
  for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext()) {
    for (const b2Fixture* shape = body->GetFixtureList(); shape != nullptr; shape = shape->GetNext()) ++shapes;
  }
  if (shapes > most_shapes) {
    throw InvalidInput(what + ": a lesson builds at most " + std::to_string(most_shapes) +
                       " shapes (a box on feet is one shape per foot and one for the box, a ground of strips two per "
                       "strip); this one would make " + std::to_string(shapes));
  }
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

struct TopFace {
  b2Vec2 centre;  // world
  float width;
};

// The flat top of a body something is placed on with on = body: the highest edge of its
// polygon, which must be level. A rotated body's top is refused rather than guessed (a box at
// 0.1° has a corner for a top), as is a circle's (nothing rests on one).
TopFace top_face(lua_State* state, Fields& fields, const b2Body* below) {
  const std::string what = fields.what() + ": on = " + body_name(state, below);
  if (below->GetAngle() != 0.0f) {
    throw InvalidInput(what + " is turned (angle ≠ 0); on = a body needs it level; place this one with x, y and angle");
  }
  // Its first fixture, the box itself: Box2D lists a body's fixtures newest first, and a box on
  // feet (box{ feet = n }) adds its feet after the box.
  const b2Fixture* fixture = below->GetFixtureList();
  while (fixture->GetNext() != nullptr) fixture = fixture->GetNext();
  if (fixture == nullptr || fixture->GetType() != b2Shape::e_polygon) {
    throw InvalidInput(what + " has no flat top face (only a box or a polygon has one); place this one with x and y");
  }
  const auto* shape = static_cast<const b2PolygonShape*>(fixture->GetShape());
  float top = -b2_maxFloat, left = b2_maxFloat, right = -b2_maxFloat;
  for (int i = 0; i < shape->m_count; ++i) top = std::max(top, shape->m_vertices[i].y);
  int on_top = 0;
  for (int i = 0; i < shape->m_count; ++i) {
    if (shape->m_vertices[i].y < top - 1e-5f) continue;
    ++on_top;
    left = std::min(left, shape->m_vertices[i].x);
    right = std::max(right, shape->m_vertices[i].x);
  }
  if (on_top < 2) throw InvalidInput(what + " has a corner on top, not a level face; place this one with x and y");
  return {below->GetWorldPoint({0.5f * (left + right), top}), right - left};
}

// Where a body goes: at x, y and angle (degrees), or resting on a surface, `at` metres along
// it, lifted by `lift` (its centre's height above the surface: a script's shapes rest on their
// surfaces, true_skin in physics/scene.h). The
// surface is a ground{} or an incline{}, or the level top face of any other body, `at` then
// measured from the face's middle.
Placement place(lua_State* state, Fields& fields, float lift) {
  // Checked here, in the script's own units and before single precision: the scene's own check
  // would report an angle in radians, and 1e39 m as "inf m".
  float angle = static_cast<float>(fields.number_in("angle", "°", 0.0, -360000.0, 360000.0) * degrees);
  if (!fields.has("on")) {
    if (fields.has("at")) throw InvalidInput(fields.what() + ": at needs on, as in on = slope, at = 1.5");
    return {{static_cast<float>(fields.number_in("x", "m", 0.0, -1e5, 1e5)),
             static_cast<float>(fields.number_in("y", "m", 0.0, -1e5, 1e5))},
            angle};
  }
  if (fields.has("x") || fields.has("y")) throw InvalidInput(fields.what() + ": give either on = ... or x and y, not both");
  fields.push("on");
  const BodyHandle* surface = body_handle(state, -1, fields.what() + ": on");
  if (!surface->is_surface) {
    const b2Body* below = surface->body;
    lua_pop(state, 1);
    const TopFace top = top_face(state, fields, below);
    const double half = 0.5 * top.width;
    const float at = static_cast<float>(fields.number_in("at", "m", 0.0, -half, half));
    return {{top.centre.x + at, top.centre.y + lift}, angle};
  }
  const b2Vec2 origin = surface->origin, along = surface->along;
  const float length = surface->length;
  const bool is_ground = along.y == 0.0f && along.x == 1.0f && origin.x == -0.5f * length;
  lua_pop(state, 1);
  // On the ground `at` is the x coordinate; on an incline, the distance up from its foot.
  const double low = is_ground ? -0.5 * length : 0.0, high = is_ground ? 0.5 * length : length;
  const float at = static_cast<float>(fields.number_in("at", "m", 0.0, low, high)) - static_cast<float>(low);
  const b2Vec2 normal{-along.y, along.x};
  return {origin + at * along + lift * normal, angle + std::atan2(along.y, along.x)};
}

// What every body may also be given: a mass (instead of its material's density), a starting
// velocity and spin, and no rotation at all.
void finish_body(Fields& fields, b2Body* body, double area) {
  if (fields.has("mass")) {
    if (body->GetType() != b2_dynamicBody) throw InvalidInput(fields.what() + ": only a dynamic body has a mass to set");
    // Box2D keeps masses in floats: far below a milligram a small body's mass and inertia lose
    // their digits, and Box2D aborts on an inertia that is no longer positive.
    const double mass = fields.number_in("mass", "kg", 1.0, 1e-6, 1e6);
    for (b2Fixture* part = body->GetFixtureList(); part != nullptr; part = part->GetNext()) {
      part->SetDensity(static_cast<float>(mass / area));  // a box on feet is several fixtures
    }
  }
  set_mass_from_surfaces(body);  // a circle's over the script's radius, not the one it collides with
  // The limits the scene puts on a body's starting motion (Scene::add_body), which the body
  // made before these were read did not see.
  const b2Vec2 velocity = fields.point("velocity", origin_point);
  validation::require_in_range(fields.what() + ": velocity x", velocity.x, -1e4, 1e4, false, " m/s");
  validation::require_in_range(fields.what() + ": velocity y", velocity.y, -1e4, 1e4, false, " m/s");
  body->SetLinearVelocity(velocity);
  body->SetAngularVelocity(static_cast<float>(fields.number_in("spin", "rad/s", 0.0, -1e4, 1e4)));
  if (fields.flag("fixed_rotation").value_or(false)) body->SetFixedRotation(true);
}

std::string required_material(LessonBuild& build, Fields& fields) {
  const std::string material = fields.text("material", "");
  if (material.empty()) throw InvalidInput(fields.what() + ": material is missing, as in material = \"wood\"");
  build.use_material(material);
  return material;
}

// box{ ..., feet = n }: n small feet spread evenly under the box, from its left edge to its
// right, each its own fixture, so each makes its own contact with the floor (a Box2D contact
// has at most two points: a face of n feet needs n fixtures).
struct Feet {
  int count = 0;
  double width = 0.0, height = 0.0;
};

Feet read_feet(Fields& fields, double width, double height) {
  if (!fields.has("feet")) {
    if (fields.has("foot_width") || fields.has("foot_height")) {
      throw InvalidInput(fields.what() + ": foot_width and foot_height go with feet = n");
    }
    return {};
  }
  const double count = fields.number_in("feet", "", 2.0, 16.0);
  if (count != std::floor(count)) throw InvalidInput(fields.what() + ": feet must be a whole number, from 2 to 16");
  Feet feet;
  feet.count = static_cast<int>(count);
  // Box2D's skin makes anything under 2 cm all skin; n feet must fit under the box side by side.
  feet.width = fields.number_in("foot_width", "m", 0.02, 0.02, width / feet.count);
  feet.height = fields.number_in("foot_height", "m", 0.02, 0.02, std::max(0.02, height));
  return feet;
}

std::vector<const b2Fixture*> add_feet(Scene& scene, b2Body* body, const std::string& material, const Feet& feet,
                                       double width, double height) {
  std::vector<const b2Fixture*> made;
  const double first = -0.5 * width + 0.5 * feet.width, gap = (width - feet.width) / (feet.count - 1);
  for (int i = 0; i < feet.count; ++i) {
    b2PolygonShape foot;
    const b2Vec2 centre{static_cast<float>(first + i * gap), static_cast<float>(-0.5 * height - 0.5 * feet.height)};
    foot.SetAsBox(static_cast<float>(0.5 * feet.width), static_cast<float>(0.5 * feet.height), centre, 0.0f);
    foot.m_radius = true_skin;
    made.push_back(scene.add_fixture(body, foot, material));
  }
  return made;
}

// A floor of several materials side by side: strips = { { "wood", to = 1.5 }, { "ice" } }, each
// strip from where the one before ends (the first from the left end) to its `to` (the last to
// the right end). Box2D snags a box sliding across the seam of two boxes side by side on the
// second one's corner (its "ghost collision"), so each strip's surface is a one-sided edge
// whose ghost vertices run on level past both its ends: the box meets a flat floor all the
// way, and each strip has its own material. Beneath each edge, a box of the strip's material
// that collides with nothing shows the floor's thickness.
struct Strip {
  std::string material;
  float from, to;
};

std::vector<Strip> read_strips(lua_State* state, Fields& fields, LessonBuild& build, float half_width) {
  fields.push("strips");
  const std::string what = fields.what() + ": strips";
  const lua_Integer count = lua_istable(state, -1) ? luaL_len(state, -1) : 0;
  if (count < 1 || count > 16) {
    lua_pop(state, 1);
    throw InvalidInput(what + " lists 1 to 16 strips from left to right, as in strips = { { \"wood\", to = 1.5 }, "
                       "{ \"ice\" } }");
  }
  std::vector<Strip> strips;
  float from = -half_width;
  for (lua_Integer i = 1; i <= count; ++i) {
    lua_rawgeti(state, -1, i);
    const std::string which = what + "[" + std::to_string(i) + "]";
    if (!lua_istable(state, -1)) {
      lua_pop(state, 2);
      throw InvalidInput(which + " must be a table, as in { \"ice\", to = 3 }");
    }
    Fields strip(state, lua_gettop(state), which, {"to"});
    lua_rawgeti(state, -1, 1);
    const bool named = lua_type(state, -1) == LUA_TSTRING;
    const std::string material = named ? lua_tostring(state, -1) : "";
    lua_pop(state, 1);
    if (!named) {
      lua_pop(state, 2);
      throw InvalidInput(which + " names its material first, as in { \"ice\", to = 3 }");
    }
    build.use_material(material);
    const bool last = i == count;
    if (last && strip.has("to")) {
      lua_pop(state, 2);
      std::ostringstream message;
      message << which << ": the last strip runs to the floor's right end, " << half_width << " m; give it no to";
      throw InvalidInput(message.str());
    }
    float to = half_width;
    if (!last) {
      if (!strip.has("to")) {
        lua_pop(state, 2);
        throw InvalidInput(which + ": to = where this strip ends (x in m) is missing");
      }
      // At least 2 cm wide, as any body; and ending before the floor does.
      to = static_cast<float>(strip.number_in("to", "m", from + 0.02, half_width - 0.02));
    }
    strips.push_back({material, from, to});
    from = to;
    lua_pop(state, 1);
  }
  lua_pop(state, 1);
  return strips;
}

int ground(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "ground");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "ground", {"material", "y", "thickness", "strips"});
    lua_rawgeti(state, 1, 1);
    const std::string name = lua_type(state, -1) == LUA_TSTRING ? fields.name() : "ground";
    lua_pop(state, 1);
    const float top = static_cast<float>(fields.number("y", "m", 0.0));
    // Thinner grounds let lanes stack close together (one block above another's floor).
    constexpr float width = 400.0f;
    const float thickness = static_cast<float>(fields.number_in("thickness", "m", 1.0, 0.02, 2.0));
    b2Body* body = nullptr;
    if (fields.has("strips")) {
      if (fields.has("material")) throw InvalidInput(fields.what() + ": give material or strips, not both");
      const std::vector<Strip> strips = read_strips(state, fields, build, 0.5f * width);
      b2BodyDef definition;
      definition.type = b2_staticBody;
      definition.position = {0.0f, top - 0.5f * thickness};
      body = build.scene->add_body(name, definition);
      const float surface = 0.5f * thickness;  // the top, in the body's own coordinates
      for (const Strip& strip : strips) {
        // Right to left, so that the one-sided edge faces up (Box2D: its normal points to the
        // right looking from v1 to v2); the ghost vertices continue the level floor both ways.
        b2EdgeShape edge;
        edge.SetOneSided({strip.to + 1.0f, surface}, {strip.to, surface}, {strip.from, surface},
                         {strip.from - 1.0f, surface});
        edge.m_radius = true_skin;
        build.scene->add_fixture(body, edge, strip.material);
        b2PolygonShape slab;
        slab.SetAsBox(0.5f * (strip.to - strip.from), 0.5f * thickness, {0.5f * (strip.from + strip.to), 0.0f}, 0.0f);
        slab.m_radius = true_skin;
        b2Fixture* shown = build.scene->add_fixture(body, slab, strip.material);
        b2Filter nothing;
        nothing.maskBits = 0;  // drawn, never touched: the edge above it is the surface
        shown->SetFilterData(nothing);
      }
    } else {
      const std::string material = required_material(build, fields);
      body = build.scene->add_box(name, b2_staticBody, material, {0.0f, top - 0.5f * thickness}, width, thickness,
                                  0.0f, true_skin);
    }
    require_room(*build.scene, fields.what());
    // Its surface runs from x = -width/2 to width/2: `at` is measured from x = 0.
    push_body(state, body, true, {-0.5f * width, top}, {1.0f, 0.0f}, width);
    return 1;
  });
}

int box(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "box");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "box", {"material", "width", "height", "x", "y", "angle", "on", "at", "mass", "kind",
                                    "velocity", "spin", "fixed_rotation", "feet", "foot_width", "foot_height"});
    const std::string name = fields.name();
    const std::string material = required_material(build, fields);
    // In double, before single precision turns the documented 0.02 m into 0.0199999996.
    const double width = fields.number_in("width", "m", 0.02, 1000.0), height = fields.number_in("height", "m", 0.02, 1000.0);
    const Feet feet = read_feet(fields, width, height);
    const Placement where = place(state, fields, static_cast<float>(0.5 * height + feet.height));
    b2Body* body = build.scene->add_box(name, body_kind(fields, "dynamic"), material, where.position,
                                        static_cast<float>(width), static_cast<float>(height), where.angle, true_skin);
    if (feet.count > 0) build.feet[body] = add_feet(*build.scene, body, material, feet, width, height);
    finish_body(fields, body, width * height + feet.count * feet.width * feet.height);
    require_room(*build.scene, fields.what());
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
    const Placement where = place(state, fields, static_cast<float>(radius));
    b2BodyDef definition;
    definition.type = body_kind(fields, "dynamic");
    definition.position = where.position;
    definition.angle = where.angle;
    b2Body* body = build.scene->add_body(name, definition);
    b2CircleShape shape;
    shape.m_radius = static_cast<float>(radius) + true_skin;  // touching at the script's radius
    build.scene->add_fixture(body, shape, material);
    finish_body(fields, body, std::numbers::pi * radius * radius);
    require_room(*build.scene, fields.what());
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
    if (std::abs(xy[0]) > 1000.0 || std::abs(xy[1]) > 1000.0) {
      throw InvalidInput(fields.what() + ": corner " + std::to_string(i) + " is more than 1000 m from {0, 0}; give the "
                         "corners around {0, 0} and place the polygon with x and y");
    }
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
  // Box2D keeps a body's inertia about its origin in floats and takes m·|c|² off it to get the
  // inertia about the centre c: corners far from the origin for their size leave nothing of
  // it, and Box2D aborts. |c|² is kept within 1e4 times I_c/m, where floats still give I_c to
  // about 0.1 %. Worked out about corner 1, per unit density.
  double twice_area = 0.0, cx = 0.0, cy = 0.0, inertia = 0.0;
  for (int i = 1; i + 1 < count; ++i) {
    const double x1 = points[i].x - points[0].x, y1 = points[i].y - points[0].y;
    const double x2 = points[i + 1].x - points[0].x, y2 = points[i + 1].y - points[0].y;
    const double d = x1 * y2 - y1 * x2;  // twice the area of the triangle corner 1, i, i + 1
    twice_area += d;
    cx += d * (x1 + x2) / 3.0;
    cy += d * (y1 + y2) / 3.0;
    inertia += d / 12.0 * (x1 * x1 + x2 * x1 + x2 * x2 + y1 * y1 + y2 * y1 + y2 * y2);
  }
  cx /= twice_area;
  cy /= twice_area;
  const double central = 2.0 * inertia / twice_area - (cx * cx + cy * cy);  // I_c / m
  const double distance = std::hypot(points[0].x + cx, points[0].y + cy);
  if (distance * distance > 1e4 * central) {
    std::ostringstream message;
    message << fields.what() << ": its corners are centred " << distance
            << " m from {0, 0}, too far for a shape this small; give them around {0, 0} and place the polygon "
               "with x and y";
    throw InvalidInput(message.str());
  }
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
    shape.m_radius = true_skin;
    build.scene->add_fixture(body, shape, material);
    b2MassData unit;
    shape.ComputeMass(&unit, 1.0f);
    finish_body(fields, body, unit.mass);
    require_room(*build.scene, fields.what());
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
    shape.m_radius = true_skin;
    build.scene->add_fixture(body, shape, material);
    require_room(*build.scene, fields.what());
    push_body(state, body, true, foot, along, static_cast<float>(length));
    return 1;
  });
}

}  // namespace

// A function of time the script gave for a body, a hand or a force: called with t, it must
// return `count` numbers.
// An answer for the same t is reused (the scene asks at t and t + h several times a step).
// A function may read the world (block.x, block.vx): it sees it as it is when first asked
// about t. The scene asks every function before the step that starts at t moves
// anything, so a force sees the state at the start of its step, and a hand or a driven body
// asked where it will be at t + h sees the state at t (the path is planned a step ahead).
// A force's answer is forgotten when the script sets a velocity (`is_force`).
std::function<std::array<double, 2>(double)> function_of_time(LessonBuild& build, int reference, int count,
                                                              std::string what, bool is_force) {
  LessonBuild* owner = &build;
  auto memory = std::make_shared<RememberedValues>();
  build.remembered.push_back(memory);
  if (is_force) build.force_memories.push_back(memory);
  return [owner, reference, count, what, memory](double t) {
    for (int i = 0; i < memory->filled; ++i) {
      if (memory->times[i] == t) {
        memory->next = i ^ 1;  // the other one is the older: replaced next
        return memory->values[i];
      }
    }
    owner->call(reference, {t}, count);
    // Within the ±1e9 the scene accepts, so the error points at the function, not the scene.
    std::array<double, 2> answer{0.0, 0.0};
    owner->numbers_returned(reference, count, what, answer.data(), t, 1e9);
    memory->times[memory->next] = t;
    memory->values[memory->next] = answer;
    memory->next ^= 1;
    memory->filled = std::min(memory->filled + 1, 2);
    return answer;
  };
}

namespace {

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
      require_script_function(state, -1, fields.what() + ": to");
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
      // Its forces on the one body would cancel out, less the turn they make: nothing a spring is.
      if (made.other == made.body) {
        throw InvalidInput(fields.what() + ": from and to are the same body; a spring joins two bodies, or a body and a "
                           "hand (to = function(t) ... end)");
      }
      made.other_local_point = fields.point("to_at", origin_point);
    }
    made.stiffness = fields.number("k", "N/m");
    const b2Vec2 far_end = made.other ? made.other->GetWorldPoint(made.other_local_point) : made.hand(0.0);
    const double length = (far_end - made.body->GetWorldPoint(made.local_point)).Length();
    made.rest_length = fields.number("rest_length", "m", length);  // unstretched at the start unless told
    build.scene->add_spring(made);
    push_indexed(state, spring_type, build.scene->springs().size() - 1);
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
    // Box2D aborts on a joint from a body to itself.
    if (from == to) throw InvalidInput(fields.what() + ": from and to are the same body; a rope joins two bodies");
    if (!fields.has("over")) throw InvalidInput(fields.what() + ": over is missing: where the pulley is, as in over = {2, 1}");
    const b2Vec2 pulley = fields.point("over", origin_point);
    const b2Vec2 a = from->GetWorldPoint(fields.point("at", origin_point)), b = to->GetWorldPoint(fields.point("to_at", origin_point));
    for (const b2Vec2 end : {a, b}) {
      if ((end - pulley).Length() < 0.05f) throw InvalidInput(fields.what() + ": each end must start at least 5 cm from the pulley");
    }
    push_indexed(state, rope_type, build.scene->add_rope(name, from, a, to, b, pulley, pulley));
    return 1;
  });
}

int force(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "force");
    LessonBuild& build = build_of(state);
    Fields fields(state, 1, "force", {"on", "at", "force", "grows", "torque"});
    AppliedForce made;
    made.name = fields.name();
    fields.push("on");
    made.body = body_handle(state, -1, fields.what() + ": on")->body;
    lua_pop(state, 1);
    made.local_point = fields.point("at", origin_point);
    if (fields.has("grows")) {
      // A force growing at a steady rate from its start value: computed here, with no call
      // into Lua a step (a pull that grows, as stacked_blocks' does, is the common case).
      if (fields.push_function("force")) {
        throw InvalidInput(fields.what() + ": grows adds to a constant force {fx, fy}; a function(t) gives the whole force");
      }
      const b2Vec2 rate = fields.point("grows", origin_point);
      const b2Vec2 start = fields.point("force", origin_point);
      made.force = [start, rate](double t) {
        return b2Vec2{static_cast<float>(start.x + rate.x * t), static_cast<float>(start.y + rate.y * t)};
      };
    } else if (fields.push_function("force")) {
      const auto push = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 2,
                                         fields.what() + ": the force function (t -> fx, fy in N)", true);
      made.force = [push](double t) {
        const std::array<double, 2> f = push(t);
        return b2Vec2{static_cast<float>(f[0]), static_cast<float>(f[1])};
      };
    } else if (fields.has("force")) {
      const b2Vec2 constant = fields.point("force", origin_point);
      made.force = [constant](double) { return constant; };
    } else if (!fields.has("torque")) {
      throw InvalidInput(fields.what() + ": force is missing: {fx, fy} in N, or a function(t), or grows = {rate_x, rate_y} in N/s; or give a torque");
    }
    // A torque about the body's centre of mass, N·m, counter-clockwise positive: a motor.
    if (fields.push_function("torque")) {
      const auto turn = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 1,
                                         fields.what() + ": the torque function (t -> N·m)", true);
      made.torque = [turn](double t) { return turn(t)[0]; };
    } else if (fields.has("torque")) {
      const double constant = fields.number_in("torque", "N·m", -1e9, 1e9);
      made.torque = [constant](double) { return constant; };
    }
    build.scene->add_applied_force(made);
    push_indexed(state, force_type, build.scene->applied_forces().size() - 1);
    return 1;
  });
}

// A driven coordinate's path as numbers (drive's position = { x = ..., y = ... } and angle): a
// number holds it there, and { offset, speed, acceleration, swing, omega, phase } is
// Motion::at. Left out: `fixed`, where the body stands.
Motion motion_field(lua_State* state, Fields& fields, const char* key, double fixed, const std::string& where) {
  Motion motion;
  motion.offset = fixed;
  fields.push(key);
  const std::string what = where + ": " + key;
  if (lua_type(state, -1) == LUA_TNUMBER) {
    motion.offset = fields.number_in(key, "", -1e9, 1e9);
  } else if (lua_istable(state, -1)) {
    Fields terms(state, -1, what, {"offset", "speed", "acceleration", "swing", "omega", "phase"});
    motion.offset = terms.number_in("offset", "", 0.0, -1e9, 1e9);
    motion.speed = terms.number_in("speed", "per s", 0.0, -1e9, 1e9);
    motion.acceleration = terms.number_in("acceleration", "per s²", 0.0, -1e9, 1e9);
    motion.swing = terms.number_in("swing", "", 0.0, -1e9, 1e9);
    motion.omega = terms.number_in("omega", "rad/s", 0.0, -1e6, 1e6);
    motion.phase = terms.number_in("phase", "rad", 0.0, -1e6, 1e6);
  } else if (!lua_isnil(state, -1)) {
    throw InvalidInput(what + " must be a number, or a motion such as { offset = 0, speed = 0.2 } or { swing = 10, "
                       "omega = 3 }" + (std::string(key) == "angle" ? ", or a function(t) returning degrees" : "") +
                       "; got " + describe(state, -1));
  }
  lua_pop(state, 1);
  return motion;
}

int drive(lua_State* state) {
  return guarded(state, [&] {
    require_building(state, "drive");
    LessonBuild& build = build_of(state);
    if (!lua_istable(state, 1)) {
      throw InvalidInput("drive takes a table, as in drive{ belt, position = function(t) return x, y end }; got " +
                         describe(state, 1));
    }
    lua_rawgeti(state, 1, 1);
    b2Body* body = body_handle(state, -1, "drive's first entry (the body to move, as in drive{ belt, position = ... })")->body;
    lua_pop(state, 1);
    const std::string what = "drive '" + body_name(state, body) + "'";
    Fields fields(state, 1, what, {"position", "angle"});
    if (body->GetType() != b2_kinematicBody) throw InvalidInput(what + ": only a body of kind = \"kinematic\" can be driven");
    PointOfTime position;
    ScalarOfTime angle;
    if (fields.push_function("position")) {
      position = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 2, what + ": position (t -> x, y in m)");
    } else if (fields.has("position")) {
      fields.push("position");
      const std::string where = what + ": position";
      if (!lua_istable(state, -1)) {
        throw InvalidInput(where + " must be a function(t) returning x, y, or { x = ..., y = ... } with a motion for "
                           "each; got " + describe(state, -1));
      }
      Fields coordinates(state, -1, where, {"x", "y"});
      const Motion x = motion_field(state, coordinates, "x", body->GetPosition().x, where);
      const Motion y = motion_field(state, coordinates, "y", body->GetPosition().y, where);
      lua_pop(state, 1);
      position = [x, y](double t) { return std::array<double, 2>{x.at(t), y.at(t)}; };
    } else {
      const std::array<double, 2> fixed{body->GetPosition().x, body->GetPosition().y};
      position = [fixed](double) { return fixed; };
    }
    if (fields.push_function("angle")) {
      const auto turn = function_of_time(build, luaL_ref(state, LUA_REGISTRYINDEX), 1, what + ": angle (t -> degrees)");
      angle = [turn](double t) { return turn(t)[0] * degrees; };
    } else {
      const Motion turn = motion_field(state, fields, "angle", body->GetAngle() / degrees, what);
      angle = [turn](double t) { return turn.at(t) * degrees; };
    }
    build.scene->drive(body, position, angle);
    return 0;
  });
}

}  // namespace

void register_world_api(lua_State* state) {
  const luaL_Reg functions[] = {{"ground", ground}, {"box", box},       {"circle", circle}, {"polygon", polygon},
                                {"incline", incline}, {"spring", spring}, {"rope", rope},     {"force", force},
                                {"drive", drive},   {nullptr, nullptr}};
  lua_pushglobaltable(state);
  luaL_setfuncs(state, functions, 0);
  lua_pop(state, 1);
  register_handles(state);
}

}  // namespace frictionlab::lessons
