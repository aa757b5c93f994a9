// The mouse in the lesson's world: a drag on a body pulls it with the hand (through the force
// gauge), a drag on empty space pans the view, the wheel zooms about the point under the mouse,
// and a double click on empty space puts the lesson's view back.
//
// It keeps its own state (the lanes' cameras as last drawn, the view's zoom and pan, the drag
// under way and the lane it began in) and acts on the running lesson's Playback, as each of Dear
// ImGui's demo windows keeps its own: the classroom holds one and calls hold_view() before the
// frame is built and handle_mouse() after.
#pragma once

#include <box2d/box2d.h>
#include <imgui.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "classroom_state/playback.h"
#include "draw/camera.h"

namespace frictionlab::classroom {

struct WorldHand {
  // The world view's cameras in the last frame (one per lane): where the hand finds bodies.
  std::vector<draw::Camera> cameras{draw::Camera{}};
  draw::ViewAdjust view_adjust;               // the wheel's zoom and the drag's pan
  bool projector = false;               // the frame's layout (FrameLayout::of): projector mode's
  std::optional<b2Vec2> panning_from;   // the world point a drag on empty space holds under the mouse
  std::size_t drag_lane = 0;            // the lane (camera) the hand's or the pan's drag began in
  bool held = false;  // the user's mouse holds a body (not a drag the record replays)
  // While the hand pulls, the view holds still: a view that follows the body would carry the
  // world point under a still mouse along with it, and the hand would chase the body it pulls.
  // The world point at the drag lane's anchor when the hand took hold, that anchor on the screen
  // (a line of status under the transport bar moves it), and the pan before it (given back on
  // letting go).
  struct HeldView {
    b2Vec2 centre;
    ImVec2 anchor;
    b2Vec2 pan;
  };
  std::optional<HeldView> held_view;

  // Another lesson: nothing held or dragged, the lesson's own view.
  void forget();
  // Something moves with the mouse: a body held or the view panned.
  bool drags() const { return held || panning_from.has_value(); }
  // The camera whose strip holds `point`, or the first one.
  const draw::Camera& camera_at(ImVec2 point) const;
  // Before the frame is built in `size` at `origin`: the pan that keeps the held point still.
  void hold_view(const classroom_state::Playback& playback, ImVec2 origin, ImVec2 size, float scale);
  // After it is built: the mouse's wheel, clicks and drags. The status line says what the hand
  // holds while the run is paused (`status`), and is cleared of it once it plays or lets go.
  void handle_mouse(classroom_state::Playback& playback, ImVec2 origin, ImVec2 size, float scale, std::string& status);
};

}  // namespace frictionlab::classroom
