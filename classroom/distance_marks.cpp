#include "classroom/distance_marks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "draw/overlays.h"

namespace frictionlab::classroom {

// The screen-point arithmetic of draw/drawing.h, used throughout here.
using draw::add;
using draw::length;
using draw::mul;
using draw::sub;

namespace {

// The least nice length (1, 2 or 5 times a power of ten) no shorter than `least`.
float nice_length_at_least(float least) {
  const float power = std::pow(10.0f, std::floor(std::log10(least)));
  const float fraction = least / power;
  return (fraction <= 1.0f ? 1.0f : fraction <= 2.0f ? 2.0f : fraction <= 5.0f ? 5.0f : 10.0f) * power;
}

}  // namespace

float distance_mark_step(float pixels_per_metre, float scale, float body_length) {
  // A nice length about 120 points long, the ruler's own size on the screen; but no longer than
  // half the body measured, so that the slide is read against ticks a fraction of the body's own
  // length apart: a projector's incline (its 0.4 m block on a slope 58 px a metre) had a tick
  // every 5 m, one in view, for a slide of 1.2 m, and the class read nothing off it (issue 31).
  float step = draw::nice_length(120.0f * scale / pixels_per_metre);
  if (body_length > 0.0f && step > 0.5f * body_length) step = draw::nice_length_within(0.5f * body_length);
  // And no closer than least_tick_spacing().
  return std::max(step, nice_length_at_least(least_tick_spacing(scale) / pixels_per_metre));
}

float length_along(const b2Body* body, b2Vec2 along) {
  float low = 1e30f, high = -1e30f;
  const auto reach = [&](b2Vec2 point, float radius) {
    const float at = b2Dot(point, along);
    low = std::min(low, at - radius), high = std::max(high, at + radius);
  };
  for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
    if (fixture->GetType() == b2Shape::e_circle) {
      const auto* circle = static_cast<const b2CircleShape*>(fixture->GetShape());
      reach(body->GetWorldPoint(circle->m_p), circle->m_radius);
    } else if (fixture->GetType() == b2Shape::e_polygon) {
      const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
      for (int k = 0; k < polygon->m_count; ++k) reach(body->GetWorldPoint(polygon->m_vertices[k]), 0.0f);
    }
  }
  return high > low ? high - low : 0.0f;
}

namespace {

struct Ruler {
  ImVec2 from, to;                   // the line, just inside the surface
  std::vector<std::pair<ImVec2, double>> ticks;  // each tick's foot on the line and its distance, m
  ImVec2 inward;                     // screen direction of the ticks: into the surface, or out of it
  double step = 1.0;                 // m between ticks
  float to_surface = 0.0f;           // px from the line back to the surface, against `inward`
};

// `step`: the ticks' spacing, m. `outside`: the line on the surface itself and its ticks out of
// it, for a surface whose inside the view leaves no room under (a lane's thin strip of ground).
std::optional<Ruler> ruler(const Surface& surface, b2Vec2 origin, const draw::Camera& camera, float scale, float step,
                           bool outside = false) {
  // The view's corners projected on the surface's line give the span of it in sight.
  const b2Vec2 corners[4] = {camera.to_world(camera.origin), camera.to_world(add(camera.origin, ImVec2(camera.size.x, 0.0f))),
                             camera.to_world(add(camera.origin, camera.size)),
                             camera.to_world(add(camera.origin, ImVec2(0.0f, camera.size.y)))};
  // The line runs through where the body stood at t = 0, along the surface it stands on now.
  const b2Vec2 base = origin + b2Dot(surface.point - origin, surface.normal) * surface.normal;
  float low = 1e30f, high = -1e30f;
  for (const b2Vec2& corner : corners) {
    low = std::min(low, b2Dot(corner - base, surface.along));
    high = std::max(high, b2Dot(corner - base, surface.along));
  }
  // No further than the surface goes (the foot and the top of a slope).
  const float shift = b2Dot(surface.point - base, surface.along);
  low = std::max(low, surface.low + shift);
  high = std::min(high, surface.high + shift);
  if (!(high > low) || (high - low) / step > 400.0f) return std::nullopt;
  Ruler ruler;
  ruler.step = static_cast<double>(step);
  ruler.to_surface = outside ? 0.0f : 6.0f * scale;
  const ImVec2 inward_world = camera.to_screen(base - surface.normal);
  ImVec2 inward = sub(inward_world, camera.to_screen(base));
  if (length(inward) < 1e-6f) return std::nullopt;
  ruler.inward = mul(inward, outside ? -1.0f / length(inward) : 1.0f / length(inward));
  const ImVec2 offset = mul(ruler.inward, outside ? 0.0f : 6.0f * scale);
  ruler.from = add(camera.to_screen(base + low * surface.along), offset);
  ruler.to = add(camera.to_screen(base + high * surface.along), offset);
  // Counted in whole ticks: far from the start a float count would stop growing.
  const double first = std::ceil(static_cast<double>(low) / step), last = std::floor(static_cast<double>(high) / step);
  // Counted forward the way a body let go moves: rightwards along a level floor, downhill on a
  // slope (as the lessons' distances are); behind the start the marks read negative.
  const double forward = surface.along.y > std::sin(0.5f * b2_pi / 180.0f) ? -1.0 : 1.0;
  for (double k = first; k <= last && k - first < 400.0; k += 1.0) {
    const double metres = k * static_cast<double>(step);
    ruler.ticks.push_back({add(camera.to_screen(base + static_cast<float>(metres) * surface.along), offset), forward * metres});
  }
  return ruler;
}

// The marks of one ruler, each number's box at its tick (beyond its end).
DistanceMarks numbered(const Ruler& line, const draw::Fonts& fonts) {
  const float s = fonts.scale;
  DistanceMarks marks{line.from, line.to, line.inward, line.step, {}, 1};
  // Numbers least_number_spacing() apart at least: every 1, 2, 5, … ticks (DistanceMarks::least_every).
  const float pixels_per_step = line.ticks.size() >= 2 ? length(sub(line.ticks[1].first, line.ticks[0].first)) : 0.0f;
  for (const std::size_t every : {1u, 2u, 5u, 10u, 20u, 50u}) {
    marks.least_every = every;
    if (pixels_per_step <= 0.0f || static_cast<float>(every) * pixels_per_step >= least_number_spacing(s) - 0.01f) break;
  }
  for (const auto& [foot, metres] : line.ticks) {
    char number[32];
    std::snprintf(number, sizeof number, "%g m", std::abs(metres) < 1e-9 ? 0.0 : metres);
    std::string text = number;
    if (text[0] == '-') text.replace(0, 1, "\u2212");  // a minus sign, not a hyphen
    const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, text.c_str());
    // How far the text's box reaches along the ticks' direction from its middle: half its height
    // under a floor, half its width and more under a steep slope's face (at 60° the box, moved
    // half its height off the line, lay over the ticks, and no number was shown).
    const float reach = std::abs(line.inward.x) * (0.5f * size.x + 2.0f) + std::abs(line.inward.y) * (0.5f * size.y + 2.0f);
    // Clear of the start's tick too, which is longer (12 px) than the others: "0 m" was never shown.
    const ImVec2 centre = add(foot, mul(line.inward, 15.0f * s + reach));
    // Across the line from its tick, just clear of the surface.
    const ImVec2 across = sub(foot, mul(line.inward, line.to_surface + 4.0f * s + reach));
    // As the placer pads a label of the size the other readings give it.
    const float half_x = 0.5f * (size.x + 6.0f) + 2.0f, half_y = 0.5f * (size.y + 2.0f) + 2.0f;
    const auto box = [&](ImVec2 c) { return ImVec4(c.x - half_x, c.y - half_y, c.x + half_x, c.y + half_y); };
    marks.ticks.push_back({foot, metres, text, box(centre), box(across), true});
  }
  return marks;
}

