// A close-up of the lesson's main body over a corner of the world, where the lesson fixed a
// window that draws it too small to see from the back of a room: incline's whole slope, its foot
// and angle mark included, leaves its 0.4 m block 23 px long on a projector (issue 31). The
// close-up follows the body at a whole number of times the world's zoom, with its contact's
// state; the world's own arrows keep the forces, at the legend's scale.
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <optional>

#include "draw/camera.h"
#include "draw/drawing.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

struct CloseUp {
  ImVec4 place{0.0f, 0.0f, 0.0f, 0.0f};  // px: x0, y0, x1, y1
  int zoom = 1;                          // times the world's pixels per metre
  float title_strip = 0.0f;              // px: the title's line at its top, which the body stays under
};

// The longer side of a body's own shapes, m: along its own axes, so a block turned on a slope
// counts its length, not its box's diagonal span.
float own_length(const b2Body* body);

// Where the close-up of `body` goes over the world's panel (`world_corner`, `world_size`) seen
// through `world`, at text scale `scale`; nothing where the world already draws it
// min_body_pixels × scale long or more, where the lesson did not fix its window (a framed view
// zooms in itself), or where no top corner is clear of the fixed bodies. Of the top two corners
// the one away from the fixed bodies' highest point (incline's slope's top, where its block
// starts), lowered where it would cover them. Decided from the fixed bodies alone, so it stays
// where it is as the body moves. `title_line`: the height of its title's text, px.
std::optional<CloseUp> close_up_place(const lessons::Lesson& lesson, const b2Body* body, const Camera& world,
                                      ImVec2 world_corner, ImVec2 world_size, float scale, float title_line);

// The close-up's camera: centred on the body, `zoom` times the world's.
Camera close_up_camera(const CloseUp& close_up, const b2Body* body, const Camera& world);

// The close-up drawn: the world around the body (no arrows), its contact's dot and word, and
// its name with the zoom. `labels` comes back with what was placed, for the layout tests.
void draw_close_up(ImDrawList* draw, const lessons::Lesson& lesson, const b2Body* body, const CloseUp& close_up,
                   const Camera& world, const Theme& theme, const Fonts& fonts, LabelPlacer& labels);

}  // namespace frictionlab::draw
