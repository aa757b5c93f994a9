#include "draw/drawing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace frictionlab::draw {
namespace {

// The same arrow, as the placer knows it: an arrow is recorded once by its own width and again,
// wider, where it is kept off (arrow()), with the same ends.
bool same_ends(const DrawnSegment& a, const DrawnSegment& b) {
  return a.from.x == b.from.x && a.from.y == b.from.y && a.to.x == b.to.x && a.to.y == b.to.y;
}

// Whether two segments' centre lines cross: each one's ends on either side of the other.
bool crosses(const DrawnSegment& a, const DrawnSegment& b) {
  const auto side = [](ImVec2 from, ImVec2 to, ImVec2 p) { return (to.x - from.x) * (p.y - from.y) - (to.y - from.y) * (p.x - from.x); };
  return side(a.from, a.to, b.from) * side(a.from, a.to, b.to) < 0.0f && side(b.from, b.to, a.from) * side(b.from, b.to, a.to) < 0.0f;
}

// How far along `a` from its start its centre line meets `b`'s, px (for lines that cross).
float crossing_along(const DrawnSegment& a, const DrawnSegment& b) {
  const ImVec2 d = sub(a.to, a.from), e = sub(b.to, b.from), w = sub(b.from, a.from);
  const float denominator = d.x * e.y - d.y * e.x;
  if (denominator == 0.0f) return 0.0f;
  return (w.x * e.y - w.y * e.x) / denominator * length(d);
}

// Whether a box (x0, y0, x1, y1) and a segment's centre line lie more than `reach` and a pixel
// apart along x or along y: then no distance between them is `reach` or less, and the exact
// gap() need not be taken. (The placer asks gap() of every arrow and line for each of hundreds
// of places round a crowded value, a hypot each: contact_area's three thin lanes on a projector
// spent 17 ms a frame placing values; the pixel keeps the answer the same whatever gap()'s
// rounding.)
bool far_apart(const ImVec4& box, const DrawnSegment& segment, float reach) {
  const float margin = reach + 1.0f;
  return std::min(segment.from.x, segment.to.x) > box.z + margin || std::max(segment.from.x, segment.to.x) < box.x - margin ||
         std::min(segment.from.y, segment.to.y) > box.w + margin || std::max(segment.from.y, segment.to.y) < box.y - margin;
}

ImVec4 bounds_of(const DrawnSegment& segment) {
  return ImVec4(std::min(segment.from.x, segment.to.x), std::min(segment.from.y, segment.to.y),
                std::max(segment.from.x, segment.to.x), std::max(segment.from.y, segment.to.y));
}

}  // namespace

float gap(const DrawnSegment& a, const DrawnSegment& b) {
  if (crosses(a, b)) return 0.0f;
  // Apart, the nearest points are an end of one and a point of the other.
  const auto to_segment = [](ImVec2 p, const DrawnSegment& s) {
    const ImVec2 along = sub(s.to, s.from);
    const float span = along.x * along.x + along.y * along.y;
    const float f = span > 0.0f ? std::clamp(((p.x - s.from.x) * along.x + (p.y - s.from.y) * along.y) / span, 0.0f, 1.0f) : 0.0f;
    return length(sub(p, add(s.from, mul(along, f))));
  };
  return std::min({to_segment(a.from, b), to_segment(a.to, b), to_segment(b.from, a), to_segment(b.to, a)});
}

bool meet(const DrawnSegment& a, const DrawnSegment& b) { return gap(a, b) < a.half_width + b.half_width; }

float nice_length(float wanted) {
  const float power = std::pow(10.0f, std::floor(std::log10(wanted)));
  const float fraction = wanted / power;
  return (fraction < 1.5f ? 1.0f : fraction < 3.5f ? 2.0f : fraction < 7.5f ? 5.0f : 10.0f) * power;
}

float nice_length_within(float most) {
  const float power = std::pow(10.0f, std::floor(std::log10(most)));
  const float fraction = most / power;
  return (fraction < 2.0f ? 1.0f : fraction < 5.0f ? 2.0f : 5.0f) * power;
}

const std::string& material_name(const Scene& scene, const b2Fixture* fixture) {
  static const std::string none = "?";
  const int id = fixture_material(const_cast<b2Fixture*>(fixture));
  return id >= 0 && id < scene.pairs().material_count() ? scene.pairs().material(id).name : none;
}

ImU32 fixture_colour(const Scene& scene, const b2Fixture* fixture, const Theme& theme) {
  const std::string& material = material_name(scene, fixture);
  return material_colour(theme, material, scene.pairs().find_material(material));
}

