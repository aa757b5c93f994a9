// The world view under the mouse: a body dragged by the hand, the wheel's zoom and a drag's pan,
// a drag kept in the lane it began in.
#include <gtest/gtest.h>

#include <cmath>

#include "classroom/classroom.h"
#include "draw/headless.h"
#include "draw/imgui_host.h"
#include "lessons/runtime/catalog.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

TEST(WorldHand, TheMouseDragsABodyAndTheFrictionArrowAnswers) {
  ClassroomHands hands("spring_pull");
  hands.frame();  // it opens paused: take hold
  lessons::Lesson& lesson = hands.lesson();
  b2Body* block = lesson.scene().body("block");
  const ImVec2 held = hands.classroom().world_camera().to_screen(block->GetPosition());
  hands.mouse_at(held);
  hands.button(true);
  ASSERT_EQ(lesson.scene().grabbed(), block);
  hands.key(Key::space);  // play while holding
  const float start = block->GetPosition().x;
  // Drag it on along the bench, away from the view's left edge (65 px from the block: dragged
  // back that way, the hand stops at the edge to keep the block in sight,
  // ForceGauge.TheBodyTheHandPullsStaysInSight): it slides, and kinetic friction
  // (mu_k·m·g = 0.35 × 1 kg × 9.81 = 3.43 N, the hand pulling level) points the other way.
  // A second of it: the hand pulls through the force gauge's spring, which takes a few tenths
  // of a second to stretch to the breakaway pull.
  double friction_sliding = 0.0;
  for (int i = 1; i <= 60; ++i) {
    ImGui::GetIO().MousePos = ImVec2(held.x + 3.0f * static_cast<float>(i), held.y);
    hands.frame(1.0 / 60.0);
    if (block->GetLinearVelocity().x > 0.05f) {
      friction_sliding = 0.0;
      for (const ForceOnBody& force : forces_on(lesson.scene(), block)) {
        if (force.kind == ForceKind::friction) friction_sliding += force.force.x;
      }
    }
  }
  EXPECT_GT(block->GetPosition().x - start, 0.05f);
  EXPECT_NEAR(friction_sliding, -0.35 * 9.81, 0.05 * 0.35 * 9.81);
  hands.button(false);
  EXPECT_EQ(lesson.scene().grabbed(), nullptr);
  EXPECT_EQ(hands.classroom().status().rfind("Holding", 0), std::string::npos) << "the hand's message outlived the hand";
  // The hand's work is in the books: the residual stays small beside it.
  EXPECT_LT(std::abs(lesson.scene().ledger().residual()), 0.02 * std::abs(lesson.scene().ledger().work_applied) + 1e-3);
}

// The wheel zooms about the point under the mouse, a drag on empty space pans the view with the
// mouse, and a double click puts the lesson's own view back; the lesson does not notice.
TEST(WorldHand, TheWheelZoomsAndADragOnEmptySpacePans) {
  ClassroomHands hands("spring_pull");
  hands.frame();  // paused: the view moves only because of the mouse
  const draw::FrameLayout layout = draw::FrameLayout::of(ImVec2(1280.0f, 720.0f), hands.classroom().ui_scale(ImVec2(1280.0f, 720.0f)),
                                             ImVec2(0.0f, ImGui::GetFrameHeight()));
  // Empty sky, high in the world view and left of the free-body diagram.
  const ImVec2 sky(layout.world_corner.x + 60.0f, layout.world_corner.y + 40.0f);
  hands.mouse_at(sky);
  const draw::Camera before = hands.classroom().world_camera();
  const b2Vec2 under = before.to_world(sky);
  ImGui::GetIO().MouseWheel = 2.0f;
  hands.frame();
  ImGui::GetIO().MouseWheel = 0.0f;
  hands.frame();
  const draw::Camera zoomed = hands.classroom().world_camera();
  EXPECT_NEAR(zoomed.pixels_per_metre, before.pixels_per_metre * 1.44f, 1e-3f * before.pixels_per_metre);
  const b2Vec2 still_under = zoomed.to_world(sky);
  EXPECT_NEAR(still_under.x, under.x, 1e-4);
  EXPECT_NEAR(still_under.y, under.y, 1e-4);

  // Drag 100 px right and 30 px down from empty space: the world moves with the mouse.
  hands.button(true);
  EXPECT_EQ(hands.lesson().scene().grabbed(), nullptr);  // nothing was taken hold of
  ImGui::GetIO().MousePos = ImVec2(sky.x + 100.0f, sky.y + 30.0f);
  hands.frame();
  hands.button(false);
  const draw::Camera panned = hands.classroom().world_camera();
  const ImVec2 moved = panned.to_screen(under);
  EXPECT_NEAR(moved.x, sky.x + 100.0f, 0.5f);
  EXPECT_NEAR(moved.y, sky.y + 30.0f, 0.5f);
  EXPECT_EQ(hands.lesson().scene().time(), 0.0);

  // A double click on empty space: the lesson's own view again.
  ImGui::GetIO().MousePos = sky;
  hands.frame();
  for (int i = 0; i < 2; ++i) {
    hands.button(true);
    hands.button(false);
  }
  EXPECT_EQ(hands.classroom().view_adjust(), draw::ViewAdjust{});
  EXPECT_FLOAT_EQ(hands.classroom().world_camera().pixels_per_metre, before.pixels_per_metre);
}

// With lanes, a drag stays in the lane it began in: each lane's camera sits on its own body's
// height, so the next lane's camera would put the hand metres away (terrain's lanes are 4 m apart).
// The mouse's x is the hand's; past the lane's lower edge the hand stops inside it, with the box
// it holds in sight (ForceGauge.TheBodyTheHandPullsStaysInSight), and the status line says so.
TEST(WorldHand, AHandDraggedAcrossALaneBoundaryStaysInItsLane) {
  ClassroomHands hands("terrain");
  hands.frame();
  const draw::Camera lane = hands.classroom().world_camera();  // the first lane's, asphalt_box's
  const b2Body* box = hands.lesson().scene().body("asphalt_box");
  const ImVec2 held = lane.to_screen(box->GetWorldCenter());
  hands.mouse_at(held);
  hands.button(true);
  ASSERT_EQ(hands.lesson().scene().grabbed(), box);
  // 5 px into the lane below (whole pixels: ImGui rounds the mouse's position down).
  const ImVec2 below(std::floor(held.x), std::floor(lane.origin.y + lane.size.y) + 5.0f);
  ImGui::GetIO().MousePos = below;
  hands.frame();
  const b2Vec2 target = hands.lesson().scene().grab_target();
  const b2Vec2 meant = lane.to_world(below);
  EXPECT_NEAR(target.x, meant.x, 1e-3);
  const float target_y = lane.to_screen(target).y;
  EXPECT_GT(target_y, lane.origin.y);
  EXPECT_LT(target_y, lane.origin.y + lane.size.y);
  EXPECT_LT(std::abs(target.y - box->GetWorldCenter().y), 1.0f);
  EXPECT_NE(hands.classroom().status().find("edge of the view"), std::string::npos) << hands.classroom().status();
  hands.button(false);
}

}  // namespace
}  // namespace frictionlab::classroom
