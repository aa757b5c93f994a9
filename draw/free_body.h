// The free-body diagram of the lesson's main body, as an inset over the world: the body alone
// at its own zoom, every force on it at its point of action with its value, and the net force.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

#include "draw/drawing.h"

#include "draw/theme.h"
#include "physics/scene.h"

namespace frictionlab::draw {

// What the inset drew, for tests: each arrow with its value and where the value went, what its
// label placer was told to keep off, and the net force's line.
struct FreeBodyRecord {
  bool drawn = false;  // arrows were drawn (the run has started)
  std::vector<LabelPlacer::ForceLabel> forces;
  std::vector<b2Vec2> directions;  // each force's direction in the world, in the order of `forces`
  std::vector<ImVec4> labels;      // every label's box, padding included
  ImVec4 bounds{0.0f, 0.0f, 0.0f, 0.0f};
  std::string net_text;            // "net force: 3.98 N"
};

// The inset's longest arrow, px, in an inset of `size` whose small text is `text` px high at
// text scale `scale`: as long as leaves its value room beyond its tip inside the diagram's area.
float free_body_reach(ImVec2 size, float text, float scale);
// Whether an inset of `size` can be read at text scale `scale`: its longest arrow at least three
// lines of its values' text long, so that a force half the largest (a push and its friction,
// weight and a slope's normal force) still has an arrow longer than its value is high. A
// screen's inset has 3.9 lines at every size (55 px at 14 px text at 1280 × 720); a projector's
// text (1.35 times) in a world of the same height gave 2.4 (67 px at 28 px text at 1920 × 1080:
// arrows of 15-50 px, a crate of 15 px, unread from the room in issue 31's trial). The frame
// leaves out an inset that cannot be read (FrameLayout::inset_size 0): the world's own arrows,
// at projector size, show the same forces.
bool free_body_readable(ImVec2 size, float scale);

void draw_free_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const std::string& name, ImVec2 corner,
                    ImVec2 size, const Theme& theme, const Fonts& fonts, FreeBodyRecord* record = nullptr);

// The net force as the inset prints it: the sum of the forces as printed (each value as its
// label shows it, along its arrow), so that a student adding the printed values by hand gets
// the printed net (push's 6.92 − 2.94 read "net force: 3.97 N" from the unrounded forces).
// Rounded to the finest printed digit first, so weight and normal force printed alike cancel.
double printed_net(const std::vector<b2Vec2>& forces);

}  // namespace frictionlab::draw
