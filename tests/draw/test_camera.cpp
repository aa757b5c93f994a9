// The view: what a lesson's view{} asks the camera to show (follow a body, a window in metres,
// lanes), and that every built-in lesson's moving bodies are in the picture and big enough to
// read at the sizes a classroom uses.
#include <gtest/gtest.h>
#include <imgui_internal.h>

#include <algorithm>
#include <string>
#include <vector>

#include "draw/frame.h"
#include "draw/theme.h"
#include "lessons/runtime/catalog.h"
#include "tests/lesson_scripts.h"
#include "tests/rendering.h"

namespace frictionlab::draw {
namespace {

// Two blocks sliding apart on two floors 3 m apart, and a view{} line to try.
std::string two_blocks(const std::string& view) {
  return lessons::with_heading(R"(
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { "floor", material = "wood" }
local upper = ground { "upper", material = "wood", y = 3, thickness = 0.2 }
local slow = box { "slow", material = "wood", width = 0.3, height = 0.1, on = floor, at = 0, mass = 1, velocity = { 1, 0 } }
local fast = box { "fast", material = "wood", width = 0.3, height = 0.1, on = upper, at = 0, mass = 1, velocity = { 3, 0 } }
)" + view + "\n");
}

const ImVec2 display(1280.0f, 720.0f);

std::vector<Camera> cameras_of(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 size = display,
                               float scale = 1.0f, const ViewAdjust& adjust = {}) {
  return world_cameras(lesson, framing, size, scale, ImVec2(0.0f, 0.0f), adjust);
}

bool inside(const Camera& camera, ImVec2 point) {
  return point.x >= camera.origin.x && point.x <= camera.origin.x + camera.size.x && point.y >= camera.origin.y &&
         point.y <= camera.origin.y + camera.size.y;
}

TEST(View, FollowKeepsTheBodyAtTheSamePlaceOnTheScreen) {
  lessons::ScriptFile script(two_blocks(R"(view { follow = fast, width = 2 })"));
  lessons::Lesson lesson(script.path());
  const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
  const ImVec2 before = cameras_of(lesson, framing).front().to_screen(lesson.scene().body("fast")->GetWorldCenter());
  lesson.step_to(0.5);
  const b2Body* fast = lesson.scene().body("fast");
  ASSERT_GT(fast->GetWorldCenter().x, 1.0f);  // it has moved a metre and more
  const Camera camera = cameras_of(lesson, framing).front();
  const ImVec2 after = camera.to_screen(fast->GetWorldCenter());
  EXPECT_NEAR(after.x, before.x, 1e-3);
  EXPECT_NEAR(after.y, before.y, 1e-3);
  // 2 m across the part of the view the free-body diagram leaves free.
  const FrameLayout layout = FrameLayout::of(display, 1.0f);
  EXPECT_NEAR(camera.pixels_per_metre * 2.0f, layout.world_size.x - layout.inset_size.x, 1e-2);
}

// A view of the whole lesson does not follow what moves: following kept spring_pull's block
// still on the screen, and only the floor's hatching showed that it moved (a teacher's projector
// trial). It stands still while the block slides less than half a page, and then moves by whole
// pages, the block in view all the while.
TEST(View, AWholeLessonsViewStandsStillWhileTheBlockSlidesAcrossIt) {
  lessons::ScriptFile script(lessons::with_heading(R"(
pair { "wood", "wood", mu_s = 0.3, mu_k = 0.2 }
local floor = ground { "floor", material = "wood" }
local block = box { "block", material = "wood", width = 0.3, height = 0.1, on = floor, at = 0, mass = 1, velocity = { 2, 0 } }
)"));
  lessons::Lesson lesson(script.path());
  const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
  const Camera first = cameras_of(lesson, framing).front();
  const b2Body* block = lesson.scene().body("block");
  const float start = block->GetWorldCenter().x;
  // Three steps: about 3 cm, a tenth of the block, well under half a page of the 0.3 m block's
  // view (a page is the view's width less the 1/1.45 of it the lesson fills: 13 cm).
  lesson.step_to(3.0 / 240.0);
  ASSERT_GT(block->GetWorldCenter().x - start, 0.02f);
  const Camera early = cameras_of(lesson, framing).front();
  EXPECT_FLOAT_EQ(early.centre.x, first.centre.x) << "the view followed the block";
  EXPECT_NEAR(early.to_screen(block->GetWorldCenter()).x - first.to_screen(b2Vec2(start, 0.0f)).x,
              (block->GetWorldCenter().x - start) * first.pixels_per_metre, 1e-2);
  // It slides about 1 m (v²/(2·μk·g)) before it stops: several pages, in view at every step.
  int pages_turned = 0;
  float centre = first.centre.x;
  for (int step = 4; step <= 240; ++step) {
    lesson.step_to(step / 240.0);
    const Camera camera = cameras_of(lesson, framing).front();
    EXPECT_TRUE(inside(camera, camera.to_screen(block->GetWorldCenter()))) << "at step " << step;
    if (camera.centre.x != centre) ++pages_turned, centre = camera.centre.x;
  }
  EXPECT_GE(pages_turned, 3);
  EXPECT_GT(block->GetWorldCenter().x - start, 0.9f);
}

TEST(View, AWindowShowsItsCornersAndFillsOneSide) {
  lessons::ScriptFile script(two_blocks(R"(view { window = { -1, -0.5, 5, 3.5 } })"));
  lessons::Lesson lesson(script.path());
  const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
  lesson.step_to(0.5);  // a fixed window does not follow
  const Camera camera = cameras_of(lesson, framing).front();
  const FrameLayout layout = FrameLayout::of(display, 1.0f);
  const float free_width = layout.world_size.x - layout.inset_size.x;
  const ImVec2 low = camera.to_screen({-1.0f, -0.5f}), high = camera.to_screen({5.0f, 3.5f});
  EXPECT_TRUE(inside(camera, low) && inside(camera, high));
  EXPECT_LE(high.x - low.x, free_width + 1e-2f);
  // It fills the free width or the height, whichever is tighter; or, where a moving body's
  // normal force (the longest arrow drawn, up from its foot) would leave the window's top, it
  // grows until that arrow's tip is at the view's top (less the lane's edge, 6 px at text scale 1)
  // with the window's foot in view: "fast" stands on the upper floor, 0.5 m under the window's top.
  const bool fills = std::abs((high.x - low.x) - free_width) < 0.5f || std::abs((low.y - high.y) - camera.size.y) < 0.5f;
  const float arrow = longest_arrow_pixels(lesson, framing, display, 1.0f);
  const float fast_foot = lessons::body_box(lesson.scene().body("fast")).lowerBound.y;
  const float tip = camera.to_screen({0.0f, fast_foot}).y - arrow;
  const bool grew = std::abs(tip - (camera.origin.y + 6.0f)) < 0.5f && low.y <= camera.origin.y + camera.size.y - 6.0f + 0.5f;
  EXPECT_TRUE(fills || grew) << "the window spans " << high.x - low.x << " × " << low.y - high.y << " px, the arrow's tip at "
                             << tip << " px";
}

TEST(View, LanesStackAStripPerBodyOnOneScaleAndOneStretchOfFloor) {
  lessons::ScriptFile script(two_blocks(R"(view { lanes = { fast, slow } })"));
  lessons::Lesson lesson(script.path());
  const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
  lesson.step_to(0.3);
  const std::vector<Camera> cameras = cameras_of(lesson, framing);
  ASSERT_EQ(cameras.size(), 2u);
  const FrameLayout layout = FrameLayout::of(display, 1.0f);
  // Top first, in the order given, covering the world view between them.
  EXPECT_FLOAT_EQ(cameras[0].origin.y, layout.world_corner.y);
  EXPECT_FLOAT_EQ(cameras[1].origin.y, cameras[0].origin.y + cameras[0].size.y);
  EXPECT_NEAR(cameras[1].origin.y + cameras[1].size.y, layout.world_corner.y + layout.world_size.y, 1e-3);
  EXPECT_TRUE(inside(cameras[0], cameras[0].to_screen(lesson.scene().body("fast")->GetWorldCenter())));
  EXPECT_TRUE(inside(cameras[1], cameras[1].to_screen(lesson.scene().body("slow")->GetWorldCenter())));
  // One scale and one horizontal window: a metre along the floor is the same in both lanes.
  EXPECT_EQ(cameras[0].pixels_per_metre, cameras[1].pixels_per_metre);
  EXPECT_EQ(cameras[0].to_screen({1.0f, 0.0f}).x, cameras[1].to_screen({1.0f, 0.0f}).x);
  // The arrows scale to a lane: the heaviest weight is at most 0.4 of a lane's height.
  const float per_newton = arrow_scale(lesson, framing, display, 1.0f);
  EXPECT_LE(per_newton * 9.81f, 0.4f * cameras[0].size.y + 1e-3f);
}

// A box thrown from 0.8 m over its floor, in a lane beside one resting on the upper floor: the
// floor the box will land on is in its lane from t = 0, and the box with it, all through the
// fall (the thrown box fell towards a floor out of sight until it landed); the lane stays
// still while the box falls, then follows it. The resting box is framed on itself, as it was.
TEST(View, ALaneKeepsTheFloorUnderABodyInTheAir) {
  lessons::ScriptFile script(lessons::with_heading(R"(
pair { "wood", "wood", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { "floor", material = "wood" }
local upper = ground { "upper", material = "wood", y = 3, thickness = 0.2 }
local thrown = box { "thrown", material = "wood", width = 0.4, height = 0.3, x = 0, y = 0.8, mass = 2, velocity = { 2, 0 } }
local resting = box { "resting", material = "wood", width = 0.4, height = 0.3, on = upper, at = 0, mass = 2 }
view { lanes = { thrown, resting } }
)"));
  for (const auto& [size, scale] : {std::pair{display, 1.0f}, std::pair{ImVec2(1920.0f, 1080.0f), 1.35f}}) {
    lessons::Lesson lesson(script.path());
    const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
    const b2Body* thrown = lesson.scene().body("thrown");
    float lane_still = 0.0f;
    for (const double t : {0.0, 0.15, 0.3}) {
      lesson.step_to(t);
      const std::vector<Camera> cameras = world_cameras(lesson, framing, size, scale);
      ASSERT_EQ(cameras.size(), 2u);
      const Camera& lane = cameras[0];
      const float floor_y = lane.to_screen({0.0f, 0.0f}).y;
      EXPECT_LT(floor_y, lane.origin.y + lane.size.y) << "the floor is in the lane at t = " << t;
      EXPECT_GT(lane.to_screen(thrown->GetWorldPoint({0.0f, 0.15f})).y, lane.origin.y) << "and the box's top, t = " << t;
      if (t == 0.0) lane_still = floor_y;
      if (t == 0.15) {
        EXPECT_FLOAT_EQ(floor_y, lane_still) << "the lane stays still while the box falls";
      }
      EXPECT_GE(0.4f * lane.pixels_per_metre, min_body_pixels * scale - 1e-3f) << "readable";
      // The resting box's lane is on the box's own height, as every resting lane is.
      EXPECT_FLOAT_EQ(cameras[1].centre.y, lesson.scene().body("resting")->GetWorldCenter().y);
    }
  }
}

TEST(View, TheWheelZoomAndTheDragPanComeOnTopOfTheLessonsView) {
  lessons::ScriptFile script(two_blocks(R"(view { follow = slow })"));
  lessons::Lesson lesson(script.path());
  const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
  const Camera plain = cameras_of(lesson, framing).front();
  ViewAdjust adjust;
  adjust.zoom = 2.0f;
  adjust.pan = b2Vec2{0.5f, -0.25f};
  const Camera moved = cameras_of(lesson, framing, display, 1.0f, adjust).front();
  EXPECT_FLOAT_EQ(moved.pixels_per_metre, 2.0f * plain.pixels_per_metre);
  EXPECT_FLOAT_EQ(moved.centre.x, plain.centre.x + 0.5f);
  EXPECT_FLOAT_EQ(moved.centre.y, plain.centre.y - 0.25f);
}

TEST(View, ABodyTheViewNamesThatAReloadRemovedFallsBackToTheWholeLesson) {
  lessons::ScriptFile script(two_blocks(R"(view { follow = fast })"));
  lessons::Lesson lesson(script.path());
  lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
  framing.view.bodies = {"gone"};
  const std::vector<Camera> cameras = cameras_of(lesson, framing);
  ASSERT_EQ(cameras.size(), 1u);
  EXPECT_GT(cameras.front().pixels_per_metre, 0.0f);
}

// Every built-in lesson at each of its moments, at the sizes a classroom uses: each moving
// body is in the picture (in its own lane, out from under the free-body diagram) and its
// longer side is at least min_body_pixels × the text scale.
struct Screen {
  const char* name;
  ImVec2 size;
  float scale;
};
const Screen screens[] = {{"1280x720", {1280.0f, 720.0f}, 1.0f},
                          {"1024x768", {1024.0f, 768.0f}, frame_scale(1024, 768)},
                          {"projector_1920x1080", {1920.0f, 1080.0f}, 1.5f * 1.35f},
                          // The window in projector mode on a 1920 × 1080 screen: its menu bar and
                          // transport bar (about 136 px at this text size) leave the frame this.
                          {"window_projector_1920x1080", {1920.0f, 944.0f}, 1.5f * 1.35f}};

void check_bodies_shown(const LessonAt& at, const std::string& what) {
  const lessons::View& view = at.lesson->view();
  for (const Screen& screen : screens) {
    const std::string where = what + ", " + screen.name;
    const std::vector<Camera> cameras = cameras_of(*at.lesson, at.framing, screen.size, screen.scale);
    const FrameLayout layout = FrameLayout::of(screen.size, screen.scale);
    const ImRect inset(layout.inset_corner, ImVec2(layout.inset_corner.x + layout.inset_size.x,
                                                   layout.inset_corner.y + layout.inset_size.y));
    for (const auto& [name, body] : at.scene().bodies()) {
      if (body->GetType() != b2_dynamicBody) continue;
      std::size_t lane = 0;
      if (view.kind == lessons::View::Kind::lanes) {
        lane = static_cast<std::size_t>(std::find(view.bodies.begin(), view.bodies.end(), name) - view.bodies.begin());
        if (lane == view.bodies.size()) continue;  // not a lane's body
      }
      const Camera& camera = cameras[lane];
      const ImVec2 centre = camera.to_screen(body->GetWorldCenter());
      EXPECT_TRUE(inside(camera, centre)) << where << ": " << name << " is out of the picture";
      EXPECT_FALSE(inset.Contains(centre)) << where << ": " << name << " is under the free-body diagram";
      const b2AABB box = lessons::body_box(body);
      const float longer = std::max(box.upperBound.x - box.lowerBound.x, box.upperBound.y - box.lowerBound.y);
      // A window the lesson fixed is exempt (framing_cameras): it shows what the script asked
      // for and grows to hold its arrows (pulley's 0.2 m hanging weight, 74 to 94 px with
      // projector text, where its block's normal force needs the room above the table).
      if (view.kind == lessons::View::Kind::window) continue;
      EXPECT_GE(longer * camera.pixels_per_metre, min_body_pixels * screen.scale - 0.5f)
          << where << ": " << name << " is drawn " << longer * camera.pixels_per_metre << " px long";
    }
  }
}

TEST(View, EveryLessonsMovingBodiesAreInThePictureAndReadableAtItsMoments) {
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    for (const lessons::Moment& moment : entry.moments) {
      LessonAt at(entry.name, moment.set, moment.at);
      check_bodies_shown(at, entry.name + " at " + moment.name);
    }
  }
}

// And all through a run at its defaults, not only at the moments its author chose.
TEST(View, EveryLessonsMovingBodiesStayInThePictureAllThroughARun) {
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    LessonAt at(entry.name, {}, 0.0);
    const double duration = at.lesson->duration();
    for (int k = 0; k <= 4; ++k) {
      const double t = duration * k / 4.0;
      at.step_to(t);
      check_bodies_shown(at, entry.name + " at t = " + std::to_string(t) + " s");
    }
  }
}

}  // namespace
}  // namespace frictionlab::draw
