// What the solver did, read for the class: every force on a body (from the friction listener's
// contact records, the springs, the ropes and the applied forces), the state of every contact,
// and the surface a body stands on. No drawing: the overlays (draw/overlays.h) draw these, the
// force gauge's record (classroom_state/gauge_record.h) and the measuring tools read them, and
// tests check them against the record.
#pragma once

#include <box2d/box2d.h>

#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include "physics/scene.h"

namespace frictionlab {

// The kinds of force the class is shown.
enum class ForceKind { applied, spring, friction, normal, weight, tension, drag };
constexpr int force_kind_count = 7;
// The word the legend gives each kind ("rope" for a tension), and a script's probe{ force = ... }.
std::string_view force_kind_name(ForceKind kind);

struct ForceOnBody {
  ForceKind kind;
  const b2Body* body = nullptr;
  b2Vec2 point{0.0f, 0.0f};  // world, where it acts
  b2Vec2 force{0.0f, 0.0f};  // N, world axes
  const b2Body* other = nullptr;  // the body pushing (normal force) or rubbing (friction, drag), if any
};

struct ContactMark {
  const b2Body* body_a = nullptr;
  const b2Body* body_b = nullptr;
  b2Vec2 point{0.0f, 0.0f};    // where the normal force acts: the centre of the manifold points' loads
  b2Vec2 tangent{1.0f, 0.0f};  // B's friction direction
  ContactState state = ContactState::sticking;
  bool frictionless = false;      // mu_s = mu_k = 0: neither sticking nor slipping (ContactRecord)
  double sliding_velocity = 0.0;  // m/s, B relative to A along the tangent
  double friction_force = 0.0;    // N, dry friction on B along the tangent
};

// The body a lesson is about: its first dynamic body, in the order the script made them.
const b2Body* main_body(const Scene& scene);

// Every force on a dynamic body now: weight at the centre of mass; the normal force at each
// touching contact, where its load is centred; dry friction and (with c or b) drag summed over
// the contacts with each other body, at the centre of their loads; springs at their ends, ropes
// at theirs and applied forces at their points, as the last step applied them.
std::vector<ForceOnBody> forces_on(const Scene& scene, const b2Body* body);
// Every touching contact with a dynamic body in it, in the world's contact order.
std::vector<ContactMark> contact_marks(const Scene& scene);
// +1 when the contact's body B is the upper of its two bodies, −1 when A is. Box2D may make
// either body A (a block on a block may be either of their contact); the normal, from A to B,
// says which is on top.
float upper_side(const ContactMark& mark);
// What a contact's mark says: "sticking", or "slipping" with the way the upper body slides over
// the lower one ("slipping →", "← slipping").
std::string contact_word(const ContactMark& mark);

// The surface a body stands on: a touching contact with a fixed body, the point on it under the
// body's centre of mass, its direction along the surface (x ≥ 0, rightwards), and the normal out of it towards the body.
// At t = 0, before any contact, a body at rest stands on the face its own angle puts lowest.
struct Surface {
  b2Vec2 point, along, normal;
  // How far the fixed body reaches along the surface from `point`, m (a slope's top ends the
  // marks; a ground runs on). Unbounded when the body is not known (set down at t = 0).
  float low = -1e30f, high = 1e30f;
};
std::optional<Surface> surface_under(const Scene& scene, const b2Body* body);

}  // namespace frictionlab
