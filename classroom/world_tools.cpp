// The window's drawing in each lane of the world (classroom/world_tools.h).
#include "classroom/world_tools.h"

#include "classroom/force_gauge.h"

namespace frictionlab::classroom {

void WorldTools::operator()(draw::WorldToolsPass pass, ImDrawList* draw, const draw::Camera& camera, std::size_t lane,
                            float newtons_to_pixels, draw::LabelPlacer& labels) const {
  const lessons::Lesson& lesson = playback.lesson();
  const Scene& scene = lesson.scene();
  // The gauge in the lane its body is drawn in: the one whose strip holds the point held.
  bool gauge_here = false;
  if (const b2Body* held = scene.grabbed()) {
    const ImVec2 at = camera.to_screen(held->GetWorldCenter());
    gauge_here = (at.y >= camera.origin.y && at.y <= camera.origin.y + camera.size.y) || lane == hand.drag_lane;
  }
  if (gauge_here && pass == draw::WorldToolsPass::avoid) avoid_gauge(scene, camera, fonts.scale, labels);
  tools.in_world(pass, draw, lesson, camera, lane, newtons_to_pixels, colours, fonts, labels);
  if (gauge_here && pass == draw::WorldToolsPass::draw) draw_gauge(draw, scene, camera, colours, fonts, labels);
}

}  // namespace frictionlab::classroom
