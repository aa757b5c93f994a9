// The strip under the world: what each colour means, the arrows' scale in newtons, the
// materials in the picture and a scale bar in metres.
#pragma once

#include <imgui.h>

#include "draw/camera.h"
#include "draw/theme.h"
#include "physics/scene.h"

namespace frictionlab::draw {

// In a strip (wider than tall): two rows. In a column (taller than wide, projector mode,
// beside the plots): an entry a line.
void draw_legend(ImDrawList* draw, const Scene& scene, const Camera& camera, ImVec2 corner, ImVec2 size,
                 const Theme& theme, const Fonts& fonts, float newtons_to_pixels);

// The width a column legend needs for the scene, the same all through its run.
float legend_column_width(const Scene& scene, const Fonts& fonts);

}  // namespace frictionlab::draw