bool overlaps(const ImVec4& box, const DrawnSegment& segment) {
  // The box grown by the half width, against the segment's centre line (Liang and Barsky's
  // clipping: the part of the line inside the box is empty or not).
  const float x0 = box.x - segment.half_width, y0 = box.y - segment.half_width;
  const float x1 = box.z + segment.half_width, y1 = box.w + segment.half_width;
  // Both ends beyond one side: no part inside (the placer's usual case, asked of every label,
  // mark and line for each place it tries).
  if ((segment.from.x < x0 && segment.to.x < x0) || (segment.from.x > x1 && segment.to.x > x1) ||
      (segment.from.y < y0 && segment.to.y < y0) || (segment.from.y > y1 && segment.to.y > y1)) {
    return false;
  }
  const float dx = segment.to.x - segment.from.x, dy = segment.to.y - segment.from.y;
  float enter = 0.0f, leave = 1.0f;
  const float p[4] = {-dx, dx, -dy, dy};
  const float q[4] = {segment.from.x - x0, x1 - segment.from.x, segment.from.y - y0, y1 - segment.from.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0f) {
      if (q[i] < 0.0f) return false;  // parallel to this side and outside it
      continue;
    }
    const float r = q[i] / p[i];
    if (p[i] < 0.0f) {
      enter = std::max(enter, r);
    } else {
      leave = std::min(leave, r);
    }
    if (enter > leave) return false;
  }
  return true;
}

float gap(const ImVec4& box, const DrawnSegment& segment) {
  if (overlaps(box, DrawnSegment{segment.from, segment.to, 0.0f})) return 0.0f;
  // Apart, the nearest points are a corner of the box and a point of the segment, or an end of
  // the segment and a point of the box.
  const auto to_box = [&](ImVec2 p) {
    return std::hypot(std::max({box.x - p.x, 0.0f, p.x - box.z}), std::max({box.y - p.y, 0.0f, p.y - box.w}));
  };
  const ImVec2 along = sub(segment.to, segment.from);
  const float span = along.x * along.x + along.y * along.y;
  const auto to_segment = [&](ImVec2 p) {
    const float f = span > 0.0f ? std::clamp(((p.x - segment.from.x) * along.x + (p.y - segment.from.y) * along.y) / span, 0.0f, 1.0f)
                                : 0.0f;
    return length(sub(p, add(segment.from, mul(along, f))));
  };
  float nearest = std::min(to_box(segment.from), to_box(segment.to));
  for (const ImVec2 corner : {ImVec2(box.x, box.y), ImVec2(box.z, box.y), ImVec2(box.z, box.w), ImVec2(box.x, box.w)}) {
    nearest = std::min(nearest, to_segment(corner));
  }
  return nearest;
}

bool LabelPlacer::beside(ImVec2 centre, ImVec2 size, const DrawnSegment& own) const {
  const ImVec4 box(centre.x - 0.5f * size.x, centre.y - 0.5f * size.y, centre.x + 0.5f * size.x, centre.y + 0.5f * size.y);
  // A pixel's margin each way, so that the box's corners rounded when drawn and recorded keep
  // to the rule.
  const float own_gap = gap(box, own);
  if (own_gap > size.y - 1.0f) return false;
  const auto same = [&](const DrawnSegment& other) {
    return other.from.x == own.from.x && other.from.y == own.from.y && other.to.x == own.to.x && other.to.y == own.to.y;
  };
  return std::none_of(arrows_.begin(), arrows_.end(), [&](const DrawnSegment& other) {
    return !same(other) && !far_apart(box, other, own_gap + 1.0f) && gap(box, other) <= own_gap + 1.0f;
  });
}

bool LabelPlacer::nearest_to_own(ImVec2 centre, ImVec2 size, const DrawnSegment& own) const {
  const ImVec4 box(centre.x - 0.5f * size.x, centre.y - 0.5f * size.y, centre.x + 0.5f * size.x, centre.y + 0.5f * size.y);
  const float own_gap = gap(box, own);
  return std::none_of(arrows_.begin(), arrows_.end(), [&](const DrawnSegment& other) {
    return !same_ends(other, own) && !far_apart(box, other, own_gap) && gap(box, other) <= own_gap;
  });
}

bool LabelPlacer::clear(const ImVec4& box, bool off_bodies) const {
  const auto any = [&](const auto& list) {
    return std::any_of(list.begin(), list.end(), [&](const auto& other) { return overlaps(box, other); });
  };
  return !any(taken_) && !any(marks_) && !any(segments_) && !(off_bodies && any(bodies_));
}

bool LabelPlacer::off_outlines(const ImVec4& box) const {
  return std::none_of(bodies_.begin(), bodies_.end(), [&](const ImVec4& body) {
    const bool inside = box.x >= body.x && box.z <= body.z && box.y >= body.y && box.w <= body.w;
    return overlaps(box, body) && !inside;
  });
}

bool LabelPlacer::apart(const ImVec4& box) const {
  // The boxes' padding counts towards the gap: their texts stand half a line and 4 px apart.
  const float gap = 0.5f * (box.w - box.y - 2.0f * pad);
  const ImVec4 wide(box.x - gap, box.y - gap, box.z + gap, box.w + gap);
  return std::none_of(taken_.begin(), taken_.end(), [&](const ImVec4& other) { return overlaps(wide, other); });
}

bool LabelPlacer::free(const ImVec4& box, bool off_bodies) const {
  const bool inside = box.x >= low_.x && box.y >= low_.y && box.z <= high_.x && box.w <= high_.y;
  return inside && clear(box, off_bodies);
}