// A number that would stick out past the view's edge slides inside it while its tick stays
// under it: it still names its place. Refused for one pixel out, a number of contact_area's
// projector lane sent the marks to the floor's other side, onto the speed readout's only place.
void keep_numbers_in(DistanceMarks& marks, const ImVec4& bounds) {
  const auto slide = [&](ImVec4& box) {
    const float out = box.x < bounds.x ? bounds.x - box.x : box.z > bounds.z ? bounds.z - box.z : 0.0f;
    if (std::abs(out) >= 0.5f * (box.z - box.x)) return;  // its tick would no longer be under it
    box.x += out, box.z += out;
  };
  for (DistanceMark& mark : marks.ticks) slide(mark.number_box), slide(mark.across_box);
}

}  // namespace

// Whether a tick is one of every `every`-th, counted from the start (0 m is always one).
bool counted(const DistanceMark& mark, std::size_t every, double step) {
  const double k = std::round(std::abs(mark.metres) / step);
  return std::fmod(k, static_cast<double>(every)) == 0.0;
}

std::optional<DistanceMarks> distance_marks_along(const Surface& surface, b2Vec2 origin, float body_length,
                                                  const draw::Camera& camera, const draw::Fonts& fonts,
                                                  const draw::LabelPlacer* labels) {
  const float s = fonts.scale, step = distance_mark_step(camera.pixels_per_metre, s, body_length);
  const std::optional<Ruler> under = ruler(surface, origin, camera, s, step);
  if (!under) return std::nullopt;
  DistanceMarks marks = numbered(*under, fonts);
  if (labels == nullptr) return marks;
  keep_numbers_in(marks, labels->bounds());
  // Under the surface when two of the numbers find room there, or as many as over it; else over
  // it: a lane's strip of ground is too thin to hold them (the trial's projector lanes showed none).
  const auto free_numbers = [&](const DistanceMarks& side) {
    return std::count_if(side.ticks.begin(), side.ticks.end(), [&](const DistanceMark& mark) { return labels->free(mark.number_box, true); });
  };
  const auto under_count = free_numbers(marks);
  if (under_count >= 2) return marks;
  const std::optional<Ruler> over = ruler(surface, origin, camera, s, step, true);
  if (!over) return marks;
  DistanceMarks over_marks = numbered(*over, fonts);
  keep_numbers_in(over_marks, labels->bounds());
  return free_numbers(over_marks) > under_count ? over_marks : marks;
}

