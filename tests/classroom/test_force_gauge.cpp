// The force gauge, driven as a teacher drives it: ImGui's mouse and keys written across frames on
// an EGL context with no display (as test_classroom does). Each test checks a figure against the
// closed form it must show: static friction mu_s·m·g as the gauge's peak, kinetic friction
// mu_k·m·g as its plateau. (The measuring tools' tests are tests/classroom/test_measuring_tools.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "classroom/classroom.h"
#include "classroom/force_gauge.h"
#include "classroom/measuring_tools.h"
#include "draw/overlays.h"
#include "draw/theme.h"
#include "lessons/runtime/catalog.h"
#include "tests/classroom_hands.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::classroom {
namespace {

constexpr double g = 9.81;

// push at its default mu (wood on wood, mu_s 0.4, mu_k 0.3), a 10 kg block, its own push at its
// slowest (0.2 N/s, so that the hand does nearly all the pulling: 0.3 N by 1.5 s, 1 % of the
// friction). Pulled by hand at a steady 0.1 m/s or so, slowly enough that the gauge's force grows
// by a few newtons a second: it holds until the hand's pull and the push reach mu_s·m·g, then
// slides with the pull at mu_k·m·g once the gauge's swing has died.
TEST(ForceGauge, AHandPullShowsStaticFrictionAsThePeakAndKineticAsThePlateau) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}));
  hands.frame();
  const double mu_s = hands.lesson().parameter("mu_s").value, mu_k = hands.lesson().parameter("mu_k").value;
  ASSERT_EQ(mu_s, 0.4);
  ASSERT_EQ(mu_k, 0.3);
  const double m = 10.0;
  // A pixel a frame: 60 px/s, about 0.1 m/s at this view's scale.
  const float ppm = hands.classroom().world_camera().pixels_per_metre;
  hands.pull_right("block", 1.0f, 2.0);
  const double hand_speed = 60.0 / static_cast<double>(ppm);
  EXPECT_GT(hand_speed, 0.03);
  EXPECT_LT(hand_speed, 0.3);

  const Scene& scene = hands.lesson().scene();
  const classroom_state::GaugeRecord& gauge = hands.classroom().playback().gauge();
  ASSERT_FALSE(gauge.empty());
  const std::optional<classroom_state::GaugeFigures> figures = gauge.figures(scene.frame_step());
  ASSERT_TRUE(figures.has_value());
  ASSERT_TRUE(figures->plateau.has_value()) << "it slid for less than 0.1 s after settling";
  // The lesson pushed too: the figures are the hand's pull and the push together, which is what
  // friction answered, and say so.
  EXPECT_EQ(figures->lesson_pulls, "push");
  EXPECT_EQ(hands.classroom().gauge_figures().rfind("hand + push: peak ", 0), 0u) << hands.classroom().gauge_figures();
  // The peak: hand and push together are static friction's limit; 1 % for the gauge's rise
  // within the breaking step.
  EXPECT_NEAR(*figures->peak, mu_s * m * g, 0.01 * mu_s * m * g);
  // The gauge alone at the peak, as the class reads the scale: within 2 % of mu_s·m·g (the push
  // is under 0.5 %).
  const auto at_peak = std::find_if(gauge.samples().begin(), gauge.samples().end(),
                                    [&](const classroom_state::GaugeSample& sample) { return sample.t == figures->peak_time; });
  ASSERT_NE(at_peak, gauge.samples().end());
  EXPECT_NEAR(at_peak->force, mu_s * m * g, 0.02 * mu_s * m * g);
  // The plateau: the mean pull while it slid, from 0.4 s after the peak; the pull's swing has
  // died to a tenth by then.
  EXPECT_NEAR(*figures->plateau, mu_k * m * g, 0.01 * mu_k * m * g);
  // The peak is static, the plateau kinetic: the drop a class sees is (mu_s − mu_k)·m·g.
  EXPECT_NEAR(*figures->peak - *figures->plateau, (mu_s - mu_k) * m * g, 0.1 * (mu_s - mu_k) * m * g);
  // Back through the time bar and forward again: the run is replayed, and the gauge reads the
  // same, sample for sample.
  const std::vector<classroom_state::GaugeSample> recorded = gauge.samples();
  const double end = scene.time();
  hands.classroom().playback().scrub_to(0.5);
  EXPECT_LT(gauge.samples().size(), recorded.size());
  hands.classroom().playback().scrub_to(end);
  ASSERT_EQ(gauge.samples().size(), recorded.size());
  for (std::size_t i = 0; i < recorded.size(); ++i) {
    EXPECT_EQ(gauge.samples()[i].frame, recorded[i].frame);
    EXPECT_EQ(gauge.samples()[i].force, recorded[i].force);
  }
  std::printf("gauge: peak %.4f N at %.3f s (mu_s·m·g %.4f N), plateau %.4f N over %.2f–%.2f s (mu_k·m·g %.4f N), "
              "hand %.3f m/s\n",
              *figures->peak, figures->peak_time, mu_s * m * g, *figures->plateau, figures->plateau_from,
              figures->plateau_to, mu_k * m * g, hand_speed);
}

