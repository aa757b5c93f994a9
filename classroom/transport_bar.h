// The transport bar along the bottom of the window: play, step, reset, the speed, and the time
// bar through the recorded run, with the window's notices (the run is over, a file saved) beside
// it or, when they do not fit there, on lines of their own under it.
//
// It keeps its own state (the time the bar is being dragged back to) and draws itself, as each
// of Dear ImGui's demo windows does: the classroom holds one, asks its shape to leave it room
// under the frame, and draws it over the running lesson's Playback.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>

#include "classroom/control_places.h"
#include "classroom_state/playback.h"

namespace frictionlab::ui {

struct TransportBar {
  std::optional<double> scrubbing_to;  // the time bar dragged back: replayed when let go

  // Its height with the words `said` beside the time bar: one row, or two when the words do not fit
  // beside it; `scale` is the fonts' scale.
  struct Shape {
    float controls = 0.0f, bar = 0.0f, height = 0.0f;
    bool words_below = false;
  };
  static Shape shape(const std::string& said, float width, float scale);
  // The bar, acting on `playback`; a speed set on its slider is kept in `speed_kept` too (the
  // window's, for the next lesson opened in this session).
  void draw(ImVec2 corner, ImVec2 size, Playback& playback, const std::string& said, float scale, double& speed_kept,
            ControlPlaces& controls);
};

}  // namespace frictionlab::ui
