// The mouse's hand in the world and the view it zooms and pans (classroom/world_hand.h).
#define IMGUI_DEFINE_MATH_OPERATORS
#include "classroom/world_hand.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "draw/frame.h"
#include "draw/overlays.h"
#include "lessons/runtime/framing.h"

namespace frictionlab::classroom {

void WorldHand::forget() {
  held = false;
  view_adjust = {};
  held_view.reset();
  panning_from.reset();
}

namespace {

// What the status line says while the hand is stopped at the view's edge.
const std::string stopped_at_the_edge = "The hand stops at the edge of the view, to keep what it pulls in sight.";

// The pointer's place as the hand's target, moved in where the body it pulls would leave the view
// (`stopped` then): the view holds still while the hand pulls, and a drag on past the world's
// edge, over the panels, pulled push's block out of the picture (a teacher's projector trial,
// issue 31). The body reaches past the point held by its box's far corners, as far on the screen
// as it does now; a margin of 12 px times the text scale keeps it clear of the world panel's
// clipped edge (10 px in projector text).
ImVec2 kept_in_sight(ImVec2 pointer, const draw::Camera& camera, const Scene& scene, float scale, bool* stopped) {
  const b2Body* body = scene.grabbed();
  if (body == nullptr || scene.applied_forces().empty()) return pointer;
  const ImVec2 hook = camera.to_screen(body->GetWorldPoint(scene.applied_forces().back().local_point));
  const b2AABB box = lessons::body_box(body);
  const ImVec2 low = camera.to_screen(box.lowerBound), high = camera.to_screen(box.upperBound);
  const float margin = 12.0f * scale;
  const ImVec2 from(camera.origin.x + margin + (hook.x - low.x), camera.origin.y + margin + (hook.y - high.y));
  const ImVec2 to(camera.origin.x + camera.size.x - margin - (high.x - hook.x), camera.origin.y + camera.size.y - margin - (low.y - hook.y));
  ImVec2 kept = pointer;
  // On an axis where the body is wider than the view, there is no place to keep it whole: left be.
  if (from.x <= to.x) kept.x = std::clamp(pointer.x, from.x, to.x);
  if (from.y <= to.y) kept.y = std::clamp(pointer.y, from.y, to.y);
  *stopped = kept.x != pointer.x || kept.y != pointer.y;
  return kept;
}

// How far the body's box on the screen runs out of the view kept `margin` px inside its edges:
// px, rightwards and downwards (0 where it is inside; where it is wider than the view, by its
// left or top edge).
ImVec2 out_of_sight(const draw::Camera& camera, const b2Body* body, float margin) {
  const b2AABB box = lessons::body_box(body);
  const ImVec2 low = camera.to_screen(box.lowerBound), high = camera.to_screen(box.upperBound);  // screen y grows down
  const auto over = [](float near, float far, float from, float to) {
    if (near < from) return near - from;
    return far > to ? far - to : 0.0f;
  };
  return ImVec2(over(low.x, high.x, camera.origin.x + margin, camera.origin.x + camera.size.x - margin),
                over(high.y, low.y, camera.origin.y + margin, camera.origin.y + camera.size.y - margin));
}

}  // namespace

void WorldHand::hold_view(const classroom_state::Playback& playback, ImVec2 origin, ImVec2 size, float scale) {
  if (!held_view) return;
  if (!held || playback.lesson().scene().grabbed() == nullptr) {
    view_adjust.pan = held_view->pan;
    held_view.reset();
    return;
  }
  const std::vector<draw::Camera> lanes =
      draw::world_cameras(playback.lesson(), playback.framing(), size, scale, origin, view_adjust, projector);
  if (drag_lane >= lanes.size()) return;
  // The same world point under the same screen point: the mouse's place means what it meant.
  const b2Vec2 shift = held_view->centre - lanes[drag_lane].to_world(held_view->anchor);
  if (shift.IsValid()) view_adjust.pan += shift;
  // A body driven on past the hand stopped at the view's edge (push's own push grows while the
  // hand holds it there) would still leave the picture: the view follows it just enough to keep
  // it in sight, and holds still there.
  const b2Body* body = playback.lesson().scene().grabbed();
  const std::vector<draw::Camera> still =
      draw::world_cameras(playback.lesson(), playback.framing(), size, scale, origin, view_adjust, projector);
  const float ppm = still[drag_lane].pixels_per_metre;
  const ImVec2 out = out_of_sight(still[drag_lane], body, 12.0f * scale);
  if ((out.x != 0.0f || out.y != 0.0f) && ppm > 0.0f) {
    const b2Vec2 follow(out.x / ppm, -out.y / ppm);
    view_adjust.pan += follow;
    held_view->centre += follow;
  }
}


// The lane under the point: lanes stand in a column, or side by side in rows (draw::lane_grid).
const draw::Camera& WorldHand::camera_at(ImVec2 point) const {
  for (const draw::Camera& camera : cameras) {
    if (point.y >= camera.origin.y && point.y < camera.origin.y + camera.size.y && point.x >= camera.origin.x &&
        point.x < camera.origin.x + camera.size.x) {
      return camera;
    }
  }
  // Left or right of every lane (the world panel's edges): the nearest lane across, in that row.
  const draw::Camera* nearest = nullptr;
  float distance = 0.0f;
  for (const draw::Camera& camera : cameras) {
    if (point.y < camera.origin.y || point.y >= camera.origin.y + camera.size.y) continue;
    const float across = std::max({camera.origin.x - point.x, point.x - (camera.origin.x + camera.size.x), 0.0f});
    if (nearest == nullptr || across < distance) nearest = &camera, distance = across;
  }
  return nearest != nullptr ? *nearest : cameras.front();
}

void WorldHand::handle_mouse(classroom_state::Playback& playback, ImVec2 origin, ImVec2 size, float scale, std::string& status) {
  ImGuiContext& context = *ImGui::GetCurrentContext();
  const ImGuiIO& io = ImGui::GetIO();
  lessons::Lesson& lesson = playback.lesson();
  Scene& scene = lesson.scene();
  const draw::FrameLayout layout = draw::FrameLayout::of(size, scale, origin, projector, lesson);
  cameras = draw::world_cameras(lesson, playback.framing(), size, scale, origin, view_adjust, projector);
  // The lane a drag began in keeps it until the button is let go: each lane's camera sits on its
  // own body's height, so the same screen point is another world point in the next lane.
  const bool dragging = (held || panning_from) && drag_lane < cameras.size();
  const draw::Camera& camera = dragging ? cameras[drag_lane] : camera_at(io.MousePos);
  const ImRect world(layout.world_corner, layout.world_corner + layout.world_size);
  const ImRect inset(layout.inset_corner, layout.inset_corner + layout.inset_size);
  const bool over_world = context.HoveredWindow != nullptr && context.HoveredWindow == ImGui::FindWindowByName("###world") &&
                          world.Contains(io.MousePos) && !inset.Contains(io.MousePos);
  if (over_world && io.MouseWheel != 0.0f) {
    // Zoom about the point under the mouse: it stays where it is on the screen.
    const b2Vec2 under = camera.to_world(io.MousePos);
    view_adjust.zoom = std::clamp(view_adjust.zoom * std::pow(1.2f, io.MouseWheel), 0.1f, 20.0f);
    const std::vector<draw::Camera> zoomed = draw::world_cameras(lesson, playback.framing(), size, scale, origin, view_adjust, projector);
    const auto lane = static_cast<std::size_t>(&camera - cameras.data());
    const b2Vec2 shift = under - zoomed[lane].to_world(io.MousePos);
    if (shift.IsValid()) view_adjust.pan += shift;
  }
  // A double click on empty space (not on a body, which the first click took hold of).
  if (over_world && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !held) {
    view_adjust = {};
    panning_from.reset();
    return;
  }
  if (scene.grabbed() == nullptr && over_world && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    drag_lane = static_cast<std::size_t>(&camera - cameras.data());
    const b2Vec2 point = camera.to_world(io.MousePos);
    for (const auto& [name, body] : scene.bodies()) {
      if (body->GetType() != b2_dynamicBody || !draw::body_contains(body, point)) continue;
      playback.grab(name, body->GetLocalPoint(point), point);
      held = true;
      held_view = HeldView{camera.centre, camera.anchor, view_adjust.pan};
      if (!playback.playing()) status = "Holding " + name + ": press Space to play, and the hand pulls it.";
      break;
    }
    // Empty space: the drag pans the view, holding that point of the world under the mouse.
    if (!held) panning_from = point;
  }
  if (panning_from) {
    if (!io.MouseDown[ImGuiMouseButton_Left]) {
      panning_from.reset();
    } else {
      const b2Vec2 shift = *panning_from - camera.to_world(io.MousePos);
      if (shift.IsValid()) view_adjust.pan += shift;  // a view squeezed to nothing has no scale to pan by
    }
  }
  // A hand the record puts back (replaying a drag) is the record's: the mouse neither moves
  // nor lets go of it. A rebuild or a step back takes the user's hand away.
  if (scene.grabbed() == nullptr) held = false;
  if (held) {
    if (!io.MouseDown[ImGuiMouseButton_Left]) {
      playback.release();
      held = false;
      // "Holding block: press Space..." is over once the hand lets go, and so is the edge's stop.
      if (status.rfind("Holding ", 0) == 0 || status == stopped_at_the_edge) status.clear();
      return;
    }
    bool stopped = false;
    const b2Vec2 target = camera.to_world(kept_in_sight(io.MousePos, camera, scene, scale, &stopped));
    if (target.x != scene.grab_target().x || target.y != scene.grab_target().y) playback.move_grab(target);
    // "press Space to play" is done with once it plays.
    if (playback.playing() && status.rfind("Holding ", 0) == 0) status.clear();
    if (stopped) {
      status = stopped_at_the_edge;
    } else if (status == stopped_at_the_edge) {
      status.clear();
    }
  }
  // The hand is drawn as the force gauge it pulls through, with the world (world_tools).
}

}  // namespace frictionlab::classroom
