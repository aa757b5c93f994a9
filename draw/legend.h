// The strip under the world: what each colour means, the arrows' scale in newtons, the
// materials in the picture and a scale bar in metres.
#pragma once

#include <imgui.h>

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

// What the legend says of the arrows' lengths beside their scale, as two lines (a column's; a
// strip joins them): the world draws a force under not_to_scale_below longer than to scale
// (drawn_arrow_pixels in overlays.h). Where the picture has forces under it and others not,
// "under 12.4 N:" "longer, dashed"; where every force is under it, "all arrows" "longer, dashed";
// where none is, "all arrows" "to scale". ("under 12.4 N: not to scale" read oddly on push,
// whose every force, its 9.81 N weight the largest, is under 12.4 N: issue 31.)
using ArrowScaleWords = std::pair<std::string, std::string>;
ArrowScaleWords arrow_scale_words(const Scene& scene, float newtons_to_pixels, float scale);

// The width a column legend needs for the scene, the same all through its run.
float legend_column_width(const Scene& scene, const Fonts& fonts);

}  // namespace frictionlab::draw
