// The mouse's hand in the world and the view it zooms and pans (classroom/world_hand.h).
#define IMGUI_DEFINE_MATH_OPERATORS
#include "classroom/world_hand.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

#include "draw/frame.h"

namespace frictionlab::classroom {

void WorldHand::forget() {
  held = false;
  view_adjust = {};
  held_view.reset();
  panning_from.reset();
}

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
}

const draw::Camera& WorldHand::camera_at(ImVec2 point) const {
  for (const draw::Camera& camera : cameras) {
    if (point.y >= camera.origin.y && point.y < camera.origin.y + camera.size.y) return camera;
  }
  return cameras.front();
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
      if (body->GetType() != b2_dynamicBody) continue;
      for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext()) {
        if (fixture->TestPoint(point)) {
          playback.grab(name, body->GetLocalPoint(point), point);
          held = true;
          held_view = HeldView{camera.centre, camera.anchor, view_adjust.pan};
          if (!playback.playing()) status = "Holding " + name + ": press Space to play, and the hand pulls it.";
          break;
        }
      }
      if (held) break;
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
      // "Holding block: press Space..." is over once the hand lets go.
      if (status.rfind("Holding ", 0) == 0) status.clear();
      return;
    }
    const b2Vec2 target = camera.to_world(io.MousePos);
    if (target.x != scene.grab_target().x || target.y != scene.grab_target().y) playback.move_grab(target);
    // "press Space to play" is done with once it plays.
    if (playback.playing() && status.rfind("Holding ", 0) == 0) status.clear();
  }
  // The hand is drawn as the force gauge it pulls through, with the world (world_tools).
}

}  // namespace frictionlab::classroom