// The mouse's hand on push's block, taken hold of at its centre with the lesson playing, moved
// to the right a number of pixels each display frame (60 a second) for a number of frames.
struct HandOnTheBlock {
  explicit HandOnTheBlock(ClassroomHands& taking) : hands(taking), held(taking.take_hold_and_play("block")), x(held.x) {}
  void move(float pixels_per_frame, int frames) {
    for (int i = 0; i < frames; ++i) {
      x += pixels_per_frame;
      ImGui::GetIO().MousePos = ImVec2(x, held.y);
      hands.frame(1.0 / 60.0);
    }
  }
  ClassroomHands& hands;
  ImVec2 held;
  float x;
};

// The peak is the breakaway's: pulled slowly until the block slides, then three times faster,
// the gauge reads more than it did at the breakaway (the hand drags it harder through the
// gauge's spring), and that later, larger pull is no peak. The trial's incline said "peak 11.4
// N" in mid-slide against a breakaway of 9.8 N, and its pulley 10.5 N for a weight's landing.
TEST(ForceGauge, ThePeakIsTheBreakawaysNotALargerPullWhileItSlides) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}));
  hands.frame();
  const double m = 10.0, mu_s = 0.4;
  HandOnTheBlock hand(hands);
  const auto move = [&](float pixels_per_frame, int frames) { hand.move(pixels_per_frame, frames); };
  move(1.0f, 20);  // slowly: still held
  EXPECT_EQ(hands.classroom().gauge_figures().rfind("hand + push: held so far ", 0), 0u)
      << hands.classroom().gauge_figures();
  move(1.0f, 100);  // until it has broken away
  const classroom_state::GaugeRecord& gauge = hands.classroom().playback().gauge();
  const double frame_step = hands.lesson().scene().frame_step();
  ASSERT_TRUE(gauge.figures(frame_step)->broke_away) << "it slid within 2 s";
  move(8.0f, 30);  // then a hard yank
  const std::optional<classroom_state::GaugeFigures> figures = gauge.figures(frame_step);
  double largest = 0.0;
  for (const classroom_state::GaugeSample& sample : gauge.samples()) largest = std::max(largest, std::abs(sample.pull));
  ASSERT_GT(largest, 1.2 * mu_s * m * g) << "the yank pulled harder than the breakaway";
  ASSERT_TRUE(figures->peak.has_value());
  EXPECT_NEAR(*figures->peak, mu_s * m * g, 0.01 * mu_s * m * g) << "the peak is the breakaway's";
  EXPECT_EQ(hands.classroom().gauge_figures().rfind("hand + push: peak ", 0), 0u) << hands.classroom().gauge_figures();
}

// Issue 31's trial: pulled along, then held still, the block coasts on through the gauge's spring
// to a stop, the reading under friction all the while (and past the hand, the spring pushing);
// those steps counted, the "sliding" figure read 33 % under μk·m·g on the mystery surface (and
// 46 % under it here). Only steps of steady sliding count now: each with a net force (its momentum's change) within 5 % of
// the pull, so that the pull is friction's within 5 %, and their mean too.
TEST(ForceGauge, AHandThatStopsLetsTheBodyCoastAndTheSlidingFigureIsTheSteadySlidesOnly) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}));
  hands.frame();
  const double m = 10.0, mu_k = 0.3;
  HandOnTheBlock hand(hands);
  const auto move = [&](float pixels_per_frame, int frames) { hand.move(pixels_per_frame, frames); };
  move(10.0f, 40);  // yanked along at about 1 m/s for two thirds of a second
  move(0.0f, 120);  // then held still for two seconds
  const classroom_state::GaugeRecord& gauge = hands.classroom().playback().gauge();
  const double frame_step = hands.lesson().scene().frame_step();
  const std::optional<classroom_state::GaugeFigures> figures = gauge.figures(frame_step);
  ASSERT_TRUE(figures && figures->broke_away && figures->plateau) << hands.classroom().gauge_figures();
  // The coast happened, and counted in would have taken the figure out of its 5 %: the mean of
  // every sliding step from the settling on, as the figure was.
  const double friction = mu_k * m * g;
  double sum = 0.0;
  long count = 0, coasting = 0;
  for (const classroom_state::GaugeSample& sample : gauge.samples()) {
    if (!sample.slipping || sample.t < figures->peak_time + classroom_state::GaugeRecord::settle_time) continue;
    sum += std::abs(sample.pull);
    ++count;
    if (std::abs(sample.pull) < 0.9 * friction) ++coasting;
  }
  ASSERT_GT(coasting, 0) << "the block did not coast under the gauge's pull";
  EXPECT_GT(std::abs(sum / static_cast<double>(count) - friction), 0.05 * friction)
      << "every sliding step's mean, " << sum / static_cast<double>(count) << " N, is within 5 % of μk·m·g: the test shows nothing";
  EXPECT_NEAR(*figures->plateau, friction, 0.05 * friction) << hands.classroom().gauge_figures();
  std::printf("stopped hand: sliding figure %.3f N (every sliding step's mean %.3f N, %ld of %ld steps coasting under 0.9·μk·m·g), "
              "μk·m·g %.3f N\n",
              *figures->plateau, sum / static_cast<double>(count), coasting, count, friction);
}

