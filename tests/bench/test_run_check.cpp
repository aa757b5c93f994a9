// Failed runs are named, not dropped: a run that chatters, sticks where the exact motion
// slides, slides or creeps where it sticks, or stops being a number is marked as such, on
// made-up velocity records. (Real runs either side of the regularized law's boundary, judged
// so: tests/bench/test_problems.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "bench/cheapest_setting.h"
#include "bench/run_check.h"
#include "physics/stability.h"

namespace frictionlab {
namespace {

constexpr double h = 1.0 / 240.0;

// A block at rest whose velocity is kicked to 5 mm/s and then multiplied by `factor` each step:
// between -1 and 0 it rings and dies away, at -1 it flips for ever.
std::string ringing(double factor, const ExpectedMotion& expected) {
  RunCheck check;
  double v = 0.005;
  for (int i = 0; i < 480; ++i, v *= factor) check.add(i * h, 0.0, v);
  return check.failure(expected);
}

TEST(RunCheck, ChatterIsFlippingThatDoesNotDieAway) {
  const ExpectedMotion at_rest{{}, false};
  EXPECT_EQ(ringing(-1.0, at_rest), "chatters");
  // Kept half its size over eight flips (|factor| >= 0.917, a step from 0.96 of the boundary):
  // chatter. The stability map's classifier asks for fifty (0.993 of it); eight is what a
  // stick phase of a coarse run has room for.
  EXPECT_EQ(ringing(-0.95, at_rest), "chatters");
  EXPECT_EQ(ringing(-0.8, at_rest), "");  // rings for a while, but dies away
  EXPECT_EQ(ringing(-0.5, at_rest), "");
  EXPECT_EQ(ringing(0.5, at_rest), "");
}

TEST(RunCheck, NotANumberAndBlowUpComeFirst) {
  RunCheck nan, blown, far;
  for (int i = 0; i < 10; ++i) {
    nan.add(i * h, 0.0, i == 5 ? NAN : 0.0);
    blown.add(i * h, std::pow(10.0, i), 1.0);
    far.add(i * h, 0.0, 150.0);  // a hundred times the exact motion's scale (at least 1 m or 1 m/s) is a blow-up
  }
  EXPECT_EQ(nan.failure({}), "not a number");
  EXPECT_EQ(blown.failure({}), "blew up");
  EXPECT_EQ(far.failure({{}, true, 0.3}), "blew up");
  EXPECT_EQ(far.failure({{}, true, 1.0}), "blew up");
  EXPECT_NE(far.failure({{}, true, 2.0}), "blew up");
}

// Three slides of a second, each followed by half a second at rest: stops at 1, 2.5 and 4 s.
RunCheck three_slides(double duration) {
  RunCheck check;
  for (int i = 0; i <= static_cast<int>(duration / h); ++i) {
    const double t = i * h, phase = std::fmod(t, 1.5);
    check.add(t, t, phase < 1.0 ? 0.3 * std::sin(M_PI * phase) : 0.0);
  }
  return check;
}

TEST(RunCheck, StopsArePairedWithTheExactOnesByTime) {
  const RunCheck check = three_slides(4.5);
  ASSERT_EQ(check.stop_times().size(), 3u);
  EXPECT_NEAR(check.stop_times()[1], 2.5, 0.01);
  EXPECT_EQ(check.failure({{1.0, 2.5, 4.0}, true}), "");
  EXPECT_EQ(check.failure({{1.05, 2.4, 4.02}, true}), "");  // near their times
  EXPECT_EQ(check.failure({{2.5}, true}), "spurious stick-slip");
  EXPECT_EQ(check.failure({{1.0, 1.8, 2.5, 4.0}, true}), "misses stick-slip");
  // As many stops as the exact motion, at the wrong times: not the same stick-slip.
  EXPECT_EQ(check.failure({{0.3, 0.5, 0.7}, true}), "spurious stick-slip");
  // The exact motion's one stop missed: it never comes to rest.
  RunCheck coasting;
  for (int i = 0; i <= 480; ++i) coasting.add(i * h, 0.5 * i * h, 0.5);
  EXPECT_EQ(coasting.failure({{1.0}, true}), "never comes to rest");
}

TEST(RunCheck, AStopInTheLastTenthIsNotHeldAgainstTheRun) {
  EXPECT_EQ(three_slides(4.5).failure({{1.0, 2.5}, true}), "spurious stick-slip");  // 4 s is before 4.05 s
  EXPECT_EQ(three_slides(4.3).failure({{1.0, 2.5}, true}), "");                     // 4 s is after 3.87 s
  EXPECT_EQ(three_slides(4.5).failure({{1.0, 2.5, 4.0, 4.45}, true}), "");
}

TEST(RunCheck, ABlockThatShouldMoveAndStaysPutSticks) {
  RunCheck held;
  for (int i = 0; i <= 480; ++i) held.add(i * h, 0.0, 0.0);
  EXPECT_EQ(held.failure({{}, true}), "sticks");
  EXPECT_EQ(held.failure({{}, false}), "");
}

TEST(RunCheck, ABlockThatShouldStayPutCreepsOrSlides) {
  RunCheck creep, slide, still;
  for (int i = 0; i <= 480; ++i) {
    const double t = i * h;
    creep.add(t, 0.01 * t, 0.01);
    slide.add(t, 0.5 * t * t, t);
    still.add(t, 1e-4 * t, 1e-4);
  }
  const ExpectedMotion at_rest{{}, false};
  EXPECT_EQ(creep.failure(at_rest), "creeps");
  EXPECT_EQ(slide.failure(at_rest), "slides");
  EXPECT_EQ(still.failure(at_rest), "");  // 0.2 mm in 2 s: within a millimetre of its place
}

}  // namespace
}  // namespace frictionlab
