// What the window draws into each lane of the world view (draw::FrameStyle::world_tools): the
// force gauge on the body the mouse's hand pulls, in the lane that body is drawn in (or the one
// the drag began in), and the Tools menu's measuring tools, each pass (draw::WorldToolsPass) in
// the order the lane's labels are placed.
//
// It keeps nothing between frames: the classroom makes one for each frame's style from the
// parts it reads, as the running lesson, the tools and the hand then stand.
#pragma once

#include <imgui.h>

#include <cstddef>

#include "classroom/measuring_tools.h"
#include "classroom/world_hand.h"
#include "classroom_state/playback.h"
#include "draw/camera.h"
#include "draw/drawing.h"
#include "draw/frame.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

struct WorldTools {
  const classroom_state::Playback& playback;  // the running lesson, read as each lane is drawn
  const MeasuringTools& tools;
  const WorldHand& hand;                      // the lane its drag began in
  const draw::Theme& colours;
  const draw::Fonts& fonts;

  // Its part in one pass of a lane's drawing: the gauge's room told to the placer first, the
  // tools' part, then the gauge drawn over them.
  void operator()(draw::WorldToolsPass pass, ImDrawList* draw, const draw::Camera& camera, std::size_t lane,
                  float newtons_to_pixels, draw::LabelPlacer& labels) const;
};

}  // namespace frictionlab::classroom