// spring_pull: the lesson's spring drags the block ahead of a hand that holds still. The gauge
// reads the hand holding back; its figures are the spring's pull and the hand's together, which
// is what friction answers: mu_s·m·g at the breakaway, mu_k·m·g while it slides. (Taken from
// the gauge alone they were "peak 9.3 N, sliding: not yet": the hand's pull only grew.)
TEST(ForceGauge, WhenTheLessonPullsTooTheFiguresAreThePullsTogether) {
  ClassroomHands hands(gauge_options("spring_pull"));
  hands.frame();
  const double mu_s = hands.lesson().parameter("mu_s").value, mu_k = hands.lesson().parameter("mu_k").value;
  const double m = hands.lesson().parameter("mass").value;
  hands.pull_right("block", 0.0f, 0.0, 5.0);
  const Scene& scene = hands.lesson().scene();
  const classroom_state::GaugeRecord& gauge = hands.classroom().playback().gauge();
  const std::optional<classroom_state::GaugeFigures> figures = gauge.figures(scene.frame_step());
  ASSERT_TRUE(figures.has_value());
  EXPECT_EQ(figures->lesson_pulls, "spring");
  std::printf("spring_pull held: peak %.4f N (mu_s·m·g %.4f N), plateau %.4f N over %.2f–%.2f s (mu_k·m·g %.4f N)\n",
              figures->peak.value_or(NAN), mu_s * m * g, figures->plateau.value_or(NAN), figures->plateau_from, figures->plateau_to,
              mu_k * m * g);
  EXPECT_NEAR(*figures->peak, mu_s * m * g, 0.01 * mu_s * m * g);
  ASSERT_TRUE(figures->plateau.has_value()) << hands.classroom().gauge_figures();
  EXPECT_NEAR(*figures->plateau, mu_k * m * g, 0.02 * mu_k * m * g);
  EXPECT_EQ(hands.classroom().gauge_figures().rfind("hand + spring: peak ", 0), 0u) << hands.classroom().gauge_figures();
  // The scale reads the hand holding back: its far end stays where the block was taken, so its
  // reading grows as the block slides away from it.
  EXPECT_GT(gauge.samples().back().force, gauge.samples().front().force);
}

// The ring the hand holds is drawn under the pointer, in projector mode at 1920 × 1080 (it was
// drawn at the far end of the scale's case, 124 px ahead of it), while the mouse moves and when
// it stops; the hook stays on the point taken, and the case lies between them.
TEST(ForceGauge, TheRingIsDrawnAtThePointer) {
  ClassroomOptions options = gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}, true);
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  hands.frame();
  const b2Body* block = hands.lesson().scene().body("block");
  const ImVec2 held = hands.take_hold_and_play("block");
  const float scale = hands.classroom().ui_scale(ImVec2(1920.0f, 1080.0f));
  for (int i = 1; i <= 120; ++i) {
    // Two pixels a frame for a second, then still for a second.
    ImGui::GetIO().MousePos = ImVec2(held.x + 2.0f * static_cast<float>(std::min(i, 60)), held.y);
    draw::FrameRecord record;
    hands.frame(1.0 / 60.0, &record);
    if (i % 30 != 0) continue;
    ASSERT_EQ(record.lanes.size(), 1u);
    const Scene& scene = hands.lesson().scene();
    const draw::Camera& camera = record.lanes.front().camera;
    const GaugeShape shape = gauge_shape(scene, camera, scale);
    const ImVec2 pointer = ImGui::GetIO().MousePos;
    EXPECT_NEAR(shape.ring.x, pointer.x, 0.5f) << "frame " << i;
    EXPECT_NEAR(shape.ring.y, pointer.y, 0.5f) << "frame " << i;
    // The pointer means the world point the hand pulls to, through the camera the lane drew with.
    const b2Vec2 under = camera.to_world(pointer);
    EXPECT_NEAR(under.x, scene.grab_target().x, 0.5f / camera.pixels_per_metre);
    const ImVec2 hook = camera.to_screen(block->GetWorldPoint(scene.applied_forces().back().local_point));
    EXPECT_NEAR(shape.hook.x, hook.x, 1e-3f);
    // The case lies between the hook and the ring, ending at the ring's edge.
    EXPECT_GE(shape.case_start.x, shape.hook.x) << "frame " << i;
    EXPECT_LE(shape.case_start.x, shape.ring.x - shape.ring_radius + 1e-3f) << "frame " << i;
  }
  hands.button(false);
}

