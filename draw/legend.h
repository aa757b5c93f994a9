// The strip under the world: what each colour means, the arrows' scale in newtons, the
// materials in the picture and a scale bar in metres.
#pragma once

#include <imgui.h>

#include <array>
#include <string>
#include <utility>

#include "draw/camera.h"
#include "draw/theme.h"
#include "physics/scene.h"

namespace frictionlab::draw {

// In a strip (wider than tall): two rows. In a column (taller than wide, projector mode,
// beside the plots): an entry a line.
void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels);

// What the legend says of the arrows' lengths beside their scale, as three lines (a column's; a
// strip joins them): "dashed: too small" "to draw to scale" "(under 2.02 N)", the force under
// which the world draws an arrow longer than to scale, broken (not_to_scale_below, drawn_longer
// in overlays.h). "under 2.02 N:" "longer, dashed" was cryptic to a teacher, its number
// differing between lessons (a projector trial, issue 31): the words now say why, the number
// follows. It depends on the lesson's arrow scale alone, the same all through a run, so the
// legend does not change under the class's eyes: it said "all arrows to scale" or "under 2.02 N:
// ..." by the forces of the moment, and push's changed from one to the other as it played (a
// teacher's trial, issue 31). Every lesson's forces may come under it (a friction grows from
// nothing under a push that grows; a body comes to rest), and where none does the words are
// still true.
using ArrowScaleWords = std::array<std::string, 3>;
ArrowScaleWords arrow_scale_words(float newtons_to_pixels, float scale);

// The width a column legend needs for the scene, the same all through its run.
float legend_column_width(const Scene& scene, const Fonts& fonts);

}  // namespace frictionlab::draw
