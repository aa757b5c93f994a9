#include "ui/overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frictionlab::ui {

const b2Body* main_body(const Scene& scene) {
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_dynamicBody) return body;
  }
  return nullptr;
}

namespace {

// Where the contact's normal load acts: the manifold points weighted by their share of it.
b2Vec2 centre_of_load(const ContactRecord& record) {
  double total = 0.0;
  b2Vec2 sum{0.0f, 0.0f};
  for (int i = 0; i < record.point_count && i < b2_maxManifoldPoints; ++i) {
    total += record.point_normal_force[i];
    sum += static_cast<float>(record.point_normal_force[i]) * record.world_points[i];
  }
  return total > 1e-9 ? (1.0f / static_cast<float>(total)) * sum : record.point;
}

bool touching(const ContactRecord& record) { return record.point_count > 0 && !record.unpaired; }

}  // namespace

std::vector<ForceOnBody> forces_on(const Scene& scene, const b2Body* body) {
  std::vector<ForceOnBody> forces;
  if (body == nullptr || body->GetType() != b2_dynamicBody) return forces;
  const b2Vec2 gravity = scene.world().GetGravity();
  forces.push_back({ForceKind::weight, body, body->GetWorldCenter(), body->GetMass() * gravity});
  struct Shared {
    const b2Body* other;
    std::size_t friction;  // its friction force's place in `forces`; its drag's is the next
    float load;            // N, the normal load summed so far
  };
  std::vector<Shared> shared;
  for (const b2Contact* contact = scene.world().GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    const b2Body* a = contact->GetFixtureA()->GetBody();
    const b2Body* b = contact->GetFixtureB()->GetBody();
    if (a != body && b != body) continue;
    const ContactRecord* found = scene.friction().record(contact);
    if (found == nullptr || !touching(*found)) continue;
    const ContactRecord& record = *found;
    const b2Vec2 point = centre_of_load(record);
    const b2Body* other = a == body ? b : a;
    forces.push_back({ForceKind::normal, body, point, record.normal_on(body), other});
    const b2Vec2 drag = record.side(body) * static_cast<float>(record.damping_force) * record.tangent();
    // Friction (and drag) from one other body is drawn as one arrow, their sum, at the centre of
    // the load: a block on six feet has six normal forces to show but one friction force to
    // read. Each foot's normal force keeps its own arrow.
    const float load = record.normal_on(body).Length();
    const auto same = std::find_if(shared.begin(), shared.end(), [&](const Shared& s) { return s.other == other; });
    if (same == shared.end()) {
      shared.push_back({other, forces.size(), load});
      forces.push_back({ForceKind::friction, body, point, record.friction_on(body), other});
      // The viscous and quadratic terms apart from dry friction, so mu_k·N stays readable.
      forces.push_back({ForceKind::drag, body, point, drag, other});
      continue;
    }
    ForceOnBody& friction = forces[same->friction];
    ForceOnBody& damping = forces[same->friction + 1];
    const float total = same->load + load;
    if (total > 0.0f) friction.point = (same->load / total) * friction.point + (load / total) * point;
    damping.point = friction.point;
    friction.force += record.friction_on(body);
    damping.force += drag;
    same->load = total;
  }
  // A drag arrow only where there is drag.
  forces.erase(std::remove_if(forces.begin(), forces.end(),
                              [](const ForceOnBody& f) { return f.kind == ForceKind::drag && f.force.LengthSquared() == 0.0f; }),
               forces.end());
  // Springs and applied forces as the last step applied them, the step whose friction the
  // record holds: while a block sticks, the forces then add up to zero.
  for (std::size_t i = 0; i < scene.springs().size(); ++i) {
    const Spring& spring = scene.springs()[i];
    const b2Vec2 pull = scene.spring_forces_applied()[i];
    if (spring.body == body) forces.push_back({ForceKind::spring, body, body->GetWorldPoint(spring.local_point), pull});
    if (spring.other == body) {
      forces.push_back({ForceKind::spring, body, body->GetWorldPoint(spring.other_local_point), -pull});
    }
  }
  // A rope pulls each end toward its pulley with the tension the last world step's solver
  // found (its impulse over that step's length).
  for (std::size_t i = 0; i < scene.ropes().size(); ++i) {
    const Rope& rope = scene.ropes()[i];
    // A slack rope pulls with nothing, and draws no arrow.
    if (!rope.taut() || scene.frame() == 0) continue;
    const auto tension = static_cast<float>(scene.rope_tension(i));
    const auto toward = [](b2Vec2 from, b2Vec2 to) {
      b2Vec2 d = to - from;
      return d.Normalize() > 0.0f ? d : b2Vec2{0.0f, 0.0f};
    };
    if (rope.body_a == body) forces.push_back({ForceKind::tension, body, rope.end_a(), tension * toward(rope.end_a(), rope.pulley_a)});
    if (rope.body_b == body) forces.push_back({ForceKind::tension, body, rope.end_b(), tension * toward(rope.end_b(), rope.pulley_b)});
  }
  for (std::size_t i = 0; i < scene.applied_forces().size(); ++i) {
    const AppliedForce& applied = scene.applied_forces()[i];
    if (applied.body != body) continue;
    forces.push_back({ForceKind::applied, body, body->GetWorldPoint(applied.local_point), scene.forces_applied()[i]});
  }
  return forces;
}

std::vector<ContactMark> contact_marks(const Scene& scene) {
  std::vector<ContactMark> marks;
  for (const b2Contact* contact = scene.world().GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    const ContactRecord* found = scene.friction().record(contact);
    if (found == nullptr || !touching(*found)) continue;
    const ContactRecord& record = *found;
    if (record.body_a->GetType() != b2_dynamicBody && record.body_b->GetType() != b2_dynamicBody) continue;
    marks.push_back({record.body_a, record.body_b, centre_of_load(record), record.tangent(), record.state,
                     record.frictionless, record.sliding_velocity, record.friction_force});
  }
  return marks;
}