// In projector mode push's plots come a page at a time, and the gauge's plot is the last page:
// while the hand pulls, the pages turn to it, so the class sees the reading the hand makes.
TEST(ForceGauge, WhileTheHandPullsThePlotPagesShowTheGauge) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}, true), ImVec2(1920.0f, 1080.0f));
  const auto gauge_plot_shown = [&] {
    draw::FrameRecord record;
    hands.frame(1.0 / 60.0, &record);
    bool paged = false, shown = false;
    for (const draw::ShownText& text : record.texts) {
      // The pager's line: the first plot's title and "  (page/pages)".
      paged = paged || (text.text.find("  (") != std::string::npos && text.text.find('/') != std::string::npos);
      shown = shown || text.text.rfind("Hand + push (N)", 0) == 0;
    }
    EXPECT_TRUE(paged) << "push's plots are expected a page at a time in projector mode";
    return shown;
  };
  gauge_plot_shown();
  const ImVec2 held = hands.take_hold_and_play("block");
  for (int i = 1; i <= 30; ++i) {
    ImGui::GetIO().MousePos = ImVec2(held.x + 2.0f * static_cast<float>(i), held.y);
    hands.frame(1.0 / 60.0);
  }
  EXPECT_TRUE(gauge_plot_shown());
  hands.button(false);
}

// A teacher's trial (issue 31): in projector mode the gauge's plot put "time (s)" on a line of its
// own under the tick labels, where the guide says a projector's plots end the tick labels' line
// with it, and ticked its force axis every 20 N of 60. On its page it is laid out as the lesson's
// plots are: the axis' name on the x tick labels' line, past the data's right end, and the force
// ticks as fine as the lesson plots' (push's key plot: a line and a half of body text apart).
TEST(ForceGauge, OnAProjectorTheGaugesPlotIsLaidOutAsTheLessonsPlotsAre) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}, true), ImVec2(1920.0f, 1080.0f));
  hands.frame();
  const ImVec2 held = hands.take_hold_and_play("block");
  draw::FrameRecord record;
  for (int i = 1; i <= 90; ++i) {
    ImGui::GetIO().MousePos = ImVec2(held.x + static_cast<float>(i), held.y);
    hands.frame(1.0 / 60.0, i == 90 ? &record : nullptr);
  }
  const std::size_t extra = hands.lesson().plots().size();
  const auto gauge = std::find_if(record.plots.begin(), record.plots.end(),
                                  [&](const draw::FrameRecord::Plot& plot) { return plot.number == extra; });
  ASSERT_NE(gauge, record.plots.end()) << "the gauge's plot is expected on the page while the hand pulls";
  const draw::ChartLayout& layout = gauge->layout;
  using TextKind = draw::ChartLayout::AxisText::Kind;
  const auto name = std::find_if(layout.axis_texts.begin(), layout.axis_texts.end(),
                                 [](const draw::ChartLayout::AxisText& text) { return text.kind == TextKind::x_name; });
  ASSERT_NE(name, layout.axis_texts.end());
  EXPECT_EQ(name->text, "time (s)");
  EXPECT_GE(name->at.x, layout.high_right.x) << "the axis' name is expected past the data's right end";
  ASSERT_GE(std::count_if(layout.axis_texts.begin(), layout.axis_texts.end(),
                          [](const draw::ChartLayout::AxisText& text) { return text.kind == TextKind::x_tick; }),
            2);
  for (const draw::ChartLayout::AxisText& tick : layout.axis_texts) {
    if (tick.kind != TextKind::x_tick) continue;
    // On the tick labels' line: their boxes overlap in height.
    EXPECT_LT(name->at.y, tick.at.w) << "\"time (s)\" is expected on the line of \"" << tick.text << "\", not under it";
    EXPECT_GT(name->at.w, tick.at.y) << "\"time (s)\" is expected on the line of \"" << tick.text << "\", not over it";
  }
  // The force ticks at least a line and a half of body text apart and no further than twice
  // that (a tick spacing of 1, 2 or 5 times a power of ten is at most 2.5 times the least).
  ASSERT_GE(layout.y_ticks.size(), 2u);
  const float spacing = (layout.low_left.y - layout.high_right.y) *
                        static_cast<float>((layout.y_ticks[1] - layout.y_ticks[0]) / (layout.y_high - layout.y_low));
  const float least = draw::plot_tick_spacing_points(true) * hands.classroom().ui_scale(ImVec2(1920.0f, 1080.0f));
  EXPECT_GE(spacing, least - 0.5f);
  EXPECT_LE(spacing, 2.5f * least) << "the force axis ticked every " << layout.y_ticks[1] - layout.y_ticks[0] << " N";
  hands.button(false);
}

