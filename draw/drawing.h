// Drawing pieces the world view, the legend and the free-body inset share: labels that keep
// out of each other's way, arrows, force arrows with their values, polygons, and a few facts
// about fixtures (is it ground, what is it made of).
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "draw/camera.h"
#include "draw/overlays.h"
#include "draw/theme.h"
#include "physics/scene.h"

namespace frictionlab::draw {

inline ImVec2 add(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
inline ImVec2 sub(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
inline ImVec2 mul(ImVec2 a, float s) { return ImVec2(a.x * s, a.y * s); }
inline float length(ImVec2 a) { return std::hypot(a.x, a.y); }

// 1, 2 or 5 times a power of ten: the nicest length near `wanted` (from 0.57 to 1.43 times it:
// 3.5 rounds up to 5).
float nice_length(float wanted);
// The longest 1, 2 or 5 times a power of ten that is no longer than `most`: for a scale bar
// that must fit its room, where a bar rounded up would be cut and read wrong.
float nice_length_within(float most);
const std::string& material_name(const Scene& scene, const b2Fixture* fixture);
ImU32 fixture_colour(const Scene& scene, const b2Fixture* fixture, const Theme& theme);

// A line drawn in the picture, as thick as it is drawn: an arrow's shaft and head.
struct DrawnSegment {
  ImVec2 from, to;
  float half_width;
};
// Whether a box (x0, y0, x1, y1) and a thick segment share any point.
bool overlaps(const ImVec4& box, const DrawnSegment& segment);
// How far a box lies from a segment's centre line (0 where they meet), px.
float gap(const ImVec4& box, const DrawnSegment& segment);
// How far apart two segments' centre lines are (0 where they cross), px.
float gap(const DrawnSegment& a, const DrawnSegment& b);
// Whether two thick segments, as drawn, share any point.
bool meet(const DrawnSegment& a, const DrawnSegment& b);
inline bool overlaps(const ImVec4& a, const ImVec4& b) { return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w; }

// Keeps text labels off each other and off the arrows and marks drawn, and inside the view,
// within one picture. Tell it what is drawn (avoid) before asking where labels go (place).
class LabelPlacer {
 public:
  LabelPlacer(ImVec2 corner, ImVec2 size) : low_(corner), high_(add(corner, size)) {}
  void avoid(const DrawnSegment& segment) { segments_.push_back(segment); }
  // A force's arrow, as wide as labels keep off it: avoided, and known as an arrow, so that
  // place_beside() puts each value nearer its own arrow than any other.
  void arrow(const DrawnSegment& segment) {
    avoid(segment);
    arrows_.push_back(segment);
  }
  void avoid(const ImVec4& box) { marks_.push_back(box); }
  // A surface's line (a ground's top), which a force's value beside its arrow keeps off where
  // a place beside the arrow off it is free: a weight's value at its tip, where the view ends at
  // the floor, lay across the floor's line (incline's 9.81 N, a teacher's trial, issue 31), read
  // as standing on it. Only a preference: a value across it beside its arrow reads better than
  // one lines away.
  void surface(const DrawnSegment& line) { surfaces_.push_back(line); }
  // A moving body's box on screen. The lesson's own labels may lie on a body (a contact's word
  // goes into the body under it); a measuring tool's reading, which names the body, keeps off.
  // `who` is the body, so that a force's value may lie on its own body and on no other.
  void body(const ImVec4& box, const b2Body* who = nullptr) {
    bodies_.push_back(box);
    body_owners_.push_back(who);
  }
  // Where a label of this size goes: at `wanted` (its centre), or the nearest place around it
  // that covers no label, arrow or mark (nor body, with `off_bodies`, unless the bodies leave no
  // such place near); `wanted` itself when there is none near. `text` is kept with its box for
  // the layout's tests.
  ImVec2 place(ImVec2 wanted, ImVec2 size, const std::string& text = {}, bool off_bodies = false);
  // As place(), but nowhere (nullopt, nothing taken) when no place near is free: a force's value
  // or a contact's word left out is better than one drawn over another label, where neither
  // can be read (a projector's thin lanes of blocks side by side).
  std::optional<ImVec2> place_if_free(ImVec2 wanted, ImVec2 size, const std::string& text = {}, bool off_bodies = false);
  // A force's value, near its arrow where there is room: at `wanted` (just beyond the tip) or
  // the nearest free place within `beside_rings` half steps of it, off the moving bodies if it
  // can be, else on one (its box is opaque); where a thin lane leaves nothing free near, the
  // nearest free place as place_if_free() finds it; nowhere (nullopt) only where nothing is free
  // at all, a value over another label or a lane's name being read as neither. Issue 31: a value
  // left out (tipping_box's friction on a projector) was read as no force, and one found many
  // lines away (stacked_blocks' normal forces, a ladder's weight by its foot) as another arrow's.
  // With `own`, the value's own arrow (given to arrow()), a place beside it comes first: the
  // text's box within one line of text (size.y) of the arrow's line and further from every
  // other arrow than from it, near the tip, else along either side of the shaft or behind the
  // tail (where a short arrow among others leaves its tip no room). Where none of those is free
  // (a friction of a few pixels where a normal force starts), the nearest free place joined to
  // the arrow by a leader (leader_line()) no longer than longest_leader() that crosses no label
  // or mark, and, where such a place is near, no drawn line, no other arrow (but within half a
  // line of its start, where forces at one contact start together), the value's box off every
  // body but `own_body`, the one the force acts on (on another block's face it reads as that
  // block's); `with_leader` says the value needs the leader drawn.
  std::optional<ImVec2> place_beside(ImVec2 wanted, ImVec2 size, const std::string& text = {},
                                     const DrawnSegment* own = nullptr, bool* with_leader = nullptr,
                                     const b2Body* own_body = nullptr);
  // A leader's longest: three lines of its text, so the eye follows it from value to arrow
  // without meeting another value; a value further off stays where the general search puts it.
  static float longest_leader(ImVec2 size) { return 3.0f * size.y; }
  // Whether a text's box centred at `centre` is beside `own` by place_beside()'s rule.
  bool beside(ImVec2 centre, ImVec2 size, const DrawnSegment& own) const;
  // Whether no other arrow known is as near a text's box centred at `centre` as `own` is: a
  // value joined to its arrow by a leader is still read as the nearest arrow's first.
  bool nearest_to_own(ImVec2 centre, ImVec2 size, const DrawnSegment& own) const;
  static constexpr int beside_rings = 6;
  // How far place_beside() moves a label's centre from `wanted` (in x and in y) where there is
  // room near: the last ring's reach, for tests that check each value is by its arrow.
  static ImVec2 beside_reach(ImVec2 size) {
    const float rings = 0.5f * static_cast<float>(beside_rings);
    return ImVec2(rings * (0.5f * size.x + pad), rings * (size.y + 2.0f * pad));
  }
  // A force's arrow and where its value went (nullopt: it has none), for the layout's tests.
  struct ForceLabel {
    DrawnSegment arrow;
    std::optional<ImVec4> box;  // padding included
    std::string text;
    ForceKind kind = ForceKind::applied;
    // A thin line from a point of the arrow to the value's box, drawn where no free place is
    // beside the arrow (beside()), so that the value is read as this arrow's and no other's.
    std::optional<DrawnSegment> leader;
    const b2Body* body = nullptr;  // the body it acts on
    // Drawn longer than to scale, its shaft broken (ScreenArrow::to_scale false), as the legend
    // says of the forces under its number.
    bool broken = false;
    // Its place in the order the arrows are drawn, 0 first: a later arrow lies over an earlier
    // where they meet (a contact's forces over a weight, draw_world).
    std::size_t drawn = 0;
  };
  void force_label(const ForceLabel& label) { force_labels_.push_back(label); }
  const std::vector<ForceLabel>& force_labels() const { return force_labels_; }
  // A label's box at `centre`, padding included, as place() takes it.
  static ImVec4 box_around(ImVec2 centre, ImVec2 size);
  // Whether a label's box (padding included) would cover nothing known and stay in the view.
  bool free(const ImVec4& box, bool off_bodies) const;
  // Whether a label's box (padding included) lies wholly on or wholly off each moving body,
  // across none's outline; and whether it stands clear of the labels placed by half its text's
  // height at least. A label beside what it names stands so where it can (issue 31:
  // stacked_blocks' values a few pixels apart round its top block, one across the top block's
  // edge, read as crowded); a force's value across a body's outline, with a short leader instead.
  bool off_outlines(const ImVec4& box) const;
  bool apart(const ImVec4& box) const;
  // Takes a box found free() as it is: a label that names a place (a distance mark's number)
  // goes there or nowhere.
  void take(const ImVec4& box, const std::string& text) {
    taken_.push_back(box);
    texts_.push_back(text);
  }

  // What it placed and what it was told to avoid, for tests that check the picture's layout.
  const std::vector<ImVec4>& labels() const { return taken_; }  // x0, y0, x1, y1, padding included
  const std::vector<std::string>& texts() const { return texts_; }  // each label's text
  const std::vector<DrawnSegment>& segments() const { return segments_; }
  const std::vector<DrawnSegment>& arrows() const { return arrows_; }  // the forces' arrows among segments()
  const std::vector<ImVec4>& marks() const { return marks_; }
  const std::vector<ImVec4>& bodies() const { return bodies_; }
  ImVec4 bounds() const { return ImVec4(low_.x, low_.y, high_.x, high_.y); }

 private:
  bool clear(const ImVec4& box, bool off_bodies) const;  // covers nothing known
  static constexpr float pad = 2.0f;  // px kept clear around a label's text
  ImVec2 moved_inside(ImVec2 centre, ImVec2 size) const;  // a centre moved so the box stays in the view
  // The places around `wanted` that the searches try, nearest first: `wanted` (moved inside the
  // view), then `rings` rings of eight at half steps.
  std::vector<ImVec2> candidates(ImVec2 wanted, ImVec2 size, int rings) const;
  // place_beside()'s parts for a value with its own arrow: the places beside it (near the tip,
  // along each side of the shaft, behind the tail); whether a leader from `place` to the arrow
  // crosses nothing it would join the value to; whether a box is off every body but `own_body`;
  // and the nearest place with such a leader, where none is free beside the arrow.
  std::vector<ImVec2> places_by_arrow(const std::vector<ImVec2>& places, ImVec2 size, const DrawnSegment& own) const;
  bool leader_clear(ImVec2 place, ImVec2 size, const DrawnSegment& own, bool across_lines) const;
  bool off_other_bodies(const ImVec4& box, const b2Body* own_body) const;
  // `off_outlines_only`: only a place off_outlines() from which a leader crosses no line, the
  // nearest to the arrow; none where there is none.
  std::optional<ImVec2> place_with_leader(ImVec2 wanted, ImVec2 size, const DrawnSegment& own,
                                          const b2Body* own_body, bool off_outlines_only = false) const;

  ImVec2 low_, high_;          // the view labels must stay in
  std::vector<ImVec4> taken_;  // x0, y0, x1, y1
  std::vector<std::string> texts_;
  std::vector<DrawnSegment> segments_;
  std::vector<DrawnSegment> arrows_;  // the forces' arrows among segments_
  std::vector<DrawnSegment> surfaces_;
  std::vector<ImVec4> marks_;
  std::vector<ImVec4> bodies_;
  std::vector<const b2Body*> body_owners_;  // each of bodies_' body, where told
  std::vector<ForceLabel> force_labels_;
};

// The passes of a lane's drawing that the window adds to the world (FrameStyle::world_tools),
// in their order: what it will draw is told to the placer first, labels that name a place take
// it before the lesson's labels, which may move, are placed, and the rest comes last.
enum class WorldToolsPass {
  avoid,         // before the world: what will be drawn, for the label placer
  fixed_labels,  // once the world's arrows, marks, springs and bodies are known, before its labels
  draw,          // after the world: the rest, with labels that may move
};

// A torque drawn as a curved arrow three quarters of the way round `centre` in its sense
// (counter-clockwise positive, as in the world), with its size in N·m by the arrow's tail.
// Made apart from drawing, so its chords can be given to the label placer before any label.
struct TorqueArc {
  ImVec2 centre;
  float radius = 0.0f;
  double torque = 0.0;
  std::vector<ImVec2> points;  // along the arc, tail first
};
TorqueArc torque_arc(ImVec2 centre, float radius, double torque);
// Keeps labels off the arc: its chords, `width` wide, for the label placer.
void avoid_arc(LabelPlacer& labels, const TorqueArc& arc, float width);
// The arc and its head, no value: the world's torques and the legend's key to them.
void draw_torque_arrow(ImDrawList* draw, const TorqueArc& arc, ImU32 colour, float thickness);
// A torque's value beside its arc's start, placed (nowhere where nothing is free), to be drawn.
struct PlacedTorque {
  std::string text;
  std::optional<ImVec2> at;
};
PlacedTorque place_torque_value(const TorqueArc& arc, ImFont* font, float thickness, LabelPlacer& labels);
// The arc, its head and its value where place_torque_value put it.
void draw_torque(ImDrawList* draw, const TorqueArc& arc, ImU32 colour, ImFont* font, ImU32 background, float thickness,
                 const PlacedTorque& placed);

// A label with a background that keeps it readable over bodies and lines; `centre` is where
// the middle of the text goes. No background when `background` is 0.
void draw_label(ImDrawList* draw, ImFont* font, ImVec2 centre, ImU32 colour, ImU32 background, const char* text);
// A force value's leader: from the arrow's point nearest the label's box (x0, y0, x1, y1) to the
// box's edge, for a value that has no free place beside its arrow.
DrawnSegment leader_line(const ImVec4& box, const DrawnSegment& arrow);
// With `halo` (not 0), outlined in it first, arrow_halo_width(thickness) wide: a force's arrow
// drawn over a body of about its own lightness is still seen (Theme::arrow_halo). `broken`: the
// shaft in dashes, for an arrow drawn longer than to scale (ScreenArrow::to_scale).
// `plate`: its outline in the halo's colour a thickness and a pixel wide, whole under a broken
// shaft, a plate of the arrow's own shape (ScreenArrow::over_its_like).
void draw_arrow(ImDrawList* draw, ImVec2 tail, ImVec2 tip, ImU32 colour, float thickness, ImU32 halo = 0,
                bool broken = false, bool plate = false);
// A broken shaft's dashes and gaps, px, for arrows `thickness` thick: half a thickness each, so
// that the shortest arrow the world draws (legible_arrow_pixels: four thicknesses, of which the
// head takes 0.6) still shows a gap between two dashes, 3.5 px each on a projector. Dashes a
// thickness long left that shaft one 2 px dash and a gap (the trial after issue 31's first).
inline float broken_dash(float thickness) { return 0.5f * thickness; }
inline float broken_gap(float thickness) { return 0.5f * thickness; }
// A force's arrow in its kind's colour, with its value in newtons just beyond the tip.
void draw_force(ImDrawList* draw, const ScreenArrow& arrow, const Theme& theme, ImFont* font, float thickness,
                LabelPlacer& labels);
// The same with its own label text ("9.81 N in all"); no label when `text` is empty.
void draw_force(ImDrawList* draw, const ScreenArrow& arrow, const Theme& theme, ImFont* font, float thickness,
                LabelPlacer& labels, const std::string& text);
// draw_force() in its two halves, so that a picture's values can be placed in trial orders on
// copies of the placer before one is drawn (draw_world): where the value goes (told to the
// placer, with its leader), then the arrow, the leader and the value drawn where they went.
struct PlacedForce {
  ScreenArrow arrow;
  std::string text;
  ImVec2 size;                          // the text's, px
  std::optional<ImVec2> at;             // the value's centre; none where nothing was free
  std::optional<DrawnSegment> leader;   // joining it to its arrow, where it is not beside it
  bool beside = false;                  // by its own arrow (LabelPlacer::beside()) or joined by a leader; or no text
};
// `drawn`: the arrow's place in the order the picture's arrows are drawn (ForceLabel::drawn).
// `wanted`: the value's centre sought first, where the caller knows a better place than just
// beyond the tip along the arrow's line (a measuring tool's long value on a short arrow).
PlacedForce place_force_label(const ScreenArrow& arrow, ImFont* font, float thickness, LabelPlacer& labels,
                              const std::string& text, std::size_t drawn, std::optional<ImVec2> wanted = std::nullopt);
void draw_placed_force(ImDrawList* draw, const PlacedForce& placed, const Theme& theme, ImFont* font, float thickness);
void draw_polygon(ImDrawList* draw, const b2Body* body, const b2PolygonShape& shape, const Camera& camera, ImU32 fill,
                  ImU32 outline, float thickness);

}  // namespace frictionlab::draw