ImVec4 LabelPlacer::box_around(ImVec2 centre, ImVec2 size) {
  return ImVec4(centre.x - 0.5f * size.x - pad, centre.y - 0.5f * size.y - pad, centre.x + 0.5f * size.x + pad,
                centre.y + 0.5f * size.y + pad);
}

ImVec2 LabelPlacer::moved_inside(ImVec2 centre, ImVec2 size) const {
  const float half_x = 0.5f * size.x + pad, half_y = 0.5f * size.y + pad;
  const float left = low_.x + half_x, right = std::max(left, high_.x - half_x);
  const float top = low_.y + half_y, bottom = std::max(top, high_.y - half_y);
  return ImVec2(std::clamp(centre.x, left, right), std::clamp(centre.y, top, bottom));
}

ImVec2 LabelPlacer::place(ImVec2 wanted, ImVec2 size, const std::string& text, bool off_bodies) {
  if (const std::optional<ImVec2> found = place_if_free(wanted, size, text, off_bodies)) return *found;
  // Nowhere free: where it was wanted, moved inside the view, over what is there.
  const ImVec2 at = moved_inside(wanted, size);
  take(box_around(at, size), text);
  return at;
}

std::vector<ImVec2> LabelPlacer::candidates(ImVec2 wanted, ImVec2 size, int rings) const {
  // Inside the view, so a label near its edge is moved in rather than cut.
  const auto inside = [&](ImVec2 c) { return moved_inside(c, size); };
  wanted = inside(wanted);
  // Rings of places around the wanted one, nearest first: above and below (a line of text
  // apart), then to the sides, then the corners between. Candidates are moved inside the view
  // first, so its edge is no obstacle here. Half steps, so a label fits a gap of one line and a half.
  const float step_y = size.y + 2.0f * pad, step_x = 0.5f * size.x + pad;
  const ImVec2 directions[8] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
  std::vector<ImVec2> places{wanted};
  for (int ring = 1; ring <= rings; ++ring) {
    const float reach = 0.5f * static_cast<float>(ring);
    for (const ImVec2& d : directions) {
      places.push_back(inside(ImVec2(wanted.x + d.x * step_x * reach, wanted.y + d.y * step_y * reach)));
    }
  }
  return places;
}

std::optional<ImVec2> LabelPlacer::place_if_free(ImVec2 wanted, ImVec2 size, const std::string& text, bool off_bodies) {
  const std::vector<ImVec2> places = candidates(wanted, size, 30);
  const auto search = [&](bool keep_off_bodies) -> std::optional<ImVec2> {
    for (const ImVec2& place : places) {
      if (clear(box_around(place, size), keep_off_bodies)) return place;
    }
    return std::nullopt;
  };
  // Where the bodies leave no room (a thin lane of blocks side by side), on a body rather than
  // on another label.
  std::optional<ImVec2> found = search(off_bodies);
  if (!found && off_bodies) found = search(false);
  if (found) take(box_around(*found, size), text);
  return found;
}

std::vector<ImVec2> LabelPlacer::places_by_arrow(const std::vector<ImVec2>& places, ImVec2 size,
                                                 const DrawnSegment& own) const {
  // The places near the tip, then along each side of the shaft from the tip back and behind
  // the tail, each clear of the arrow as wide as it is kept off (arrow()'s width, else its own).
  std::vector<ImVec2> near = places;
  const ImVec2 along = sub(own.to, own.from);
  const float span = length(along);
  if (span > 0.0f) {
    float half_width = own.half_width;
    for (const DrawnSegment& known : arrows_) {
      if (same_ends(known, own)) {
        half_width = std::max(half_width, known.half_width);
      }
    }
    const ImVec2 unit = mul(along, 1.0f / span), across(-unit.y, unit.x);
    const float half_across = 0.5f * (std::abs(across.x) * size.x + std::abs(across.y) * size.y) + pad + half_width + 1.0f;
    const float half_along = 0.5f * (std::abs(unit.x) * size.x + std::abs(unit.y) * size.y) + pad + half_width + 1.0f;
    for (const float f : {1.0f, 0.75f, 0.5f, 0.25f, 0.0f}) {
      for (const float side : {1.0f, -1.0f}) {
        near.push_back(moved_inside(add(add(own.from, mul(along, f)), mul(across, side * half_across)), size));
      }
    }
    near.push_back(moved_inside(sub(own.from, mul(unit, half_along)), size));
    // Then along each side in steps of a quarter line, from the box's far end level with the
    // tip's beyond it back to its far end level with the tail behind it: a short arrow among
    // others (a top block's weight in a stack, between its normal force and the pressing force
    // below; that pressing force, between the weight's tip and the lower block's weight) has
    // no room at the places above, but a gap a few pixels off them is beside it and nearer it
    // than any other arrow. (Issue 31: stacked_blocks' 9.81 N weight and pressing force on a
    // projector stood 38–74 px off with leaders, nearer other arrows.)
    const float box_along = 0.5f * (std::abs(unit.x) * size.x + std::abs(unit.y) * size.y) + pad;
    const float step = 0.25f * size.y;
    for (float s = span + box_along; s >= -box_along; s -= step) {
      for (const float side : {1.0f, -1.0f}) {
        near.push_back(moved_inside(add(add(own.from, mul(unit, s)), mul(across, side * half_across)), size));
      }
    }
  }
  std::vector<ImVec2> by_own;
  for (const ImVec2& place : near) {
    if (beside(place, size, own)) by_own.push_back(place);
  }
  return by_own;
}