// The gauge's plot covers the hand's latest pull, not the lesson's whole time axis: a pull of a
// second at t = 20 s after one at t = 0 is drawn over 20 s or so, not as a line at the end of
// 0–21 s. With the lesson pushing too, the line is the hand's pull and the push together.
TEST(ForceGauge, ThePlotsTimeAxisCoversTheLatestPull) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}));
  hands.frame();
  hands.pull_right("block", 1.0f, 1.0);
  classroom_state::Playback& playback = hands.classroom().playback();
  playback.run_to(20.0);
  const double taken = playback.lesson().scene().time();
  hands.pull_right("block", 1.0f, 1.0);
  const double h = playback.lesson().scene().frame_step();
  const classroom_state::GaugeRecord& gauge = playback.gauge();
  ASSERT_EQ(gauge.stretches(h).size(), 2u);
  const double end = gauge.samples().back().t;
  const draw::Chart chart = gauge_chart(gauge, h, theme(draw::ThemeName::light));
  ASSERT_TRUE(chart.fixed_x);
  // From a tenth of the pull before the hand took hold to a twentieth after it let go.
  EXPECT_NEAR(chart.x_low, taken - 0.1 * (end - taken), 2.0 * h);
  EXPECT_NEAR(chart.x_high, end + 0.05 * (end - taken), 2.0 * h);
  ASSERT_EQ(chart.series.size(), 1u);
  for (const auto& [t, force] : chart.series[0].points) EXPECT_GE(t, taken);
  // The lesson pushes too: the line is the hand's reading and the push together along the floor,
  // as the figures over it are taken.
  EXPECT_EQ(chart.series[0].name, "hand + push");
  const classroom_state::GaugeSample& last = gauge.samples().back();
  EXPECT_NEAR(chart.series[0].points.back().second, last.force + 0.2 * (last.t - h), 1e-3);
  for (const auto& [from, to] : chart.bands) EXPECT_GE(from, taken - h);
}

// The view holds still while the hand pulls, so a body can be dragged to the world's top right,
// where the free-body inset sits: the inset then moves to the top left, and the body, the gauge
// and the ring stay in sight (the trial's block went under it). On a screen: a projector leaves
// the inset out (draw::free_body_readable).
TEST(ForceGauge, ABodyDraggedUnderTheFreeBodyInsetStaysInSight) {
  ClassroomHands hands(gauge_options("push", {}, false), ImVec2(1920.0f, 1080.0f));
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  const ImVec4 inset_at_first = record.inset;
  const b2Body* block = hands.lesson().scene().body("block");
  const ImVec2 held = hands.take_hold_and_play("block");
  // Across to under the inset's middle, in a second and a half.
  const float to_x = 0.5f * (inset_at_first.x + inset_at_first.z);
  const float to_y = 0.5f * (inset_at_first.y + inset_at_first.w);
  for (int i = 1; i <= 90; ++i) {
    const float part = static_cast<float>(i) / 90.0f;
    ImGui::GetIO().MousePos = ImVec2(held.x + part * (to_x - held.x), held.y + part * (to_y - held.y));
    hands.frame(1.0 / 60.0, &record);
  }
  const b2AABB box = lessons::body_box(block);
  const draw::Camera& camera = record.lanes.front().camera;
  const ImVec2 top_right = camera.to_screen(box.upperBound), bottom_left = camera.to_screen(box.lowerBound);
  ASSERT_GT(top_right.x, inset_at_first.x) << "the block was dragged to where the inset was";
  ASSERT_LT(top_right.y, inset_at_first.w);
  const bool covered = top_right.x > record.inset.x && bottom_left.x < record.inset.z && top_right.y < record.inset.w &&
                       bottom_left.y > record.inset.y;
  EXPECT_FALSE(covered) << "the inset now spans x " << record.inset.x << " to " << record.inset.z;
  hands.button(false);
}

