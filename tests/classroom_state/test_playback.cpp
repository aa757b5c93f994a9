// The lesson as the window runs it (classroom_state/playback.h), with no window: whole frames
// of the lesson at the chosen speed, a display frame's share held to what keeps the window
// answering, an earlier moment shown again exactly, and the run's end. (A failing expect row
// in the running window is tested with the window: tests/classroom/test_script_messages.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "classroom_state/playback.h"
#include "lessons/runtime/catalog.h"

namespace frictionlab::classroom_state {
namespace {

// push at its defaults, 240 Hz: the block breaks away at 3.92 N, 1.96 s, and the run ends 1.5 s later.
std::string push_lesson() { return lessons::resolve_lesson("push"); }

// A held block's measured acceleration is the rounding of the step's float numbers, and the
// window printed it (1.1×10⁻⁹ m/s² in a teacher's trial). What one world step h resolves under
// gravity g: a speed of ε·g·h, an acceleration of ε·g (ε = 2⁻²³, a float's). The rows read below
// it are 0 as the window shows them; the lesson's own measurement is not 0 (else this tests
// nothing), and a motion the step resolves is shown as measured.
TEST(Playback, AMeasuredSpeedOrAccelerationUnderWhatTheStepResolvesReadsZero) {
  const double epsilon = std::ldexp(1.0, -23), g = 9.81, h = 1.0 / 240.0;
  const lessons::MotionResolution resolution = lessons::motion_resolution(h, g);
  EXPECT_NEAR(resolution.speed, epsilon * g * h, 1e-6 * epsilon * g * h);
  EXPECT_NEAR(resolution.acceleration, epsilon * g, 1e-6 * epsilon * g);
  struct Case {
    const char* lesson;
    std::map<std::string, std::string> set;
    const char* row;
    bool held;
  };
  const Case cases[] = {{"incline", {{"angle", "15"}, {"mass", "5"}}, "mean acceleration down the slope", true},
                        {"pulley", {{"mu_s", "0.7"}}, "acceleration", true},
                        {"incline", {}, "mean acceleration down the slope", false},
                        {"push", {}, "speed at the end", false}};
  for (const Case& c : cases) {
    Playback playback(lessons::resolve_lesson(c.lesson), c.set, {});
    playback.run_to(playback.lesson().duration());
    playback.refresh_readings();
    const auto row_in = [&](const std::vector<lessons::ExpectationResult>& rows) {
      const auto row = std::find_if(rows.begin(), rows.end(), [&](const lessons::ExpectationResult& r) { return r.name == c.row; });
      EXPECT_NE(row, rows.end()) << c.lesson << ": no row " << c.row;
      return row == rows.end() ? lessons::ExpectationResult{} : *row;
    };
    const lessons::ExpectationResult measured = row_in(playback.lesson().expectations());
    const lessons::ExpectationResult shown = row_in(playback.readings().expectations);
    ASSERT_TRUE(measured.measured_yet && shown.measured_yet) << c.lesson;
    if (c.held) {
      EXPECT_NE(measured.measured, 0.0) << c.lesson << ": the held block measured no rounding: the case tests nothing";
      EXPECT_LT(std::abs(measured.measured), epsilon * g) << c.lesson;
      EXPECT_EQ(shown.measured, 0.0) << c.lesson << ": " << measured.measured << " " << measured.unit << " is shown";
    } else {
      EXPECT_GT(std::abs(measured.measured), 1.0) << c.lesson;
      EXPECT_EQ(shown.measured, measured.measured) << c.lesson;
    }
  }
}

TEST(Playback, RealTimeRunsWholeFramesOfTheLessonAtItsSpeed) {
  Playback playback(push_lesson(), {}, {});
  playback.play();
  playback.advance(0.1);  // 24 frames of 1/240 s
  EXPECT_EQ(playback.lesson().scene().frame(), 24);
  playback.set_speed(0.5);
  playback.advance(0.1);  // 0.05 s of lesson: 12 more
  EXPECT_EQ(playback.lesson().scene().frame(), 36);
  // A fraction of a frame waits for the next display frame: 1/480 s twice is one frame.
  playback.set_speed(1.0);
  playback.advance(1.0 / 480.0);
  EXPECT_EQ(playback.lesson().scene().frame(), 36);
  playback.advance(1.0 / 480.0);
  EXPECT_EQ(playback.lesson().scene().frame(), 37);
  EXPECT_FALSE(playback.behind());
}

TEST(Playback, ADisplayFrameRunsAtMostAQuarterSecondOrSoAndSaysItFellBehind) {
  Playback playback(push_lesson(), {}, {});
  playback.set_speed(Playback::fastest);
  playback.play();
  // 0.1 s at ×8 asks for 0.8 s of lesson; a display frame runs 0.27 s of it (8× at 30 frames a
  // second), 64 whole frames, and drops the rest.
  playback.advance(0.1);
  EXPECT_EQ(playback.lesson().scene().frame(), 64);
  EXPECT_TRUE(playback.behind());
  playback.advance(1.0 / 240.0 / Playback::fastest);  // an eighth of a frame's lesson time
  EXPECT_FALSE(playback.behind());
}

TEST(Playback, TheSpeedStaysBetweenTheSlowestAndTheFastest) {
  Playback playback(push_lesson(), {}, {});
  playback.set_speed(100.0);
  EXPECT_EQ(playback.speed(), Playback::fastest);
  playback.set_speed(0.0);
  EXPECT_EQ(playback.speed(), Playback::slowest);
  playback.set_speed(2.0);
  EXPECT_EQ(playback.speed(), 2.0);
}

TEST(Playback, GoingBackReplaysTheRunWithItsChangesExactly) {
  Playback playback(push_lesson(), {}, {});
  playback.run_to(0.5);
  playback.set_parameter("mu_k", 0.1);  // a pair's slider changes the running lesson: joins the record at 0.5 s
  playback.run_to(2.5);
  const b2Body* block = playback.lesson().scene().body("block");
  const b2Vec2 then = block->GetPosition();
  EXPECT_GT(then.x, 0.0f) << "broken away at 1.96 s";
  playback.scrub_to(0.25);
  EXPECT_EQ(playback.lesson().scene().frame(), 60);
  EXPECT_DOUBLE_EQ(playback.lesson().parameter("mu_k").value, 0.3) << "before 0.5 s the script's own mu_k";
  playback.scrub_to(2.5);
  EXPECT_DOUBLE_EQ(playback.lesson().parameter("mu_k").value, 0.1);
  const b2Body* again = playback.lesson().scene().body("block");
  EXPECT_EQ(again->GetPosition().x, then.x);
  EXPECT_EQ(again->GetPosition().y, then.y);
}

TEST(Playback, TheRunPausesAtItsEndAndPlayedOnSaysTheTableKeepsItsRows) {
  Playback playback(push_lesson(), {}, {});
  playback.play();
  for (int frame = 0; frame < 1000 && playback.playing(); ++frame) playback.advance(0.25);
  ASSERT_FALSE(playback.playing()) << "the run never ended";
  EXPECT_TRUE(playback.at_run_end());
  EXPECT_EQ(playback.past_end_words(), "") << "at the end itself the rows are the run's own";
  playback.step_once();
  EXPECT_FALSE(playback.at_run_end());
  EXPECT_EQ(playback.past_end_words().rfind("Past the run's end at ", 0), 0u) << playback.past_end_words();
}

}  // namespace
}  // namespace frictionlab::classroom_state