namespace {

// Two numbers' boxes, as drawn (without the placer's padding), share a point.
bool numbers_meet(const ImVec4& a, const ImVec4& b) {
  return draw::overlaps(ImVec4(a.x + 2.0f, a.y + 2.0f, a.z - 2.0f, a.w - 2.0f), ImVec4(b.x + 2.0f, b.y + 2.0f, b.z - 2.0f, b.w - 2.0f));
}

}  // namespace

void number_marks(DistanceMarks& marks, const draw::LabelPlacer& labels, std::size_t fewest_every) {
  // Every marks.least_every-th tick, else every 2nd, 5th, 10th, 20th or 50th: the first whose
  // numbers, each at its tick where that is free (else across the line), lie clear of each other
  // and are two at least, so that the scale can be read (fewer numbers rather than none), else
  // the one giving the most. Ticks a fraction of the body's length apart (distance_mark_step)
  // are closer than their numbers are wide.
  fewest_every = std::max({fewest_every, marks.least_every, std::size_t{1}});
  std::size_t best_every = fewest_every, best_count = 0;
  for (const std::size_t every : {1u, 2u, 5u, 10u, 20u, 50u}) {
    if (every < fewest_every) continue;
    std::vector<ImVec4> chosen;
    for (const DistanceMark& mark : marks.ticks) {
      if (!counted(mark, every, marks.step)) continue;
      for (const ImVec4& box : {mark.number_box, mark.across_box}) {
        if (!labels.free(box, true)) continue;
        chosen.push_back(box);
        break;
      }
    }
    bool apart = true;
    for (std::size_t i = 0; i < chosen.size() && apart; ++i) {
      for (std::size_t j = i + 1; j < chosen.size() && apart; ++j) apart = !numbers_meet(chosen[i], chosen[j]);
    }
    if (!apart) continue;
    if (chosen.size() > best_count) best_every = every, best_count = chosen.size();
    if (chosen.size() >= 2) break;
  }
  for (DistanceMark& mark : marks.ticks) {
    mark.numbered = counted(mark, best_every, marks.step);
    // Its number across the line where its own side has no room.
    if (!labels.free(mark.number_box, true) && labels.free(mark.across_box, true)) std::swap(mark.number_box, mark.across_box);
  }
}

// The marks' line and ticks, told to the placer as they are drawn.
void draw_distance_lines(ImDrawList* draw, const DistanceMarks& marks, const draw::Theme& theme, float s, draw::LabelPlacer& labels) {
  draw->AddLine(marks.from, marks.to, theme.text, 1.5f * s);
  labels.avoid(draw::DrawnSegment{marks.from, marks.to, 1.5f * s});
  for (const DistanceMark& mark : marks.ticks) {
    const bool zero = std::abs(mark.metres) < 1e-9;
    const ImVec2 end = add(mark.foot, mul(marks.inward, (zero ? 12.0f : 8.0f) * s));
    draw->AddLine(mark.foot, end, theme.text, (zero ? 2.5f : 1.5f) * s);
    labels.avoid(draw::DrawnSegment{mark.foot, end, 1.0f * s});
  }
}

// Each number just beyond its tick or not at all: moved away it would name another place.
void draw_distance_numbers(ImDrawList* draw, const DistanceMarks& marks, const draw::Theme& theme, const draw::Fonts& fonts,
                           draw::LabelPlacer& labels) {
  std::vector<const DistanceMark*> shown;
  for (const DistanceMark& mark : marks.ticks) {
    const bool clear_of_shown = std::none_of(shown.begin(), shown.end(), [&](const DistanceMark* other) {
      return numbers_meet(mark.number_box, other->number_box);
    });
    if (mark.numbered && labels.free(mark.number_box, true) && clear_of_shown) shown.push_back(&mark);
  }
  for (const DistanceMark* mark : shown) {
    labels.take(mark->number_box, mark->text);
    const ImVec2 centre(0.5f * (mark->number_box.x + mark->number_box.z), 0.5f * (mark->number_box.y + mark->number_box.w));
    draw::draw_label(draw, fonts.small, centre, theme.text, theme.panel, mark->text.c_str());
  }
  // Fewer than two numbers cannot give the scale: the ticks' spacing then says it, in the
  // nearest free place to the middle of the line, on the numbers' side (it names no place).
  if (shown.size() >= 2 || marks.ticks.size() < 2) return;
  char spacing[48];
  std::snprintf(spacing, sizeof spacing, "ticks %g m apart", marks.step);
  const ImVec2 size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, spacing);
  const ImVec2 middle = mul(add(marks.from, marks.to), 0.5f);
  const ImVec2 wanted = add(middle, mul(marks.inward, 15.0f * fonts.scale + 0.5f * size.y + 2.0f));
  if (const std::optional<ImVec2> at = labels.place_if_free(wanted, ImVec2(size.x + 6.0f, size.y + 2.0f), spacing, true)) {
    draw::draw_label(draw, fonts.small, *at, theme.text, theme.panel, spacing);
  }
}

}  // namespace frictionlab::classroom
