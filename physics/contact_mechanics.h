// The mechanics of one contact that the listener and the treatments share: the mass its
// tangential motion feels, its sliding speed, and a tangential impulse on both bodies.
#pragma once

#include <box2d/box2d.h>

#include <algorithm>

#include "physics/materials.h"

namespace frictionlab {

// Box2D reports inertia about the body origin; dynamics needs it about the centre of mass.
inline float central_inertia(const b2Body* body) {
  const b2Vec2 c = body->GetLocalCenter();
  return body->GetInertia() - body->GetMass() * b2Dot(c, c);
}

// J: the body's kinetic energy, its motion and its spin about the centre of mass.
inline double kinetic_energy(const b2Body* body) {
  const b2Vec2 v = body->GetLinearVelocity();
  const double w = body->GetAngularVelocity();
  return 0.5 * body->GetMass() * b2Dot(v, v) + 0.5 * central_inertia(body) * w * w;
}

// Whether a drive moves the body: a kinematic body, whose velocity the scene sets each step
// from its path, whatever that velocity is now. The listener counts such a body's velocity
// (and nothing else) as the drive, in the sliding's change between steps and in the work the
// drivers do, and the stick-slip treatment decides a stop on it at once by Coulomb's law; at
// rest, a driven body's drive terms are all 0 there, and that decision is Coulomb's law's on a
// still surface too, so "with a velocity" needs no test of its own. One rule, here.
inline bool is_driven(const b2Body* body) { return body->GetType() == b2_kinematicBody; }

inline b2Vec2 point_velocity(const b2Body* body, const b2Vec2& world_point) {
  return body->GetLinearVelocityFromWorldPoint(world_point);
}

// After a step of length h: the velocity the solver gave the point of `body` that was at
// `world_point` when the step began. The solver's lever arms are from the centre of mass of
// then, which the step has since moved by h·v; about the centre of now, a body spinning while
// it moves would be given a point velocity off by ω·v·h across the contact (2 m/s on a wheel
// spinning at 60 rad/s at 8 m/s), and the books would call that an impact.
inline b2Vec2 solved_point_velocity(const b2Body* body, const b2Vec2& world_point, float h) {
  const b2Vec2 v = body->GetLinearVelocity();
  const b2Vec2 centre_then = body->GetWorldCenter() - h * v;
  return v + b2Cross(body->GetAngularVelocity(), world_point - centre_then);
}

// The mass the contact's tangential motion feels: what an impulse P along t at p needs to
// change the relative sliding speed by P / m.
inline float tangential_mass(const b2Body* a, const b2Body* b, const b2Vec2& p, const b2Vec2& t) {
  float inverse = 0.0f;
  for (const b2Body* body : {a, b}) {
    if (body->GetType() != b2_dynamicBody) continue;
    inverse += 1.0f / body->GetMass();
    // A fixed-rotation body (inertia 0) cannot turn, so the lever arm adds nothing.
    const float inertia = central_inertia(body);
    const float arm = b2Cross(p - body->GetWorldCenter(), t);
    if (inertia > 0.0f) inverse += arm * arm / inertia;
  }
  return inverse > 0.0f ? 1.0f / inverse : 0.0f;
}

// The mass a push through both centres of mass feels, rotation aside.
inline float translational_mass(const b2Body* a, const b2Body* b) {
  float inverse = 0.0f;
  for (const b2Body* body : {a, b}) {
    if (body->GetType() == b2_dynamicBody) inverse += 1.0f / body->GetMass();
  }
  return inverse > 0.0f ? 1.0f / inverse : 0.0f;
}

// On a face (two manifold points) the normal forces redistribute to keep a body from pitching,
// so tangential impulses there move the translational mass and go through the centres of
// mass. Applied at the face instead, their torque would set the body pitching for a step until
// the normal impulses stopped it, and the velocity they leave can even reverse. At a single
// point (a corner, a wheel) rotation is free and the point's own effective mass applies.
inline float contact_mass(const b2Body* a, const b2Body* b, bool face, const b2Vec2& p, const b2Vec2& t) {
  return face ? translational_mass(a, b) : tangential_mass(a, b, p, t);
}

// The sliding speed the contact's own impulses act on: of the centres of mass on a face (where
// those impulses go through the centres), of the contact point elsewhere.
inline double sliding_speed(const b2Body* a, const b2Body* b, bool face, const b2Vec2& p, const b2Vec2& t) {
  const b2Vec2 relative = face ? b->GetLinearVelocity() - a->GetLinearVelocity() : point_velocity(b, p) - point_velocity(a, p);
  return b2Dot(relative, t);
}

// The static limit: with mu_k > mu_s a contact pushed past mu_s·N but not mu_k·N would be
// pushed back by kinetic friction the moment it moved, so it cannot start until mu_k·N.
inline double breakaway_coefficient(const FrictionPair& pair) { return std::max(pair.mu_s, pair.mu_k); }

inline void apply_tangential_impulse(b2Body* a, b2Body* b, const b2Vec2& p, const b2Vec2& t, float impulse,
                                     bool through_centres = false) {
  for (b2Body* body : {b, a}) {
    if (body->GetType() != b2_dynamicBody) continue;
    const b2Vec2 push = (body == b ? impulse : -impulse) * t;
    if (through_centres) {
      body->ApplyLinearImpulseToCenter(push, true);
    } else {
      body->ApplyLinearImpulse(push, p, true);
    }
  }
}

}  // namespace frictionlab