// A leader (leader_line(), which draw_force() draws) that crosses no label, mark, line or other
// arrow: a leader over another value or arrow would join the wrong two.
bool LabelPlacer::leader_clear(ImVec2 place, ImVec2 size, const DrawnSegment& own, bool across_lines) const {
  const DrawnSegment leader = leader_line(box_around(place, size), own);
  const auto on = [&](const std::vector<ImVec4>& list) {
    return std::any_of(list.begin(), list.end(), [&](const ImVec4& other) { return overlaps(other, leader); });
  };
  // The lines drawn that are not arrows (a torque's arc, a spring, another value's leader, a
  // tool's line): a leader that crosses one is read as joined to it. (Their kept-off width
  // is for text: a leader may start within a spring's coils where its arrow does.)
  const auto is_arrow = [&](const DrawnSegment& segment) {
    return std::any_of(arrows_.begin(), arrows_.end(), [&](const DrawnSegment& arrow) { return same_ends(arrow, segment); });
  };
  // A leader that runs by a line's end within its own width meets it as one across it does.
  const ImVec4 leader_bounds = bounds_of(leader);
  const bool on_line = std::any_of(segments_.begin(), segments_.end(), [&](const DrawnSegment& other) {
    return !far_apart(leader_bounds, other, leader.half_width) && !is_arrow(other) && gap(leader, other) < leader.half_width;
  });
  // Another arrow is avoided by its centre line: the leader starts on its own arrow, within
  // the kept-off width of an arrow that starts where it does (a normal force and a friction
  // at one contact), and a leader that crosses another arrow joins the value to both.
  // Where the forces at one contact start together, another arrow may pass within half a
  // line of the own arrow, and a leader that crosses it there leaves from where they meet.
  const bool crosses_arrow = std::any_of(arrows_.begin(), arrows_.end(), [&](const DrawnSegment& other) {
    return !same_ends(other, own) && crosses(leader, other) &&
           (!across_lines || crossing_along(leader, other) > 0.5f * size.y);
  });
  return length(sub(leader.to, leader.from)) <= longest_leader(size) && !on(taken_) && !on(marks_) &&
         (across_lines || !on_line) &&
         !crosses_arrow;
}

// Off every body but the force's own: a value moved away from its arrow lands on whatever is
// there, and on another body's face it reads as that body's (issue 31: a block's face in a
// stack).
bool LabelPlacer::off_other_bodies(const ImVec4& box, const b2Body* own_body) const {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const bool its_own = own_body != nullptr && body_owners_[k] == own_body;
    if (!its_own && overlaps(box, bodies_[k])) return false;
  }
  return true;
}