// The body the hand pulls stays in sight. push in projector mode at 1920 × 1080: its block
// taken hold of at its centre and pulled to the right at 12 px a frame for 2.5 s, the mouse
// running on over the panels beside the world to the screen's edge, and held there for a second.
// In every frame the block's box on the screen, and the gauge's ring, lie inside what the world
// view shows; once the hand is stopped at the view's edge the status line says so, and it says
// it no more once the hand lets go. Issue 31: the view holds still while the hand pulls (so that
// the mouse's place keeps its meaning), and a teacher's drag pulled the block out of the picture.
TEST(ForceGauge, TheBodyTheHandPullsStaysInSight) {
  ClassroomHands hands(gauge_options("push", {}, true), ImVec2(1920.0f, 1080.0f));
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  const b2Body* block = hands.lesson().scene().body("block");
  const ImVec2 held = hands.take_hold_and_play("block");
  bool stopped_said = false;
  float furthest_mouse = held.x;
  const auto check = [&](const std::string& when) {
    ASSERT_EQ(record.lanes.size(), 1u);
    const ImVec4& shown = record.lanes.front().shown;
    const draw::Camera& camera = record.lanes.front().camera;
    const b2AABB box = lessons::body_box(block);
    const ImVec2 low = camera.to_screen(box.lowerBound), high = camera.to_screen(box.upperBound);
    EXPECT_TRUE(low.x >= shown.x && high.x <= shown.z && high.y >= shown.y && low.y <= shown.w)
        << when << ": the block spans x " << low.x << " to " << high.x << ", y " << high.y << " to " << low.y
        << "; the view shows x " << shown.x << " to " << shown.z << ", y " << shown.y << " to " << shown.w;
    const ImVec2 ring = camera.to_screen(hands.lesson().scene().grab_target());
    EXPECT_TRUE(ring.x >= shown.x && ring.x <= shown.z && ring.y >= shown.y && ring.y <= shown.w)
        << when << ": the gauge's ring at " << ring.x << ", " << ring.y << " is out of the view";
    stopped_said = stopped_said || hands.classroom().status().find("edge of the view") != std::string::npos;
  };
  for (int i = 1; i <= 150; ++i) {
    furthest_mouse = std::min(held.x + 12.0f * static_cast<float>(i), 1919.0f);
    ImGui::GetIO().MousePos = ImVec2(furthest_mouse, held.y);
    hands.frame(1.0 / 60.0, &record);
    check("pulled for " + std::to_string(i) + " frames");
  }
  for (int i = 0; i < 60; ++i) {
    hands.frame(1.0 / 60.0, &record);
    check("held at the screen's edge for " + std::to_string(i) + " frames");
  }
  ASSERT_GT(furthest_mouse, record.lanes.front().shown.z) << "the mouse went past the view's right edge";
  ASSERT_EQ(hands.lesson().scene().grabbed(), block) << "the hand still holds the block";
  EXPECT_TRUE(stopped_said) << "the status line never said the hand stopped at the view's edge: " << hands.classroom().status();
  hands.button(false);
  EXPECT_EQ(hands.classroom().status().find("edge of the view"), std::string::npos) << hands.classroom().status();
}

// The lesson's run ends (and pauses) at its duration, but not under a hand that is pulling: the
// trial's teacher had push pause mid-pull. Let go past the end, it pauses then.
TEST(ForceGauge, TheRunsEndWaitsForAPullingHand) {
  ClassroomHands hands(gauge_options("push"));
  hands.frame();
  classroom_state::Playback& playback = hands.classroom().playback();
  const double duration = playback.lesson().duration();
  const ImVec2 held = hands.take_hold_and_play("block");
  const int frames = static_cast<int>(std::lround((duration + 1.0) * 60.0));
  for (int i = 1; i <= frames; ++i) {
    ImGui::GetIO().MousePos = ImVec2(held.x + 0.5f * static_cast<float>(std::min(i, 120)), held.y);
    hands.frame(1.0 / 60.0);
  }
  EXPECT_GT(playback.lesson().scene().time(), duration + 0.5);
  EXPECT_TRUE(playback.playing()) << "paused under the hand at the run's end";
  hands.button(false);
  hands.frame(1.0 / 60.0);
  hands.frame(1.0 / 60.0);
  EXPECT_FALSE(playback.playing()) << "let go past the end, the run pauses";
}

