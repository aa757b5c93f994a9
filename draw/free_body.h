// The free-body diagram of the lesson's main body, as an inset over the world: the body alone
// at its own zoom, every force on it at its point of action with its value, and the net force.
#pragma once

#include <imgui.h>

#include <string>

#include "draw/theme.h"
#include "physics/scene.h"

namespace frictionlab::ui {

void draw_free_body(ImDrawList* draw, const Scene& scene, const b2Body* body, const std::string& name, ImVec2 corner,
                    ImVec2 size, const Theme& theme, const Fonts& fonts);

}  // namespace frictionlab::ui