float upper_side(const ContactMark& mark) {
  const b2Vec2 normal = b2Cross(1.0f, mark.tangent);  // from A to B
  return normal.y >= 0.0f ? 1.0f : -1.0f;
}

std::string contact_word(const ContactMark& mark) {
  // With no dry friction nothing sticks or slips: the word says so, sliding along or not.
  if (mark.frictionless) return "frictionless";
  if (mark.state != ContactState::slipping) return "sticking";
  // The record's sliding is B's relative to A; turned into the upper body's over the lower one.
  const b2Vec2 way = upper_side(mark) * static_cast<float>(mark.sliding_velocity >= 0.0 ? 1.0 : -1.0) * mark.tangent;
  return way.x >= 0.0f ? "slipping \u2192" : "\u2190 slipping";
}

float pixels_per_newton(const Scene& scene, float reference_pixels) {
  float heaviest = 0.0f;
  const float g = scene.world().GetGravity().Length();
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_dynamicBody) heaviest = std::max(heaviest, body->GetMass() * g);
  }
  return reference_pixels / std::max(heaviest, 1e-3f);
}

float ScreenArrow::length() const { return std::hypot(tip.x - tail.x, tip.y - tail.y); }

std::vector<ScreenArrow> place_arrows(const std::vector<ForceOnBody>& forces, const Camera& camera,
                                      float pixels_per_newton) {
  std::vector<ScreenArrow> arrows;
  for (const ForceOnBody& force : forces) {
    const ImVec2 tail = camera.to_screen(force.point);
    const ImVec2 tip(tail.x + force.force.x * pixels_per_newton, tail.y - force.force.y * pixels_per_newton);
    ScreenArrow arrow{force, tail, tip};
    if (arrow.length() >= 2.0f) arrows.push_back(arrow);
  }
  // Side by side where two lie along one line and overlap, as textbooks draw weight and normal
  // force: each moves half a gap across, keeping its length and direction.
  constexpr float gap = 9.0f;
  for (std::size_t i = 0; i < arrows.size(); ++i) {
    for (std::size_t j = i + 1; j < arrows.size(); ++j) {
      ScreenArrow& p = arrows[i];
      ScreenArrow& q = arrows[j];
      const float px = p.tip.x - p.tail.x, py = p.tip.y - p.tail.y, pl = p.length();
      const float qx = q.tip.x - q.tail.x, qy = q.tip.y - q.tail.y, ql = q.length();
      const float cross = std::abs(px * qy - py * qx) / (pl * ql);
      if (cross > 0.17f) continue;  // more than 10° apart
      const float ux = px / pl, uy = py / pl;
      const float offset = (q.tail.x - p.tail.x) * -uy + (q.tail.y - p.tail.y) * ux;
      if (std::abs(offset) > gap) continue;
      // Overlap along the line: project q's ends on p's line.
      const float q0 = (q.tail.x - p.tail.x) * ux + (q.tail.y - p.tail.y) * uy;
      const float q1 = (q.tip.x - p.tail.x) * ux + (q.tip.y - p.tail.y) * uy;
      if (std::max(q0, q1) <= 0.0f || std::min(q0, q1) >= pl) continue;
      const float side = offset >= 0.0f ? 1.0f : -1.0f;
      const ImVec2 shift(-uy * side * 0.5f * gap, ux * side * 0.5f * gap);
      p.tail = ImVec2(p.tail.x - shift.x, p.tail.y - shift.y);
      p.tip = ImVec2(p.tip.x - shift.x, p.tip.y - shift.y);
      q.tail = ImVec2(q.tail.x + shift.x, q.tail.y + shift.y);
      q.tip = ImVec2(q.tip.x + shift.x, q.tip.y + shift.y);
    }
  }
  return arrows;
}

std::string format_quantity(double value, const char* unit) {
  char text[64];
  const double magnitude = std::abs(value);
  if (magnitude == 0.0) return std::string("0 ") + unit;
  if (magnitude < 1e-3) {
    // 4.2×10⁻⁸ rather than 4.2e-08: the notation of the classroom.
    int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    double mantissa = value / std::pow(10.0, exponent);
    // 9.96×10⁻⁴ rounds to two digits as 10: written 1×10⁻³, not 10×10⁻⁴.
    if (std::abs(mantissa) >= 9.95) {
      mantissa /= 10.0;
      ++exponent;
    }
    std::snprintf(text, sizeof text, "%.2g\u00d710", mantissa);
    std::string shown = text;
    static const char* const superscript[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                              "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
    shown += "\u207b";
    for (char digit : std::to_string(-exponent)) shown += superscript[digit - '0'];
    shown = shown + " " + unit;
    if (shown[0] == '-') shown.replace(0, 1, "\u2212");
    return shown;
  }
  const char* format = magnitude >= 100.0 ? "%.0f %s" : magnitude >= 10.0 ? "%.1f %s" : magnitude >= 1.0 ? "%.2f %s"
                       : magnitude >= 0.1 ? "%.3f %s" : magnitude >= 0.01 ? "%.4f %s" : "%.5f %s";
  std::snprintf(text, sizeof text, format, value, unit);
  // A minus sign, not a hyphen, in front of negative numbers.
  std::string shown = text;
  if (!shown.empty() && shown[0] == '-') shown.replace(0, 1, "\u2212");
  return shown;
}

}  // namespace frictionlab::ui
