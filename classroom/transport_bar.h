// The transport bar along the bottom of the window: play, step, reset, the speed, and the time
// bar through the recorded run, with the window's notices (the run is over, a file saved) on one
// line: beside the time bar, or on a line of its own under it when the run's end notice would
// not fit beside it. Which of the two is decided by what the lesson will say, not by what it says
// now, so that the bar never grows as the run ends (the trial's notice wrapped to a second line
// and pushed the whole frame up); words longer than their line are shortened in the middle
// ("…"), whole in a tooltip.
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

namespace frictionlab::classroom {

struct TransportBar {
  std::optional<double> scrubbing_to;  // the time bar dragged back: replayed when let go

  // Its height, planned for the words `room_for` (Playback::run_end_notice): one row when they
  // fit beside the time bar, else two, the second a line of words in `words_font` (the small
  // font); `scale` is the fonts' scale.
  struct Shape {
    float controls = 0.0f, bar = 0.0f, height = 0.0f;
    bool words_below = false;
  };
  static Shape shape(const std::string& room_for, float width, float scale, ImFont* words_font);
  // The bar, acting on `playback`, with the words `said` in the place shape(room_for) made; a
  // speed set on its slider is kept in `speed_kept` too (the window's, for the next lesson
  // opened in this session).
  void draw(ImVec2 corner, ImVec2 size, classroom_state::Playback& playback, const std::string& said, const std::string& room_for,
            float scale, ImFont* words_font, double& speed_kept, ControlPlaces& controls);

 private:
  // The time bar through the recorded run, `width` wide: dragged forward it plays on to the
  // time; dragged back it waits until let go, then replays from t = 0 (scrubbing_to).
  void time_bar(classroom_state::Playback& playback, float width, ControlPlaces& controls);
};

}  // namespace frictionlab::classroom
