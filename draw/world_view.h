// The world as a teacher sees it: ground, bodies in their materials' colours, springs that
// stretch, ropes over pulleys, hands and driven bodies, slopes with their angle marked, the
// force arrows with their values and every contact's state.
#pragma once

#include <imgui.h>

#include <functional>
#include <vector>

#include "draw/camera.h"
#include "draw/drawing.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

// The world, the arrows on every dynamic body and the contact marks into `camera`'s view;
// `labels` already knows what else covers the view (the free-body inset), and keeps labels off it.
// `labelled`, when given, are the bodies whose arrows and contact marks this view draws (a
// lane's own): the others are drawn as bodies only, so a neighbour seen at a lane's edge does
// not repeat its forces there. `fixed_labels`, when given, is called once every arrow, mark,
// spring and body is known to `labels` and before any label is placed: labels that cannot move
// (a distance mark's number) take their places then.
// `arrows`: none draws the contact marks and words alone (a close-up, whose forces the world's
// view already shows at the legend's scale).
enum class WorldArrows { drawn, none };
void draw_world(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                const Fonts& fonts, float newtons_to_pixels, LabelPlacer& labels,
                const std::vector<const b2Body*>* labelled = nullptr, const std::function<void()>& fixed_labels = {},
                WorldArrows arrows = WorldArrows::drawn);

// What placing the forces' values took in draw_world on this thread, summed until the caller
// sets it back to {}, for the benchmark only (nothing drawn depends on it), in wall-clock
// seconds: the values placed in the arrows' order, which alone would be drawn with no retries,
// and the retries where that order left some away from their arrows.
struct ForceLabelTimes {
  double arrows_order = 0.0;
  double retries = 0.0;
  int views = 0;    // draw_world's calls: one a lane
  int retried = 0;  // of them, those whose arrows' order left a value away
};
ForceLabelTimes& force_label_times();

}  // namespace frictionlab::draw
