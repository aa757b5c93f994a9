// When a host draws the classroom, for the desktop window and the web page alike. Something
// moving (a run playing, a search measuring, a hand held) draws every frame. Paused and
// untouched, the picture cannot change: the host sleeps until input comes, and a wake-up by the
// clock (for the script files' watchers) draws only when the watchers found a change. A paused
// llvmpipe window drew at 97 % of a core, then, waking four times a second, at 12 %; now at
// nothing while nothing changes.
#pragma once

#include <algorithm>

namespace frictionlab::classroom {

class FramePacing {
 public:
  // After input, a few frames let ImGui settle hover and focus before the host sleeps again.
  static constexpr int frames_after_input = 3;

  // After each frame drawn, with whether the classroom is idle now (Classroom::idle()).
  void drawn(bool idle) { settle_frames_ = idle ? std::max(0, settle_frames_ - 1) : std::max(settle_frames_, frames_after_input); }
  // Whether the host may sleep until input or its clock wakes it.
  bool may_sleep() const { return settle_frames_ == 0; }
  // Woken by input: draw, and settle after it.
  void input() { settle(frames_after_input); }
  // At least `frames` more before sleeping (the web page's resize: its panels take ten to find
  // their sizes again).
  void settle(int frames) { settle_frames_ = std::max(settle_frames_, frames); }
  // Woken by the clock: draw only when the watchers found what changes the picture
  // (Classroom::waited's answer); then one frame is enough, nobody's pointer moved.
  bool draw_on_clock(bool watchers_changed_something) {
    if (watchers_changed_something) settle_frames_ = std::max(settle_frames_, 1);
    return watchers_changed_something;
  }

 private:
  int settle_frames_ = frames_after_input;
};

}  // namespace frictionlab::classroom
