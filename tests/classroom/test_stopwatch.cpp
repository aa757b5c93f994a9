// The stopwatch (classroom/stopwatch.h) as a teacher's trial drove it in the window: Play and the
// run's end, W and L, R and the time bar taken back, read in lesson seconds. Keys come as the
// window layer passes them on.
#include <gtest/gtest.h>

#include <string>

#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// A lesson with the theory shown from the start: nothing asked of the class before Play.
ClassroomOptions lesson_options(const std::string& lesson) {
  ClassroomOptions options;
  options.lesson = lesson;
  options.window.predictions = false;
  return options;
}

// The trial: the stopwatch shown before the run stayed at 0 when Play was pressed, and R cleared
// it. Shown before the run, it starts with Play, reads the lesson's time while it plays, stops
// when the run pauses or ends, and R takes it back to the run's start: 0, armed for the next run.
TEST(Stopwatch, ShownBeforeTheRunItStartsWithPlayAndStopsWithTheRun) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  hands.click("Tools menu");
  hands.click("tool stopwatch");
  ASSERT_TRUE(hands.classroom().window_settings().tools.stopwatch);
  const Stopwatch& stopwatch = hands.classroom().tools().stopwatch;
  // The lesson's time (R and the time bar rebuild its scene).
  const auto now = [&] { return hands.lesson().scene().time(); };
  EXPECT_TRUE(stopwatch.running()) << "armed before the run";
  EXPECT_EQ(stopwatch.text(0.0, false), "stopwatch 0.00 s (starts with Play)");
  // Armed, it has not started: the Tools menu offers to disarm it, not to stop it (the trial's
  // menu said "Stop the stopwatch" at 0.00 s), and there is no lap to take.
  EXPECT_TRUE(stopwatch.armed(0.0));
  EXPECT_STREQ(stopwatch.start_stop_words(0.0), "Disarm the stopwatch (it starts with Play)");
  hands.key(Key::l);
  EXPECT_TRUE(stopwatch.laps().empty()) << "a lap of 0 s, before anything was timed";
  hands.key(Key::space);
  for (int i = 0; i < 24; ++i) hands.frame(1.0 / 60.0);
  EXPECT_GT(now(), 0.3);
  EXPECT_NEAR(stopwatch.reading(now()), now(), 1e-12) << "it started with Play, at t = 0";
  EXPECT_STREQ(stopwatch.start_stop_words(now()), "Stop the stopwatch");
  hands.key(Key::space);  // pause
  const double paused_at = now();
  for (int i = 0; i < 30; ++i) hands.frame(1.0 / 60.0);
  EXPECT_NEAR(stopwatch.reading(now()), paused_at, 1e-12);
  EXPECT_NE(stopwatch.text(now(), false).find("(paused)"), std::string::npos);
  // Played on to the run's end (1 s), where the window pauses: the reading stops there, and it
  // says it stopped with the run, not that someone paused it (the trial's "(paused)").
  hands.key(Key::space);
  for (int i = 0; i < 120; ++i) hands.frame(1.0 / 60.0);
  ASSERT_FALSE(hands.classroom().playback().playing()) << "the run ended";
  const double duration = hands.classroom().playback().readings().duration;
  EXPECT_NEAR(now(), duration, hands.lesson().scene().frame_step());
  EXPECT_NEAR(stopwatch.reading(now()), now(), 1e-12);
  ASSERT_TRUE(hands.classroom().playback().at_run_end());
  char said[64];
  std::snprintf(said, sizeof said, "stopwatch %.2f s (stopped at the run's end)", now());
  const auto shown_text = [&] {
    draw::FrameRecord record;
    hands.frame(0.0, &record);
    // Over the title, beside the lesson's clock.
    for (const draw::ShownText& text : record.texts) {
      if (text.text.rfind("stopwatch ", 0) == 0) return text.text;
    }
    return std::string("no stopwatch drawn");
  };
  EXPECT_EQ(shown_text(), said) << "as the window draws it";
  // A step back from the end is no longer the run's end: paused there.
  hands.key(Key::comma);
  EXPECT_FALSE(hands.classroom().playback().at_run_end());
  std::snprintf(said, sizeof said, "stopwatch %.2f s (paused)", now());
  EXPECT_EQ(shown_text(), said);
  hands.key(Key::period);
  ASSERT_TRUE(hands.classroom().playback().at_run_end()) << "stepped forward to the end again";
  // Played on past the end and paused by hand: paused, as it says.
  hands.key(Key::space);
  for (int i = 0; i < 6; ++i) hands.frame(1.0 / 60.0);
  hands.key(Key::space);
  EXPECT_FALSE(hands.classroom().playback().at_run_end());
  std::snprintf(said, sizeof said, "stopwatch %.2f s (paused)", now());
  EXPECT_EQ(shown_text(), said);
  // R: back to t = 0, where it read 0 and was armed.
  hands.key(Key::r);
  EXPECT_EQ(now(), 0.0);
  EXPECT_EQ(stopwatch.reading(0.0), 0.0);
  EXPECT_TRUE(stopwatch.running()) << "still armed for the next run";
  hands.key(Key::space);
  for (int i = 0; i < 12; ++i) hands.frame(1.0 / 60.0);
  EXPECT_GT(now(), 0.1);
  EXPECT_NEAR(stopwatch.reading(now()), now(), 1e-12) << "the next run is timed too";
}

