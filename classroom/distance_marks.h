// The distance marks, a measuring tool: a ruler along the surface the measured body stands on,
// its ticks counted from where the body stood at t = 0, and their numbers placed where the view
// has room. Which body, and in which lane, is MeasuringTools' to say; this is the ruler's
// geometry, the choice of its numbered ticks, and its drawing through the lane's label placer.
#pragma once

#include <imgui.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "draw/camera.h"
#include "draw/drawing.h"
#include "draw/theme.h"
#include "physics/scene_forces.h"

namespace frictionlab::classroom {

// The distance marks in a lane: a line along the surface just inside it, from where the view
// shows it to where it ends, a tick every nice length (distance_mark_step) counted from where
// the measured body stood at t = 0, and each tick's number just under it: counted forward
// rightwards along a level
// floor and downhill on a slope, with a minus sign behind the start. Where the view has no room
// under the surface for the numbers (a lane's thin strip of ground), the line lies on the
// surface with its ticks and numbers over it; and where fewer than two numbers find room at their
// ticks (nor across the line from them), or would lie on each other, only every 2nd, 5th,
// 10th, 20th or 50th tick is numbered, so that the scale can be read.
struct DistanceMark {
  ImVec2 foot;        // the tick's foot on the line
  double metres;      // from the start, forward (rightwards, or downhill) positive
  std::string text;   // "0.4 m", "−0.2 m"
  ImVec4 number_box;  // where its number goes, x0, y0, x1, y1, as the label placer pads a label
  ImVec4 across_box;  // or across the line from its tick, where that side has no room
  bool numbered;      // one of the ticks whose numbers are drawn (where they are free)
};
struct DistanceMarks {
  ImVec2 from, to;  // the line
  ImVec2 inward;    // screen direction of the ticks and the numbers: into the surface, or out of it
  double step;      // m between ticks
  std::vector<DistanceMark> ticks;
  // The fewest ticks from one number to the next (1, 2, 5, 10, 20 or 50): numbers about
  // least_number_spacing() apart or more, as far apart as the ruler's ticks were before they came
  // to be a fraction of the body's length apart, so that they take no more of the room the
  // forces' values need (incline's weight at 45° lost its place beside its arrow to "4 m").
  std::size_t least_every = 1;
};
// The least distance between two numbers of the ruler, px: 60 points.
inline float least_number_spacing(float scale) { return 60.0f * scale; }
// Whether a tick is one of every `every`-th, counted from the start (0 m is always one).
bool counted(const DistanceMark& mark, std::size_t every, double step);
// Chooses the ticks whose numbers are drawn: every one, else every 2nd, 5th, 10th, 20th or
// 50th, the first whose numbers lie clear of each other, two at least, where `labels` has them free.
// `fewest_every`: not every tick, but every 2nd at least (and so on).
void number_marks(DistanceMarks& marks, const draw::LabelPlacer& labels, std::size_t fewest_every = 1);
// The ticks' spacing, m, at `pixels_per_metre` and text scale `scale`, for a body `body_length`
// m long along the surface (0: not known): a nice length (1, 2 or 5 times a power of ten) about
// 120 points long, but no longer than half the body, and no shorter than least_tick_spacing().
float distance_mark_step(float pixels_per_metre, float scale, float body_length);
// The least distance between two ticks, px: 14 points, a line of the numbers' text, so that the
// ruler reads as ticks and not as a hatched band the labels find no room beside.
inline float least_tick_spacing(float scale) { return 14.0f * scale; }
// How long a body is along `along` (a unit vector), m: its shapes' extent.
float length_along(const b2Body* body, b2Vec2 along);
// The marks along `surface` in the view of `camera`, counted from `origin` (where the measured
// body's centre of mass was at t = 0), their step distance_mark_step()'s for the measured body,
// `body_length` m long along the surface. With `labels`, the placer as the marks find it when
// drawn: their side is chosen where the view has room for their numbers (every tick numbered;
// number_marks chooses which). None where the view shows none of the surface.
std::optional<DistanceMarks> distance_marks_along(const Surface& surface, b2Vec2 origin, float body_length,
                                                  const draw::Camera& camera, const draw::Fonts& fonts,
                                                  const draw::LabelPlacer* labels);

// The marks' line and ticks, told to the placer as they are drawn.
void draw_distance_lines(ImDrawList* draw, const DistanceMarks& marks, const draw::Theme& theme, float s, draw::LabelPlacer& labels);
// Each numbered tick's number just beyond it where free, or not at all; where fewer than two
// are drawn, the ticks' spacing in words.
void draw_distance_numbers(ImDrawList* draw, const DistanceMarks& marks, const draw::Theme& theme, const draw::Fonts& fonts,
                           draw::LabelPlacer& labels);

}  // namespace frictionlab::classroom
