// Inside the runtime: the handles a script holds (bodies, springs, forces, contact views) and
// how API functions recognise them. Not for use outside lessons/runtime/.
#pragma once

#include <string>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {

// The handle types a script holds, each with its own metatable.
enum HandleType { body_type, spring_type, force_type, contact_type, rope_type };
extern const char* const type_names[5];

// A body as the script holds it. Ground and inclines also carry their surface, a line along
// which `on = ..., at = s` places things: origin, and the unit direction s grows in.
struct BodyHandle {
  b2Body* body;
  bool is_surface;
  b2Vec2 origin;
  b2Vec2 along;
  float length;  // how far along the surface `at` may go: [0, length] (ground: centred on x = 0)
};
struct SpringHandle {
  size_t index;
};
struct ForceHandle {
  size_t index;
};
// rope{}: its index in the scene's ropes.
struct RopeHandle {
  size_t index;
};
// contact(a, b): a view of the touching pair, read when a field is read. contact(a, b, k) is
// the view of one foot of a body on feet: the touch of that foot's fixture alone.
struct ContactHandle {
  const b2Body* a;
  const b2Body* b;
  const b2Fixture* foot = nullptr;  // null: the first touching contact between the two bodies
};

// b2Vec2's default constructor leaves it uninitialised: every default here is spelled out.
inline const b2Vec2 origin_point{0.0f, 0.0f};

void push_body(lua_State* state, b2Body* body, bool is_surface = false, b2Vec2 origin = origin_point,
               b2Vec2 along = {1.0f, 0.0f}, float length = 0.0f);
// Pushes a new handle of `type` holding `index` (a spring's, a force's or a rope's place in the scene).
void push_indexed(lua_State* state, HandleType type, size_t index);

// The userdata at `index` when its metatable is `type`'s; null otherwise.
void* handle_of(lua_State* state, int index, HandleType type);
// Throws InvalidInput naming `what` when the value is not a body.
BodyHandle* body_handle(lua_State* state, int index, const char* what);
BodyHandle* body_handle(lua_State* state, int index, const std::string& what);
std::string body_name(lua_State* state, const b2Body* body);

// The handle types' metatables, and contact(a, b).
void register_handles(lua_State* state);

}  // namespace frictionlab::lessons
