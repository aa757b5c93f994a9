// The classroom's measuring tools and force gauge in the world's lanes (the Tools menu is the
// measuring tools' own, classroom/measuring_tools.h; the gauge's plot and figures force_gauge.h's).
#include <cstdio>

#include "classroom/classroom.h"
#include "classroom/force_gauge.h"
#include "draw/overlays.h"
#include "draw/panels.h"
#include "draw/text_record.h"

namespace frictionlab::classroom {

void Classroom::world_tools(draw::WorldToolsPass pass, ImDrawList* draw, const draw::Camera& camera, std::size_t lane,
                            float newtons_to_pixels, draw::LabelPlacer& labels) {
  const lessons::Lesson& lesson = playback_->lesson();
  const Scene& scene = lesson.scene();
  const float s = fonts_->scale;
  // The gauge in the lane its body is drawn in: the one whose strip holds the point held.
  bool gauge_here = false;
  if (const b2Body* held = scene.grabbed()) {
    const ImVec2 at = camera.to_screen(held->GetWorldCenter());
    gauge_here = (at.y >= camera.origin.y && at.y <= camera.origin.y + camera.size.y) || lane == hand_.drag_lane;
  }
  if (gauge_here && pass == draw::WorldToolsPass::avoid) avoid_gauge(scene, camera, s, labels);
  const draw::Theme& colours = theme(window_.theme);
  tools_.in_world(pass, draw, lesson, camera, lane, newtons_to_pixels, colours, *fonts_, labels);
  if (gauge_here && pass == draw::WorldToolsPass::draw) draw_gauge(draw, scene, camera, colours, *fonts_, labels);
}

std::string Classroom::gauge_figures() const {
  return classroom::gauge_figures(playback_->gauge(), playback_->lesson().scene().frame_step());
}

}  // namespace frictionlab::classroom