// The class's prediction is about the lesson, not the hand: a run the hand pulled measured the
// hand too (push's breakaway read 3.19 N after a pull by hand, and the class that said 39 N was
// told it was 370 % above), so it is judged against the theory and says why.
TEST(ForceGauge, AHandPulledRunJudgesTheClassAgainstTheTheory) {
  lessons::Prediction breakaway{"breakaway push", "How hard?", "N", {}, "push.lua:1"};
  lessons::ExpectationResult row;
  row.name = "breakaway push";
  row.unit = "N";
  row.numeric = true;
  row.predicted = 39.24;
  row.measured = 3.19;
  row.measured_yet = true;
  row.tolerance = 0.5;
  const Closeness measured = closeness(breakaway, "39", row);
  EXPECT_FALSE(measured.close) << measured.words;  // without the hand: judged against 3.19 N
  row.hand_pulled = true;
  const Closeness pulled = closeness(breakaway, "39", row);
  EXPECT_TRUE(pulled.close) << pulled.words;
  EXPECT_NE(pulled.words.find("the theory (the hand pulled this run)"), std::string::npos) << pulled.words;
}

// A hand-pulled run differs from the lesson's predictions because of the hand, not the physics:
// the theory table marks the rows hand-pulled with the stretch's times and why, and shows no
// failure for them; a reset measures without the hand and judges again.
TEST(ForceGauge, TheTheoryTableMarksAHandPulledStretchAndCountsNoFailure) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}));
  hands.frame();
  hands.pull_right("block", 1.0f, 2.0);
  classroom_state::Playback& playback = hands.classroom().playback();
  playback.refresh_readings();
  const double h = hands.lesson().scene().frame_step();
  const std::vector<classroom_state::HandStretch> stretches = playback.gauge().stretches(h);
  ASSERT_EQ(stretches.size(), 1u);
  EXPECT_NEAR(stretches[0].from, 0.0, 1e-9);
  EXPECT_NEAR(stretches[0].to, hands.lesson().scene().time(), 0.02);  // let go in the last display frame
  const lessons::LessonReadings& readings = playback.readings();
  // The breakaway row measured the lesson's push at breakaway: a third of a newton against
  // 39.2 N, since the hand did the pulling. Without the mark it is a failure.
  const auto breakaway = std::find_if(readings.expectations.begin(), readings.expectations.end(),
                                      [](const lessons::ExpectationResult& row) { return row.name == "breakaway push"; });
  ASSERT_NE(breakaway, readings.expectations.end());
  ASSERT_TRUE(breakaway->measured_yet);
  EXPECT_FALSE(breakaway->passes);
  for (const lessons::ExpectationResult& row : readings.expectations) EXPECT_TRUE(row.hand_pulled) << row.name;
  char times[64];
  std::snprintf(times, sizeof times, "Hand-pulled 0.00\u2013%.2f s: ", stretches[0].to);
  EXPECT_EQ(readings.caveat.rfind(times, 0), 0u) << readings.caveat;
  EXPECT_NE(readings.caveat.find("in no prediction"), std::string::npos) << readings.caveat;

  // What the panel shows: the word, and no failure's cross anywhere.
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  bool marked = false, caveat_shown = false;
  for (const draw::ShownText& text : record.texts) {
    marked = marked || text.text == "hand-pulled";
    caveat_shown = caveat_shown || text.text == readings.caveat;
    EXPECT_EQ(text.text.find("\u2717"), std::string::npos) << "a failure is shown: " << text.text;
  }
  EXPECT_TRUE(marked);
  EXPECT_TRUE(caveat_shown);

  // The window's CSV says which rows the hand pulled and what the gauge read.
  const std::string path = hands.classroom().export_history();
  std::ifstream csv(path);
  std::string header, first, line, last_pulled;
  std::getline(csv, header);
  EXPECT_NE(header.find(",hand_pulled,gauge (N)"), std::string::npos) << header;
  std::getline(csv, first);
  EXPECT_NE(first.find(",1,"), std::string::npos) << "the first step was pulled: " << first;
  std::size_t pulled = 0, rows = 1;
  while (std::getline(csv, line)) {
    ++rows;
    if (line.size() >= 2 && line.back() != ',') ++pulled;
  }
  EXPECT_EQ(pulled + 1, playback.gauge().samples().size());

  // Reset: a run without the hand, judged again.
  hands.key(Key::r);
  playback.refresh_readings();
  EXPECT_TRUE(playback.gauge().empty());
  for (const lessons::ExpectationResult& row : playback.readings().expectations) EXPECT_FALSE(row.hand_pulled) << row.name;
  EXPECT_EQ(playback.readings().caveat.find("Hand-pulled"), std::string::npos);
}

