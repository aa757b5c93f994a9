// When the window draws (classroom/frame_pacing.h): every frame while something moves; paused
// and untouched, nothing until input or a changed script file.
#include "classroom/frame_pacing.h"

#include <gtest/gtest.h>

namespace frictionlab::classroom {
namespace {

// Issue 31: a paused window drew four frames a second (12 % of a core on llvmpipe) though
// nothing could change. Woken by its clock, it draws only when the file watchers found a change.
TEST(FramePacing, APausedWindowSleepsAndDrawsOnlyForInputOrAChangedFile) {
  FramePacing pacing;
  EXPECT_FALSE(pacing.may_sleep()) << "a window just opened settles first";
  for (int i = 0; i < FramePacing::frames_after_input; ++i) pacing.drawn(true);
  EXPECT_TRUE(pacing.may_sleep());
  for (int wake = 0; wake < 40; ++wake) {  // ten seconds of the clock's wake-ups
    EXPECT_FALSE(pacing.draw_on_clock(false)) << "nothing changed: no frame";
    EXPECT_TRUE(pacing.may_sleep());
  }
  EXPECT_TRUE(pacing.draw_on_clock(true)) << "a saved script: one frame";
  pacing.drawn(true);
  EXPECT_TRUE(pacing.may_sleep()) << "one frame is enough when nobody's pointer moved";
  pacing.input();
  for (int i = 0; i < FramePacing::frames_after_input; ++i) {
    EXPECT_FALSE(pacing.may_sleep()) << "hover and focus settle: frame " << i;
    pacing.drawn(true);
  }
  EXPECT_TRUE(pacing.may_sleep());
  pacing.input();
  pacing.drawn(false);  // Space: the run plays
  for (int i = 0; i < 100; ++i) {
    EXPECT_FALSE(pacing.may_sleep()) << "a playing run draws every frame";
    pacing.drawn(false);
  }
  pacing.settle(10);  // the web page resized
  for (int i = 0; i < 10; ++i) {
    EXPECT_FALSE(pacing.may_sleep());
    pacing.drawn(true);
  }
  EXPECT_TRUE(pacing.may_sleep());
}

}  // namespace
}  // namespace frictionlab::classroom