// Shown from the last class's settings, it is armed as the window opens: a window opened at a
// later time (--at, as the README's screenshots are taken) shows it read the run up to there.
TEST(Stopwatch, ShownFromTheSettingsItTimesTheRunFromTheStart) {
  ClassroomOptions options = lesson_options("incline");
  options.window.tools.stopwatch = true;
  ClassroomHands hands(options);
  hands.classroom().playback().run_to(0.6);  // what --at does before the first frame
  hands.frame();
  const double now = hands.lesson().scene().time();
  EXPECT_NEAR(now, 0.6, 1e-9);
  EXPECT_NEAR(hands.classroom().tools().stopwatch.reading(now), now, 1e-12);
  EXPECT_EQ(hands.classroom().tools().stopwatch.text(now, false), "stopwatch 0.60 s (paused)");
}

// A stopwatch started and stopped by hand (W) mid-run, with a lap: taken back to a time inside
// what it timed, it reads what it read then, is on again, and keeps the laps taken by then only.
TEST(Stopwatch, TakenBackInTimeItReadsWhatItReadThen) {
  ClassroomHands hands(lesson_options("push"));
  classroom_state::Playback& playback = hands.classroom().playback();
  const auto now = [&] { return hands.lesson().scene().time(); };  // R and the time bar rebuild the scene
  const Stopwatch& stopwatch = hands.classroom().tools().stopwatch;
  hands.frame();
  playback.run_to(0.5);
  hands.key(Key::w);  // on at 0.5, paused: Play starts it
  EXPECT_EQ(stopwatch.text(now(), false), "stopwatch 0.00 s (starts with Play)");
  hands.key(Key::space);
  while (now() < 0.75 - 1e-9) hands.frame(1.0 / 240.0);
  hands.key(Key::l);  // a lap at 0.75: 0.25 s
  while (now() < 1.5 - 1e-9) hands.frame(1.0 / 240.0);
  hands.key(Key::w);  // off at 1.5
  const double stopped_at = now();
  while (now() < 2.0 - 1e-9) hands.frame(1.0 / 240.0);
  hands.key(Key::space);
  ASSERT_FALSE(playback.playing());
  EXPECT_NEAR(stopwatch.reading(now()), stopped_at - 0.5, 1e-9);
  ASSERT_EQ(stopwatch.laps().size(), 1u);
  EXPECT_NEAR(stopwatch.laps()[0], 0.25, 1e-9);
  // The time bar back to t = 1.0: it read 0.5 s then, running.
  playback.scrub_to(1.0);
  hands.frame();
  EXPECT_NEAR(now(), 1.0, 1e-9);
  EXPECT_NEAR(stopwatch.reading(now()), 0.5, 1e-9);
  EXPECT_TRUE(stopwatch.running());
  EXPECT_EQ(stopwatch.laps().size(), 1u) << "the lap at 0.75 was taken by then";
  // Back to 0.6: the lap had not been taken yet.
  playback.scrub_to(0.6);
  hands.frame();
  EXPECT_NEAR(stopwatch.reading(now()), 0.1, 1e-9);
  EXPECT_TRUE(stopwatch.laps().empty());
  // R: at t = 0 it had not been started; nor does Play start it now (the teacher started it at 0.5).
  hands.key(Key::r);
  EXPECT_EQ(stopwatch.reading(0.0), 0.0);
  EXPECT_FALSE(stopwatch.running());
  EXPECT_EQ(stopwatch.text(0.0, false), "stopwatch 0.00 s (stopped)");
}

}  // namespace
}  // namespace frictionlab::classroom
