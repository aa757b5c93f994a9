// Headless frames: the arrows and contact marks found in the pixels where the record puts them,
// the same picture for the same moment whatever was drawn before, and a chart's cells where their
// grid points are. (The picture comparison and PNG files: tests/draw/test_image.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "draw/chart.h"
#include "draw/frame.h"
#include "draw/image.h"
#include "draw/legend.h"
#include "draw/overlays.h"
#include "tests/rendering.h"

namespace frictionlab::draw {
namespace {

// One renderer for the suite's tests in this process: EGL starts once.
HeadlessRenderer& renderer() {
  static HeadlessRenderer shared(frame_width, frame_height);
  return shared;
}

int distance(const std::uint8_t* pixel, ImU32 colour) {
  const int r = static_cast<int>(colour >> IM_COL32_R_SHIFT & 0xFF), g = static_cast<int>(colour >> IM_COL32_G_SHIFT & 0xFF),
            b = static_cast<int>(colour >> IM_COL32_B_SHIFT & 0xFF);
  return std::max({std::abs(pixel[0] - r), std::abs(pixel[1] - g), std::abs(pixel[2] - b)});
}

// Walks from the tail along the arrow while the pixels are the arrow's colour: the drawn
// length, which must be the recorded force times the scale.
float drawn_length(const Image& image, const ScreenArrow& arrow, ImU32 colour) {
  const float length = arrow.length();
  const float ux = (arrow.tip.x - arrow.tail.x) / length, uy = (arrow.tip.y - arrow.tail.y) / length;
  float reached = 0.0f;
  for (float s = 4.0f; s < length + 40.0f; s += 0.5f) {
    const int x = static_cast<int>(std::lround(arrow.tail.x + ux * s)), y = static_cast<int>(std::lround(arrow.tail.y + uy * s));
    if (distance(image.pixel(x, y), colour) > 60) break;
    reached = s;
  }
  return reached;
}

void expect_friction_arrow_and_mark(const LessonAt& at, const Image& image, const FrameRecord& record, ContactState state) {
  const ImVec2 display(frame_width, frame_height);
  const Camera camera = world_camera(*at.lesson, at.framing, display, 1.0f);
  const float scale = arrow_scale(*at.lesson, at.framing, display, 1.0f);
  const b2Body* block = at.scene().body("block");
  // Where the frame drew it: from the contact dot's rim, and slid along its line past the
  // weight's shaft where that crosses it (draw_world); its length is what is measured here.
  ASSERT_EQ(record.lanes.size(), 1u);
  std::optional<ScreenArrow> drawn;
  for (const LabelPlacer::ForceLabel& force : record.lanes.front().forces) {
    if (force.kind == ForceKind::friction && force.body == block) {
      drawn = ScreenArrow{ForceOnBody{}, force.arrow.from, force.arrow.to};
    }
  }
  ASSERT_TRUE(drawn.has_value()) << "no friction arrow drawn";
  const ScreenArrow& friction = *drawn;
  const Theme& colours = theme(ThemeName::light);
  const ContactRecord* touch = at.scene().friction().find(block, at.scene().body("ground"));
  const float recorded = static_cast<float>(std::abs(touch->solver.friction_force));
  // The tip's last pixels fade into the background: within 2 px. The contact point is on the
  // floor's surface, so the arrow runs along the ground's 2.5 px edge line, and its tip's last
  // pixels fade into that dark line instead: up to half its width more.
  // As long as the force at the arrows' scale, or lengthened in order where that is short of what
  // a back row can read (drawn_arrow_pixels: the legend says "not to scale" under that force).
  EXPECT_NEAR(drawn_length(image, friction, colours.force[static_cast<int>(ForceKind::friction)]),
              drawn_arrow_pixels(recorded, scale, legible_arrow_pixels(1.0f)), 2.0f + 0.5f * 2.5f);

  // The contact's mark, just below the friction arrow's shaft at the contact point.
  const std::vector<ContactMark> marks = contact_marks(at.scene());
  ASSERT_EQ(marks.size(), 1u);
  // Read inside the 6 px disc, 4 px below the point: the pixel nearest that which shows either
  // state's colour, since the disc's anti-aliased rim can fall on the sampled pixel (the point
  // is a fraction of a pixel off the drawn centre). It must be the expected state's.
  const ImVec2 point = camera.to_screen(marks[0].point);
  const ImU32 expected = state == ContactState::sticking ? colours.sticking : colours.slipping;
  const ImU32 other = state == ContactState::sticking ? colours.slipping : colours.sticking;
  int nearest = 1000, best = 255;
  for (int dy = -3; dy <= 3; ++dy) {
    for (int dx = -3; dx <= 3; ++dx) {
      const std::uint8_t* pixel = image.pixel(static_cast<int>(point.x) + dx, static_cast<int>(point.y) + 4 + dy);
      const int reach = dx * dx + dy * dy;
      if (std::min(distance(pixel, expected), distance(pixel, other)) <= 8 && reach < nearest) {
        nearest = reach;
        best = distance(pixel, expected);
      }
    }
  }
  EXPECT_LE(best, 8) << "the contact is not marked as " << (state == ContactState::sticking ? "sticking" : "slipping");
}

// Issue 31: the legend said "under 12.4 N: not to scale" on push in projector mode, whose every
// force (its 9.81 N weight the largest) is under 12.4 N: every arrow was lengthened, and the
// words left a class asking which were to scale. The next trial found its words changing as the
// run played ("all arrows to scale" once its friction and push had grown past the number). Said
// now from the arrow scale alone: "dashed: too small" "to draw to scale" "(under X N)" (a
// teacher found "under X N: longer, dashed" cryptic), X the force whose arrow at that scale is
// the legible length, at arrow scales round push's forces and at the projector's own, where X is
// the force drawn_longer turns at.
TEST(Legend, SaysUnderWhichForceArrowsAreDrawnLongerFromTheScaleAlone) {
  LessonAt at("push", {}, 3.0);
  const float scale = 2.0f;
  for (const float newtons : {0.5f, 2.94f, 9.81f, 20.0f}) {
    // The arrow scale (px per N) at which lengthening starts at `newtons`.
    const float pixels_per_newton = legible_arrow_pixels(scale) / newtons;
    EXPECT_EQ(arrow_scale_words(pixels_per_newton, scale),
              ArrowScaleWords({"dashed: too small", "to draw to scale", "(under " + format_quantity(newtons, "N") + ")"}));
  }
  // The projector's text scale: the frame's, a third larger (Classroom::ui_scale).
  const float projector_scale = 1.35f * frame_scale(1920, 1080);
  const float projector = arrow_scale(*at.lesson, at.framing, ImVec2(1920.0f, 1080.0f), projector_scale, true);
  const float below = not_to_scale_below(projector, projector_scale);
  const float legible = legible_arrow_pixels(projector_scale);
  EXPECT_TRUE(drawn_longer(std::nextafter(below, 0.0f), projector, legible));
  EXPECT_FALSE(drawn_longer(below, projector, legible));
  EXPECT_EQ(arrow_scale_words(projector, projector_scale)[2], "(under " + format_quantity(below, "N") + ")");
}

TEST(Rendering, TheFrictionArrowIsDrawnAsLongAsTheRecordedForceAndTheStickingContactIsMarked) {
  LessonAt at("spring_pull", {}, 0.5);
  FrameRecord record;
  const Image image = renderer().render(*at.lesson, at.framing, &record);
  expect_friction_arrow_and_mark(at, image, record, ContactState::sticking);
}

TEST(Rendering, MidSlipTheArrowIsKineticFrictionAndTheContactIsMarkedSlipping) {
  LessonAt at("spring_pull", {}, 1.2);
  FrameRecord record;
  const Image image = renderer().render(*at.lesson, at.framing, &record);
  expect_friction_arrow_and_mark(at, image, record, ContactState::slipping);
}

TEST(Rendering, TheSameMomentGivesTheSamePictureWhateverWasDrawnBefore) {
  LessonAt direct("spring_pull", {}, 1.2);
  const Image once = renderer().render(*direct.lesson, direct.framing);
  LessonAt stepped("spring_pull", {}, 0.3);
  renderer().render(*stepped.lesson, stepped.framing);
  renderer().render(*stepped.lesson, stepped.framing);
  stepped.step_to(1.2);
  const Image later = renderer().render(*stepped.lesson, stepped.framing);
  EXPECT_EQ(once.rgba, later.rgba);
}

// Two renderers at once (a window and a screenshot, say): each draws into its own context and
// font atlas, and the pictures do not depend on the other being there.
TEST(Rendering, TwoRenderersAtOnceDrawTheSamePicture) {
  LessonAt at("incline", {}, 0.5);
  const Image alone = renderer().render(*at.lesson, at.framing);
  {
    HeadlessRenderer second(frame_width, frame_height);
    EXPECT_EQ(second.render(*at.lesson, at.framing).rgba, alone.rgba);
    EXPECT_EQ(renderer().render(*at.lesson, at.framing).rgba, alone.rgba);
  }
  EXPECT_EQ(renderer().render(*at.lesson, at.framing).rgba, alone.rgba);
}

}  // namespace
}  // namespace frictionlab::draw

