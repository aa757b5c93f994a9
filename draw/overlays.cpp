#include "draw/overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace frictionlab::draw {

float pixels_per_newton(const Scene& scene, float reference_pixels) {
  float heaviest = 0.0f;
  const float g = scene.world().GetGravity().Length();
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() == b2_dynamicBody) heaviest = std::max(heaviest, body->GetMass() * g);
  }
  return reference_pixels / std::max(heaviest, 1e-3f);
}

bool body_contains(const b2Body* body, b2Vec2 point) {
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->TestPoint(point)) return true;
  }
  return false;
}

namespace {

// Whether an applied force acts on its body's outline and points into the body: a push on a
// face. Tested a millimetre either side of its point along its direction (the lessons' bodies
// are centimetres across and more): outside before it, inside after. A force at the centre of
// mass (push's) is inside on both sides, a pull on a face (stacked_blocks') the other way round.
bool pushes_on_face(const ForceOnBody& force) {
  if (force.kind != ForceKind::applied || force.body == nullptr) return false;
  const float size = force.force.Length();
  if (size == 0.0f) return false;
  const b2Vec2 step = (1e-3f / size) * force.force;
  return !body_contains(force.body, force.point - step) && body_contains(force.body, force.point + step);
}

}  // namespace

float ScreenArrow::length() const { return std::hypot(tip.x - tail.x, tip.y - tail.y); }

std::vector<ScreenArrow> place_arrows(const std::vector<ForceOnBody>& forces, const Camera& camera,
                                      float pixels_per_newton, float scale, float shortest, float gap,
                                      bool weight_at_its_centre) {
  // Whether a force counts is a question of the printed values, not of pixels: one that shows in
  // its body's numbers (at least half the last digit printed for the body's largest force) is
  // drawn, however short its arrow would be at the picture's scale. A tipping box's last
  // newton of friction under a 98 N weight was a pixel long and was left out, with its label, and
  // the free-body diagram's net force then did not add up. One that does not show (the solver's
  // round-off on a resting block) is left out.
  float largest = 0.0f;
  for (const ForceOnBody& force : forces) largest = std::max(largest, force.force.Length());
  const double smallest_shown = 0.5 * printed_number(largest).step;
  std::vector<ScreenArrow> arrows;
  for (const ForceOnBody& force : forces) {
    const float size = force.force.Length();
    if (size == 0.0f || size < smallest_shown) continue;
    const ImVec2 at = camera.to_screen(force.point);
    // Too short to see at the scale: as long as an arrowhead needs, its label giving its size;
    // with a legible length asked for, lengthened in order.
    const float legible = std::max(shortest, shortest_arrow_pixels(scale));
    const float drawn = drawn_arrow_pixels(size, pixels_per_newton, legible);
    const ImVec2 reach(force.force.x / size * drawn, -force.force.y / size * drawn);
    // A push on a body's face ends there, its tail outside: drawn from the face, it lay inside
    // the body (tipping_box pushed low, issue 31), as though the box were pulled from within.
    const bool onto_face = pushes_on_face(force);
    const ImVec2 tail = onto_face ? ImVec2(at.x - reach.x, at.y - reach.y) : at;
    const ImVec2 tip = onto_face ? at : ImVec2(at.x + reach.x, at.y + reach.y);
    arrows.push_back(ScreenArrow{force, tail, tip, !drawn_longer(size, pixels_per_newton, legible)});
  }
  // Side by side where two lie along one line and overlap, as textbooks draw weight and normal
  // force: they move apart across the line, keeping their lengths and directions, until they are
  // a gap apart; each moves half of that, but a weight, which stays at its centre of mass while
  // the other moves all of it. The gap grows with the arrows' thickness (3.5 px times the scale)
  // and clears a head beside a shaft (side_by_side_gap).
  if (gap <= 0.0f) gap = side_by_side_gap(world_arrow_thickness(scale));
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
      // Only as far as makes the gap: moved a whole gap more than they already stood apart,
      // tipping_box's normal force, acting 0.10 m ahead of the weight at 1.5 s pushed at 0.3 m,
      // was drawn 0.19 m ahead, nearly at the corner the box was not yet tipping about (issue 31).
      const float apart = gap - std::abs(offset);
      // A weight stays at its body's centre of mass and the other goes all the way across:
      // each moving half, a weight beside each of a body's six feet's normal forces went
      // 58 px across, off contact_area's block (issue 31).
      const bool p_stays = weight_at_its_centre && p.force.kind == ForceKind::weight && q.force.kind != ForceKind::weight;
      const bool q_stays = weight_at_its_centre && q.force.kind == ForceKind::weight && p.force.kind != ForceKind::weight;
      const float p_share = p_stays ? 0.0f : q_stays ? 1.0f : 0.5f;
      const ImVec2 across(-uy * side * apart, ux * side * apart);
      p.tail = ImVec2(p.tail.x - p_share * across.x, p.tail.y - p_share * across.y);
      p.tip = ImVec2(p.tip.x - p_share * across.x, p.tip.y - p_share * across.y);
      q.tail = ImVec2(q.tail.x + (1.0f - p_share) * across.x, q.tail.y + (1.0f - p_share) * across.y);
      q.tip = ImVec2(q.tip.x + (1.0f - p_share) * across.x, q.tip.y + (1.0f - p_share) * across.y);
    }
  }
  return arrows;
}

std::string format_quantity(double value, const char* unit) {
  if (value == 0.0) return std::string("0 ") + unit;
  // The digits printed_number() rounds to, written out: the rounding lives there alone, so the
  // free-body inset's sum of printed forces is what a student adds up from these texts.
  const PrintedNumber printed = printed_number(value);
  const int last_digit = static_cast<int>(std::lround(std::log10(printed.step)));
  char text[64];
  std::string shown;
  if (std::abs(value) < 1e-3) {
    // 4.2×10⁻⁸ rather than 4.2e-08: the notation of the classroom; two figures, the last at
    // `last_digit`.
    const int exponent = last_digit + 1;
    std::snprintf(text, sizeof text, "%.2g\u00d710", printed.value / std::pow(10.0, exponent));
    shown = text;
    static const char* const superscript[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                              "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
    shown += "\u207b";
    for (char digit : std::to_string(-exponent)) shown += superscript[digit - '0'];
    shown = shown + " " + unit;
  } else {
    std::snprintf(text, sizeof text, "%.*f %s", -last_digit, printed.value, unit);
    shown = text;
  }
  // A minus sign, not a hyphen, in front of negative numbers.
  if (!shown.empty() && shown[0] == '-') shown.replace(0, 1, "\u2212");
  return shown;
}

PrintedNumber printed_number(double value) {
  const double magnitude = std::abs(value);
  if (magnitude == 0.0) return {0.0, 1.0};
  if (magnitude < 1e-3) {
    // Two significant figures times a power of ten; 9.96×10⁻⁴ rounds to two digits as 10, so
    // it is 1×10⁻³, not 10×10⁻⁴.
    int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(mantissa) >= 9.95) {
      mantissa /= 10.0;
      ++exponent;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2g", mantissa);
    return {std::strtod(text, nullptr) * std::pow(10.0, exponent), std::pow(10.0, exponent - 1)};
  }
  const int decimals = magnitude >= 100.0 ? 0 : magnitude >= 10.0 ? 1 : magnitude >= 1.0 ? 2 : magnitude >= 0.1 ? 3
                       : magnitude >= 0.01 ? 4 : 5;
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return {std::strtod(text, nullptr), std::pow(10.0, -decimals)};
}

}  // namespace frictionlab::draw
