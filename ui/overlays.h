// What the teaching overlays show, taken from what the solver did: forces on each body (from
// the friction listener's contact records, the springs and the applied forces) and the state
// of every contact. Worked out apart from drawing, so tests can check them against the record.
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <string>
#include <vector>

#include "physics/scene.h"
#include "ui/camera.h"
#include "ui/theme.h"

namespace frictionlab::ui {

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

// Newtons to pixels, the same for every frame of a lesson: the heaviest weight gets
// `reference_pixels`.
float pixels_per_newton(const Scene& scene, float reference_pixels);

// An arrow as drawn: tail and tip in pixels.
struct ScreenArrow {
  ForceOnBody force;
  ImVec2 tail, tip;
  float length() const;
};
// Tails at the point of action; an arrow too short to see (under 2 px) is left out. Two
// arrows of one body lying along one line (weight and normal force) are drawn side by side.
std::vector<ScreenArrow> place_arrows(const std::vector<ForceOnBody>& forces, const Camera& camera,
                                      float pixels_per_newton);

// "4.42 N", "98.1 N", "0.0120 N", "4.2×10⁻⁸ J": three significant figures (two in powers of
// ten) and the unit.
std::string format_quantity(double value, const char* unit);

}  // namespace frictionlab::ui