std::optional<ImVec2> LabelPlacer::place_with_leader(ImVec2 wanted, ImVec2 size, const DrawnSegment& own,
                                                     const b2Body* own_body, bool off_outlines_only) const {
  // The nearest place to the arrow, of a grid of places half a line apart round it as far as a
  // leader reaches, from which a leader crosses no line nor arrow, where no other arrow is nearer
  // the value, off every body but its own (or on one, with `on_bodies`), off the bodies' outlines
  // where asked; apart from the other labels first (apart()), where such a place is. (The rings
  // round `wanted` run along eight rays only, and missed stacked_blocks' top block's weight's
  // place over the block: its value lay across the block's edge instead.)
  const auto on_grid = [&](bool need_off_outlines, bool on_bodies) -> std::optional<ImVec2> {
    const float step = 0.5f * size.y, reach_x = longest_leader(size) + 0.5f * size.x, reach_y = longest_leader(size) + 0.5f * size.y;
    const ImVec2 low(std::min(own.from.x, own.to.x) - reach_x, std::min(own.from.y, own.to.y) - reach_y);
    const ImVec2 high(std::max(own.from.x, own.to.x) + reach_x, std::max(own.from.y, own.to.y) + reach_y);
    std::optional<ImVec2> nearest;
    float nearest_gap = std::numeric_limits<float>::max();
    bool nearest_apart = false;
    // Moved inside the view, as candidates() moves them: the room by its edge counts too. Rows
    // and columns moved onto the one before are the same places, tried once (a projector's thin
    // lanes moved most of the grid's rows onto their edges).
    float last_row = std::numeric_limits<float>::quiet_NaN();
    for (float y = low.y; y <= high.y; y += step) {
      const float row = moved_inside(ImVec2(low.x, y), size).y;
      if (row == last_row) continue;
      last_row = row;
      float last_column = std::numeric_limits<float>::quiet_NaN();
      for (float x = low.x; x <= high.x; x += step) {
        const ImVec2 place = moved_inside(ImVec2(x, y), size);
        if (place.x == last_column) continue;
        last_column = place.x;
        const ImVec4 box = box_around(place, size);
        const float own_gap = gap(box, own);
        // Apart from the other labels matters only against a place found already, and for the
        // one kept.
        if (nearest && own_gap >= nearest_gap && !nearest_apart) {
          // No nearer, and not apart where the kept one is not either: only apartness could win.
          if (!apart(box)) continue;
        } else if (nearest && nearest_apart && (own_gap >= nearest_gap || !apart(box))) {
          continue;
        }
        if (!clear(box, false) || (!on_bodies && !off_other_bodies(box, own_body)) || (need_off_outlines && !off_outlines(box)) ||
            !nearest_to_own(place, size, own) || !leader_clear(place, size, own, false)) {
          continue;
        }
        nearest_gap = own_gap, nearest = place, nearest_apart = apart(box);
      }
    }
    return nearest;
  };
  if (off_outlines_only) return on_grid(true, false);
  // Across a line that is not an arrow, or across another arrow where they start together,
  // only where nothing else is near (a wheel's friction inside its torque's arc, a friction
  // beside a normal force): a value by its arrow reads better than one far off with no leader.
  const std::vector<ImVec2> further = candidates(wanted, size, 30);
  // On another body last: a value on a block's face with a leader to its own arrow is still
  // read as its arrow's, where one lines away with no leader is read as nobody's (a stack's
  // friction between its blocks, hemmed in by the normal forces and weights).
  // And, at each of those, first where no other arrow is nearer the value than its own: a value with a leader
  // beside another arrow is read as that one's (issue 31: stacked_blocks' pressing force, 9.81 N,
  // sat by the bottom block's weight, 27 px from it and 43 px from its own arrow).
  // Each place's answers are kept across the eight passes (taken as first asked): the placer
  // does not change meanwhile, and asking them again for each of a few hundred places made this
  // most of a crowded frame's cost.
  enum class Answer : char { unknown, no, yes };
  struct Tried {
    Answer clear = Answer::unknown, off_others = Answer::unknown, nearest = Answer::unknown;
    Answer leader[2] = {Answer::unknown, Answer::unknown};
  };
  std::vector<Tried> tried(further.size());
  const auto ask = [](Answer& kept, const auto& question) {
    if (kept == Answer::unknown) kept = question() ? Answer::yes : Answer::no;
    return kept == Answer::yes;
  };
  for (const bool on_bodies : {false, true}) {
    for (const bool across_lines : {false, true}) {
      for (const bool nearest_first : {true, false}) {
        for (std::size_t k = 0; k < further.size(); ++k) {
          const ImVec2& place = further[k];
          Tried& t = tried[k];
          const ImVec4 box = box_around(place, size);
          if (ask(t.clear, [&] { return clear(box, false); }) &&
              (on_bodies || ask(t.off_others, [&] { return off_other_bodies(box, own_body); })) &&
              (!nearest_first || ask(t.nearest, [&] { return nearest_to_own(place, size, own); })) &&
              ask(t.leader[across_lines ? 1 : 0], [&] { return leader_clear(place, size, own, across_lines); })) {
            return place;
          }
        }
      }
    }
  }
  // None along the rays: the grid's, off the other bodies, else on one.
  if (const std::optional<ImVec2> found = on_grid(false, false)) return found;
  return on_grid(false, true);
}