// A hand that pulls the block and then holds still brings it to rest, and it is held there: its
// contact sticks (it is not labelled slipping at 0 m/s). push (10 kg, its own push growing at
// 0.2 N/s) pulled 2 s at 9 cm/s, then held still for 2 s: the gauge and the push together
// (28.5 N + 0.6 N) are under mu_s·m·g = 39.2 N, so static friction holds. With a critically
// damped gauge the block crept after the hand at rate/k = 0.2 mm/s, slipping, for ever.
TEST(ForceGauge, ABodyTheHandHoldsStillSticks) {
  ClassroomHands hands(gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}));
  hands.frame();
  const b2Body* block = hands.lesson().scene().body("block");
  // Held still for 2 s, not let go: the last frame still holds it.
  const ImVec2 held = hands.take_hold_and_play("block");
  for (int i = 1; i <= 240; ++i) {
    ImGui::GetIO().MousePos = ImVec2(held.x + static_cast<float>(std::min(i, 120)), held.y);
    hands.frame(1.0 / 60.0);
  }
  const Scene& scene = hands.lesson().scene();
  ASSERT_EQ(scene.grabbed(), block);
  EXPECT_NEAR(scene.time(), 4.0, 0.01);
  const std::optional<classroom_state::GaugeFigures> figures = hands.classroom().playback().gauge().figures(scene.frame_step());
  ASSERT_TRUE(figures && figures->plateau) << "it slid while the hand pulled";
  // At rest, to float round-off: not a creep of 0.2 mm/s the speed tool shows as 0.000 m/s.
  EXPECT_LT(block->GetLinearVelocity().Length(), 1e-6f) << speed_reading(block);
  ASSERT_FALSE(scene.slipping().empty());
  EXPECT_EQ(scene.slipping().back(), 0) << "the contact still slips";
  const std::vector<ContactMark> marks = contact_marks(scene);
  ASSERT_EQ(marks.size(), 1u);
  EXPECT_EQ(contact_word(marks.front()), "sticking");
  // And what holds it is within static friction's limit.
  const double pull = static_cast<double>(scene.forces_applied()[0].x + scene.forces_applied().back().x);
  EXPECT_LT(pull, 0.4 * 10.0 * g);
  EXPECT_NEAR(std::abs(marks.front().friction_force), pull, 1e-3 * pull);
}

// A teacher's trial: the class answered both of push's questions, the block was pulled by the
// mouse, and the class's lines read "measured: 2.68 N (hand-pulled)" and "measured: larger
// (hand-pulled)", the opposite of what the hand's gauge showed. Before the reveal each line
// says only that the hand pulled, and stays on its answer's line.
TEST(ForceGauge, AClassLineAfterAHandPullSaysTheHandPulledAndNoMeasurement) {
  ClassroomOptions options = gauge_options("push", {}, true);
  options.window.predictions = true;
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  hands.classroom().predictions().answers["breakaway push"] = "5.5";
  hands.classroom().predictions().answers["sliding vs breakaway"] = "smaller";
  hands.frame();
  hands.pull_right("block", 1.0f, 3.0);
  hands.playback().run_to(hands.lesson().duration());
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  ASSERT_TRUE(hands.classroom().theory_hidden());
  int notes = 0;
  for (const draw::ShownText& text : record.texts) {
    if (text.text.rfind("measured:", 0) != 0) continue;
    ++notes;
    EXPECT_EQ(text.text, "measured: hand-pulled");
    EXPECT_TRUE(text.whole_across()) << text.text;
  }
  EXPECT_EQ(notes, 2) << "each answered question has its line";
}

// A teacher's trial, projector mode at 1920×1080: the class predicted push's breakaway, the block
// was pulled by the mouse and the theory revealed; "0.602 N (hand-pulled)" ran past the class
// table's right edge, with no way to scroll sideways. Each cell wraps in its column now; since
// the reveal shows the measurement once, in the theory table ("hand-pulled" in its error
// column), and the class's line says what its answer was set against ("the hand pulled this
// run"), each of those is looked for.
TEST(ForceGauge, AHandPulledMeasurementStaysWholeInTheClassTableOnAProjector) {
  ClassroomOptions options = gauge_options("push", {{"mass", "10"}, {"push_rate", "0.2"}}, true);
  options.window.predictions = true;
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  hands.classroom().predictions().answers["breakaway push"] = "5";
  hands.frame();
  hands.pull_right("block", 1.0f, 1.0);
  hands.classroom().predictions().revealed = true;
  hands.frame();
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  int found = 0;
  for (const draw::ShownText& text : record.texts) {
    if (text.text.find("hand-pulled") == std::string::npos && text.text.find("hand pulled") == std::string::npos) continue;
    ++found;
    EXPECT_TRUE(text.whole_across()) << "\"" << text.text << "\" needs x " << text.needed.x << " to " << text.needed.z
                                     << ", its panel shows " << text.visible.x << " to " << text.visible.z;
  }
  EXPECT_GE(found, 2) << "the theory table's row and the class's line should both say the hand pulled";
}

}  // namespace
}  // namespace frictionlab::classroom