namespace frictionlab::draw {
namespace {

// A chart's map cells land where their grid points are: a 2×2 map of two categories, read back
// from the picture at the middle of each quarter of the plot.
TEST(Charts, MapCellsAreDrawnWhereTheirGridPointsAre) {
  Chart chart;
  chart.title = "map";
  chart.log_x = chart.log_y = true;
  chart.categories = {{"low", IM_COL32(0, 200, 0, 255)}, {"high", IM_COL32(200, 0, 0, 255)}};
  chart.cells = {{1.0, 1.0, 0}, {10.0, 1.0, 0}, {1.0, 10.0, 1}, {10.0, 10.0, 1}};
  const Image image = render_charts({chart}, 1, 800, 600);
  // Down a column through the left cells (the middle one is their shared edge).
  int first_red = -1, last_green = -1;
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* p = image.pixel(image.width * 2 / 5, y);
    if (p[0] == 200 && p[1] == 0 && first_red < 0) first_red = y;
    if (p[0] == 0 && p[1] == 200) last_green = y;
  }
  ASSERT_GE(first_red, 0) << "no cell of the upper category";
  ASSERT_GT(last_green, first_red) << "the upper category is not above the lower one";
  // Both halves of the plot are about equally tall: cells span half-way to their neighbours.
  int red_rows = 0, green_rows = 0;
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* p = image.pixel(image.width * 2 / 5, y);
    red_rows += p[0] == 200 && p[1] == 0;
    green_rows += p[0] == 0 && p[1] == 200;
  }
  EXPECT_NEAR(red_rows, green_rows, 3);
}

}  // namespace
}  // namespace frictionlab::draw