std::optional<ImVec2> LabelPlacer::place_beside(ImVec2 wanted, ImVec2 size, const std::string& text,
                                                const DrawnSegment* own, bool* with_leader, const b2Body* own_body) {
  if (with_leader != nullptr) *with_leader = false;
  const std::vector<ImVec2> places = candidates(wanted, size, beside_rings);
  const auto first_clear = [&](const std::vector<ImVec2>& list, bool off_bodies) -> std::optional<ImVec2> {
    for (const ImVec2& place : list) {
      if (clear(box_around(place, size), off_bodies)) return place;
    }
    return std::nullopt;
  };
  if (own != nullptr) {
    const std::vector<ImVec2> by_own = places_by_arrow(places, size, *own);
    // Beside it off the bodies' outlines first, apart from the other labels too where it can be
    // (off_outlines(), apart()): off the bodies, else on its own body whole. Else off the
    // outlines with a leader: a value across a body's edge crowds the picture more than a short
    // line to it.
    // Off the surfaces' lines where it can be, the least of these preferences (surface()).
    const auto off_surfaces = [&](const ImVec4& box) {
      return std::none_of(surfaces_.begin(), surfaces_.end(), [&](const DrawnSegment& line) { return overlaps(box, line); });
    };
    std::optional<ImVec2> found;
    for (const bool apart_too : {true, false}) {
      for (const bool off_bodies : {true, false}) {
        for (const bool off_the_surfaces : {true, false}) {
          for (std::size_t k = 0; k < by_own.size() && !found; ++k) {
            const ImVec4 box = box_around(by_own[k], size);
            if (clear(box, off_bodies) && off_other_bodies(box, own_body) && off_outlines(box) && (!apart_too || apart(box)) &&
                (!off_the_surfaces || off_surfaces(box))) {
              found = by_own[k];
            }
          }
        }
      }
    }
    if (!found) {
      found = place_with_leader(wanted, size, *own, own_body, true);
      if (found && with_leader != nullptr) *with_leader = true;
    }
    if (!found) found = first_clear(by_own, true);
    // Else on its own body, off the others: beside its arrow on another block's face it reads
    // as that block's (issue 31), as a value with a leader does (place_with_leader).
    for (std::size_t k = 0; k < by_own.size() && !found; ++k) {
      const ImVec4 box = box_around(by_own[k], size);
      if (clear(box, false) && off_other_bodies(box, own_body)) found = by_own[k];
    }
    // Nowhere free beside it: the nearest free place from which a leader to the arrow crosses
    // nothing it would join the value to; else beside it on another body.
    if (!found) {
      found = place_with_leader(wanted, size, *own, own_body);
      if (found && with_leader != nullptr) *with_leader = true;
    }
    if (!found) found = first_clear(by_own, false);
    if (found) {
      take(box_around(*found, size), text);
      return found;
    }
  }
  // Near the tip, off the moving bodies (a normal force's value was read as the body's); else
  // near, on a body (the box is opaque and reads there).
  std::optional<ImVec2> found = first_clear(places, true);
  if (!found) found = first_clear(places, false);
  // A thin lane of blocks side by side may have no free place near: the nearest free one further
  // off, as the other labels search, rather than a value over a lane's name or another value.
  if (!found) found = first_clear(candidates(wanted, size, 30), false);
  if (found) take(box_around(*found, size), text);
  return found;
}

void draw_label(ImDrawList* draw, ImFont* font, ImVec2 centre, ImU32 colour, ImU32 background, const char* text) {
  const ImVec2 size = font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text);
  const ImVec2 corner(std::round(centre.x - 0.5f * size.x), std::round(centre.y - 0.5f * size.y));
  // The box is opaque, so the text reads the same over the ground, a body or the sky: at 84 %
  // a label over a dark body read 3.1:1. Its ink is the arrow's colour where that reads 4.5:1
  // on the box, else a shade of it that does (draw/theme.h).
  if (background != 0) {
    background |= IM_COL32_A_MASK;
    draw->AddRectFilled(ImVec2(corner.x - 3, corner.y - 1), ImVec2(corner.x + size.x + 3, corner.y + size.y + 1), background,
                        3.0f);
    colour = readable_ink(colour, background);
  }
  draw->AddText(font, font->FontSize, corner, colour, text);
}

void draw_arrow(ImDrawList* draw, ImVec2 tail, ImVec2 tip, ImU32 colour, float thickness, ImU32 halo, bool broken,
                bool plate) {
  const ImVec2 along = sub(tip, tail);
  const float span = length(along);
  if (span < 1e-3f) return;
  const ImVec2 unit = mul(along, 1.0f / span);
  const ImVec2 across(-unit.y, unit.x);
  const float head = std::min(4.0f * thickness, 0.6f * span);
  const ImVec2 base = sub(tip, mul(unit, head));
  const ImVec2 left = add(base, mul(across, 0.45f * head)), right = sub(base, mul(across, 0.45f * head));
  // A broken shaft's dashes from the tail, the last one running on under the head: gaps of
  // broken_gap, at least one, and the dashes as long as fills the shaft whole from tail to head.
  const auto for_each_dash = [&](const auto& dash_from_to) {
    const float shaft = span - head, gap = broken_gap(thickness);
    const int gaps = std::max(1, static_cast<int>(std::lround((shaft - broken_dash(thickness)) / (broken_dash(thickness) + gap))));
    const float dash = std::max(0.0f, (shaft - static_cast<float>(gaps) * gap) / static_cast<float>(gaps + 1));
    for (int i = 0; i <= gaps; ++i) {
      const float from = static_cast<float>(i) * (dash + gap);
      const float to = i == gaps ? shaft + 0.3f * head : from + dash;
      dash_from_to(add(tail, mul(unit, from)), add(tail, mul(unit, to)));
    }
  };
  if (halo != 0) {
    if (plate) {
      // On a plate: the arrow's shape grown a thickness and a pixel all round, the surround an
      // arrow over a fill like its colour needs (ForceArrows.EachStandsOutFromASurroundAsWideAsItsShaft),
      // with round corners (a grown triangle's mitred tip would reach 2.5 widths past the arrow's),
      // whole under a broken shaft's gaps: an outline of the arrow, not the strip as wide as its
      // head from tail to tip that the dark theme drew as black bars beside terrain's weights on
      // a projector (issue 31).
      const float width = thickness + 1.0f;
      const ImVec2 head_base = add(base, mul(unit, 0.3f * head));
      draw->AddLine(tail, head_base, halo, thickness + 2.0f * width);
      draw->AddCircleFilled(tail, 0.5f * thickness + width, halo, 16);
      draw->AddTriangleFilled(tip, left, right, halo);
      const ImVec2 corners[3] = {tip, left, right};
      for (int k = 0; k < 3; ++k) {
        draw->AddLine(corners[k], corners[(k + 1) % 3], halo, 2.0f * width);
        draw->AddCircleFilled(corners[k], width, halo, 16);
      }
    } else {
      // The outline first, arrow_halo_width() past the shaft's sides and the head's edges: the head
      // grown about its incentre, which moves each edge out by the same width.
      const float width = arrow_halo_width(thickness);
      const float a = length(sub(left, right)), b = length(sub(tip, right)), c = length(sub(tip, left));
      const ImVec2 incentre = mul(add(add(mul(tip, a), mul(left, b)), mul(right, c)), 1.0f / (a + b + c));
      const float area = 0.5f * std::abs((left.x - tip.x) * (right.y - tip.y) - (left.y - tip.y) * (right.x - tip.x));
      const float grow = 1.0f + width / std::max(2.0f * area / (a + b + c), 1e-3f);
      const auto grown = [&](ImVec2 p) { return add(incentre, mul(sub(p, incentre), grow)); };
      if (broken) {
        for_each_dash([&](ImVec2 from, ImVec2 to) { draw->AddLine(sub(from, mul(unit, width)), add(to, mul(unit, width)), halo, thickness + 2.0f * width); });
      } else {
        draw->AddLine(sub(tail, mul(unit, width)), add(base, mul(unit, 0.3f * head)), halo, thickness + 2.0f * width);
      }
      draw->AddTriangleFilled(grown(tip), grown(left), grown(right), halo);
    }
  }
  if (broken) {
    for_each_dash([&](ImVec2 from, ImVec2 to) { draw->AddLine(from, to, colour, thickness); });
  } else {
    // The shaft runs on under the head, so no seam of anti-aliased edges shows between them.
    draw->AddLine(tail, add(base, mul(unit, 0.3f * head)), colour, thickness);
  }
  draw->AddTriangleFilled(tip, left, right, colour);
}

