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

void draw_free_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const std::string& name, ImVec2 corner,
                    ImVec2 size, const Theme& theme, const Fonts& fonts, FreeBodyRecord* record = nullptr);

// The net force as the inset prints it: the sum of the forces as printed (each value as its
// label shows it, along its arrow), so that a student adding the printed values by hand gets
// the printed net (push's 6.92 − 2.94 read "net force: 3.97 N" from the unrounded forces).
// Rounded to the finest printed digit first, so weight and normal force printed alike cancel.
double printed_net(const std::vector<b2Vec2>& forces);

}  // namespace frictionlab::draw
