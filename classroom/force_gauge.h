// The force gauge: the mouse's hand pulls a body through a spring scale (the scene's grab,
// physics/scene.h). Its reading is recorded frame by frame against the lesson's time, drawn in
// the world as a spring scale with its reading in newtons, and plotted, so the classic lab works
// by hand: pull slowly, the peak is static friction (mu_s·m·g), the plateau while it slides is
// kinetic friction (mu_k·m·g). The stretches of the run the hand pulled are what the theory
// table marks "hand-pulled": the lesson's predictions know nothing of the hand.
//
// A lesson may pull the held body too (push's push, spring_pull's spring). Then the gauge alone
// is not what friction answers: its peak and plateau are taken from the pull along the surface
// of the hand and the lesson together (while the body sticks, friction answers exactly that),
// and they say so ("hand + spring"). The scale drawn reads the hand's own pull.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include "classroom_state/gauge_record.h"
#include "draw/camera.h"
#include "draw/chart.h"
#include "draw/drawing.h"
#include "draw/theme.h"
#include "physics/scene.h"

namespace frictionlab::classroom {

// Where the gauge lies on the screen: its hook on the body, the hand's end of the coil (where the
// scale's spring ends), the case from `case_start` to the ring, and the ring the hand holds,
// centred on the pointer (the hand's target). The case is as long as the room between hook and
// ring allows, up to its full length; with no room it is not drawn.
struct GaugeShape {
  ImVec2 hook, hand, case_start, ring, along;
  float half_width, ring_radius;
};
GaugeShape gauge_shape(const Scene& scene, const draw::Camera& camera, float scale);

// The gauge in the world, between the point the hand holds and the pointer: its coil and case
// given to the label placer first (before any label is placed), then drawn with its reading.
// Nothing when no body is held.
void avoid_gauge(const Scene& scene, const draw::Camera& camera, float scale, draw::LabelPlacer& labels);
void draw_gauge(ImDrawList* draw, const Scene& scene, const draw::Camera& camera, const draw::Theme& theme, const draw::Fonts& fonts,
                draw::LabelPlacer& labels);

// The gauge's reading against time over the latest stretch the hand pulled (from a little
// before it took hold), the slips shaded; the hand's and the lesson's pull together instead when
// the lesson pulled the body too, as the figures are taken. `steady`: laid out as a projector's
// lesson plots are (draw::Chart::steady), on a page of its own.
draw::Chart gauge_chart(const classroom_state::GaugeRecord& record, double frame_step, const draw::Theme& theme,
                        bool steady = false);

// The plot's title: "Force gauge (N)", or "Hand + spring (N)" when the lesson pulled the body too.
std::string gauge_plot_title(const classroom_state::GaugeRecord& record, double frame_step);
// The figures over the plot: "peak 39.4 N,  sliding 29.1 N", or "hand + spring: peak ..." when
// the lesson pulled the body too; "" before the hand pulls.
std::string gauge_figures(const classroom_state::GaugeRecord& record, double frame_step);
// The plot under the world at `corner`, `size`: the latest stretch's figures over its chart, as a
// class reads them off a sensor's screen; `steady` on a projector, as gauge_chart says.
draw::ChartLayout draw_gauge_plot(ImVec2 corner, ImVec2 size, const classroom_state::GaugeRecord& record, double frame_step,
                                  const draw::Theme& theme, const draw::Fonts& fonts, bool steady = false);

}  // namespace frictionlab::classroom