DrawnSegment leader_line(const ImVec4& box, const DrawnSegment& arrow) {
  // From the arrow's point nearest the box's centre to the box's edge nearest that point: the
  // shortest such line, so it crosses as little of the picture as it can.
  const ImVec2 centre(0.5f * (box.x + box.z), 0.5f * (box.y + box.w));
  const ImVec2 along = sub(arrow.to, arrow.from);
  const float span = along.x * along.x + along.y * along.y;
  const float f = span > 0.0f
                      ? std::clamp(((centre.x - arrow.from.x) * along.x + (centre.y - arrow.from.y) * along.y) / span, 0.0f, 1.0f)
                      : 0.0f;
  const ImVec2 on_arrow = add(arrow.from, mul(along, f));
  const ImVec2 on_box(std::clamp(on_arrow.x, box.x, box.z), std::clamp(on_arrow.y, box.y, box.w));
  // Half as wide as the arrow's shaft, and at least a pixel, so it reads as a pointer, not a force.
  return DrawnSegment{on_arrow, on_box, std::max(0.5f, 0.5f * arrow.half_width)};
}

void draw_force(ImDrawList* draw, const ScreenArrow& arrow, const Theme& theme, ImFont* font, float thickness,
                LabelPlacer& labels) {
  draw_force(draw, arrow, theme, font, thickness, labels, format_quantity(arrow.force.force.Length(), "N"));
}

PlacedForce place_force_label(const ScreenArrow& arrow, ImFont* font, float thickness, LabelPlacer& labels,
                              const std::string& text, std::size_t drawn, std::optional<ImVec2> wanted) {
  PlacedForce placed{arrow, text, ImVec2(0.0f, 0.0f), std::nullopt, std::nullopt, false};
  const DrawnSegment own{arrow.tail, arrow.tip, 0.5f * thickness};
  if (text.empty()) {
    labels.force_label({own, std::nullopt, text, arrow.force.kind, std::nullopt, arrow.force.body, !arrow.to_scale, drawn});
    placed.beside = true;  // nothing to read
    return placed;
  }
  placed.size = font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, text.c_str());
  const ImVec2 unit = mul(sub(arrow.tip, arrow.tail), 1.0f / arrow.length());
  // Just beyond the tip, far enough along the arrow's line that the text clears the head.
  const float reach = 0.5f * (std::abs(unit.x) * placed.size.x + std::abs(unit.y) * placed.size.y) + 1.5f * thickness;
  // By its own arrow (place_beside): off the moving bodies where that is as near (a normal
  // force's arrow points into the body it pushes; a spring's runs along the spring).
  bool with_leader = false;
  placed.at = labels.place_beside(wanted.value_or(add(arrow.tip, mul(unit, reach))), placed.size, text, &own, &with_leader,
                                  arrow.force.body);
  if (placed.at && with_leader) {
    // No free place within a line of the arrow and nearer it than any other (a friction of a few
    // pixels where a normal force starts, a crowded stack): the value went to the nearest free
    // place, and a thin line from the arrow to it says whose it is, as a textbook's figure does.
    // Later labels keep off the line.
    placed.leader = leader_line(LabelPlacer::box_around(*placed.at, placed.size), own);
    labels.avoid(*placed.leader);
  }
  // A value with a leader counts as by its arrow where no other arrow is nearer it: one by
  // another arrow is away, and draw_world places it again first.
  placed.beside = placed.at && (with_leader ? labels.nearest_to_own(*placed.at, placed.size, own)
                                            : labels.beside(*placed.at, placed.size, own));
  const std::optional<ImVec4> box = placed.at ? std::optional<ImVec4>(labels.labels().back()) : std::nullopt;
  labels.force_label({own, box, text, arrow.force.kind, placed.leader, arrow.force.body, !arrow.to_scale, drawn});
  return placed;
}

