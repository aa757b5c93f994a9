// What the teaching overlays show, taken from what the solver did: forces on each body (from
// the friction listener's contact records, the springs and the applied forces) and the state
// of every contact. Worked out apart from drawing, so tests can check them against the record.
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "draw/camera.h"
#include "draw/theme.h"
#include "physics/scene.h"
#include "physics/scene_forces.h"

namespace frictionlab::draw {


// Newtons to pixels, the same for every frame of a lesson: the heaviest weight gets
// `reference_pixels`.
float pixels_per_newton(const Scene& scene, float reference_pixels);

// A contact's dot's radius at text scale 1, px: the world's dots, the legend's chips that name
// their states, and the friction arrows that start at a dot's rim and the labels that keep off
// it all take this one, so a dot drawn larger never hides an arrow it was measured not to.
constexpr float contact_dot_radius = 6.0f;

// An arrow as drawn: tail and tip in pixels.
struct ScreenArrow {
  ForceOnBody force;
  ImVec2 tail, tip;
  // False where the arrow is drawn longer than the force at the picture's scale: it is then
  // drawn with a broken shaft (draw_arrow's `broken`), so that a class reading lengths does not
  // take it for to scale (issue 31: push's lengthened 2.94 N friction and 4.99 N push looked
  // nearly alike, and a class reads the picture, not the legend).
  bool to_scale = true;
  // Whether it lies over a fill it does not stand out from (under 3:1 against its colour,
  // mark_arrows_over_their_like in world_view.cpp): it is then drawn on a plate of its outline's
  // colour (draw_arrow's `plate`), as a value lies on its box. driven_wheel's dark grey weight on
  // its dark rubber wheel showed only its thin outline, read as an empty arrow (a teacher's trial,
  // issue 31); an outline a shaft wide each side read the same, a white arrow with a dark core.
  bool over_its_like = false;
  float length() const;
};
// The shortest arrow drawn at text scale `scale`: one whose head can be seen. It grows with the
// text, as the arrows' thickness and heads do (3.5 px times the scale in the world): at a
// projector's scale (2.0 at 1920 × 1080) 8 px was shorter than the head drawn on it.
inline float shortest_arrow_pixels(float scale) { return 8.0f * scale; }
// The world's arrows' thickness at text scale `scale` (3.5 px at scale 1), which their heads,
// four thicknesses long, the gaps between them and the room kept round them follow.
inline float world_arrow_thickness(float scale) { return 3.5f * scale; }
// The outline round a force's arrow past its shaft's sides and its head's edges (draw_arrow's
// halo), px: a third of the arrow's thickness and at least a pixel and a half, a line a back
// row sees round the shaft (2.3 px on a projector's 7 px arrows).
inline float arrow_halo_width(float thickness) { return std::max(1.5f, thickness / 3.0f); }
// How far apart two arrows `thickness` px thick along one line (weight and normal force) are
// drawn, centre line to centre line, px: one's head (draw_arrow's, 0.45 of four thicknesses each side) beside the
// other's shaft (half a thickness), each in its halo (arrow_halo_width), and a halo's width of
// the background between them. 9 px times the scale put driven_wheel's normal force's head on
// its weight's shaft on a projector (a teacher's trial, issue 31): 18 px where 23 are needed.
inline float side_by_side_gap(float thickness) {
  return 0.45f * 4.0f * thickness + 0.5f * thickness + 3.0f * arrow_halo_width(thickness);
}
// The shortest force arrow the world draws, to be read from a classroom's back row: four
// thicknesses, a head (draw_arrow's, shortened to 0.6 of the arrow) and a shaft of two thirds of
// it, 14 px at text scale 1 and 28 px on a projector (2.0). One force scale per lesson, set by
// its heaviest weight, drew tipping_box's 19.9 N push 15 px long on a projector (issue 31). Eight
// thicknesses (56 px) lengthened spring_pull's 3.43 N friction to the length of its 4.64 N
// spring force, and pulley's and push's smaller forces likewise: a class comparing lengths read
// them as equal (the trial after). At four, those forces are to scale, and what is lengthened is
// small beside the forces it is seen with.
inline float legible_arrow_pixels(float scale) { return 4.0f * world_arrow_thickness(scale); }
// The force under which an arrow is drawn longer than to scale, at `pixels_per_newton` with its
// shortest length `legible` px: the one number both the world's drawing (drawn_longer, in
// place_arrows) and the legend (not_to_scale_below, arrow_scale_words) decide by. The drawing
// once counted a length within half a pixel of `legible` as to scale while the legend compared
// newtons: push's 1.99 N arrows were drawn solid, 27.9 px, under a legend saying "under 2.02 N:
// longer, dashed" (a teacher's trial, issue 31).
inline float lengthened_below(float pixels_per_newton, float legible) { return legible / pixels_per_newton; }
// Whether a force of `newtons` is drawn longer than to scale, `legible` px and broken.
inline bool drawn_longer(float newtons, float pixels_per_newton, float legible) {
  return newtons < lengthened_below(pixels_per_newton, legible);
}
// How long a force's arrow is drawn, px: to scale where it is not drawn_longer, else `legible`,
// its shaft broken (ScreenArrow::to_scale) and its value beside it. Lengthening every arrow
// under twice `legible` in order (`legible` and half its length at the scale) kept the order but
// not one ratio: push's 2.94 N friction and 4.99 N push came out 70 and 79 px on a projector, all
// its arrows "drawn longer", and a class reads the picture, not the legend (a teacher's trial,
// issue 31). Now an arrow is to scale, or drawn broken at the shortest length a back row reads:
// no smaller force has a longer arrow, and none lengthened looks to scale.
inline float drawn_arrow_pixels(float newtons, float pixels_per_newton, float legible) {
  return drawn_longer(newtons, pixels_per_newton, legible) ? legible : newtons * pixels_per_newton;
}
// The force under which the world's arrows are lengthened (drawn_arrow_pixels), which the legend says.
inline float not_to_scale_below(float newtons_to_pixels, float scale) {
  return lengthened_below(newtons_to_pixels, legible_arrow_pixels(scale));
}
// Whether a world point lies in one of a body's shapes (on its outline counts).
bool body_contains(const b2Body* body, b2Vec2 point);

// Tails at the point of action (but a push on a face, whose tip is there: the body is pushed,
// not pulled from inside), lengths to scale; a force that shows in the printed values of
// its body's forces but would be shorter than `shortest` pixels (at least
// shortest_arrow_pixels(scale)) is drawn that long, and one too small to show in them is left out. Two arrows of one body lying along one line
// (weight and normal force) are drawn side by side, their gap growing with the text as well.
// `gap`: how far apart two along one line end, px (they move only as far as that needs); 0: the
// world's, side_by_side_gap of its arrows.
// `weight_at_its_centre`: a weight stays at its centre of mass and the other moves all the way
// aside (the world's); else each goes half (the free-body inset's, whose values are placed by
// its arrows from near and found no place beside a normal force moved all the way aside).
std::vector<ScreenArrow> place_arrows(const std::vector<ForceOnBody>& forces, const Camera& camera,
                                      float pixels_per_newton, float scale, float shortest = 0.0f, float gap = 0.0f,
                                      bool weight_at_its_centre = true);

// "4.42 N", "98.1 N", "0.0120 N", "4.2×10⁻⁸ J": three significant figures (two in powers of
// ten) and the unit.
std::string format_quantity(double value, const char* unit);
// The number format_quantity() prints for `value`, as a number (4.42 for 4.4213), and the step
// of its last digit (0.01): what a student adding printed values by hand adds.
struct PrintedNumber {
  double value = 0.0;
  double step = 1.0;
};
PrintedNumber printed_number(double value);

}  // namespace frictionlab::draw