void draw_placed_force(ImDrawList* draw, const PlacedForce& placed, const Theme& theme, ImFont* font, float thickness) {
  const ImU32 colour = theme.force[static_cast<int>(placed.arrow.force.kind)];
  draw_arrow(draw, placed.arrow.tail, placed.arrow.tip, colour, thickness, theme.arrow_halo, !placed.arrow.to_scale,
             placed.arrow.over_its_like);
  if (placed.leader) draw->AddLine(placed.leader->from, placed.leader->to, colour, 2.0f * placed.leader->half_width);
  if (placed.at) draw_label(draw, font, *placed.at, colour, theme.panel, placed.text.c_str());
}

void draw_force(ImDrawList* draw, const ScreenArrow& arrow, const Theme& theme, ImFont* font, float thickness,
                LabelPlacer& labels, const std::string& text) {
  // Each drawn as soon as placed: its place in the drawing is the number placed before it.
  draw_placed_force(draw, place_force_label(arrow, font, thickness, labels, text, labels.force_labels().size()), theme,
                    font, thickness);
}

TorqueArc torque_arc(ImVec2 centre, float radius, double torque) {
  TorqueArc arc{centre, radius, torque, {}};
  // Screen y runs down, so a counter-clockwise torque turns the screen angle down.
  const float sense = torque >= 0.0 ? -1.0f : 1.0f;
  const float start = -0.25f * b2_pi;
  constexpr int segments = 24;
  for (int i = 0; i <= segments; ++i) {
    const float angle = start + sense * 1.5f * b2_pi * static_cast<float>(i) / segments;
    arc.points.push_back(ImVec2(centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)));
  }
  return arc;
}

void avoid_arc(LabelPlacer& labels, const TorqueArc& arc, float width) {
  for (std::size_t k = 1; k < arc.points.size(); ++k) labels.avoid(DrawnSegment{arc.points[k - 1], arc.points[k], width});
}

void draw_torque_arrow(ImDrawList* draw, const TorqueArc& arc, ImU32 colour, float thickness) {
  draw->AddPolyline(arc.points.data(), static_cast<int>(arc.points.size()), colour, ImDrawFlags_None, thickness);
  // The head, along the arc's last chord.
  const ImVec2 tip = arc.points.back();
  ImVec2 along = sub(tip, arc.points[arc.points.size() - 2]);
  along = mul(along, 1.0f / std::sqrt(along.x * along.x + along.y * along.y));
  const ImVec2 across(-along.y, along.x);
  const float head = 3.0f * thickness;
  draw->AddTriangleFilled(add(tip, mul(along, head)), add(tip, mul(across, 0.6f * head)), sub(tip, mul(across, 0.6f * head)),
                          colour);
}

PlacedTorque place_torque_value(const TorqueArc& arc, ImFont* font, float thickness, LabelPlacer& labels) {
  PlacedTorque placed{format_quantity(std::abs(arc.torque), "N·m"), std::nullopt};
  const ImVec2 size = font->CalcTextSizeA(font->FontSize, 1e6f, 0.0f, placed.text.c_str());
  const ImVec2 outward = mul(sub(arc.points.front(), arc.centre), 1.0f / arc.radius);
  const ImVec2 wanted = add(arc.points.front(), mul(outward, 0.5f * size.x + 2.0f * thickness));
  placed.at = labels.place_beside(wanted, size, placed.text);
  return placed;
}

void draw_torque(ImDrawList* draw, const TorqueArc& arc, ImU32 colour, ImFont* font, ImU32 background, float thickness,
                 const PlacedTorque& placed) {
  draw_torque_arrow(draw, arc, colour, thickness);
  if (placed.at) draw_label(draw, font, *placed.at, colour, background, placed.text.c_str());
}

void draw_polygon(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera,
                  ImU32 fill, ImU32 outline, float thickness) {
  ImVec2 points[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) points[i] = camera.to_screen(body->GetWorldPoint(shape.m_vertices[i]));
  draw->AddConvexPolyFilled(points, shape.m_count, fill);
  draw->AddPolyline(points, shape.m_count, outline, ImDrawFlags_Closed, thickness);
}


}  // namespace frictionlab::draw
