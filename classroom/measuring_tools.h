// The measuring tools a teacher switches on from the Tools menu: a stopwatch in lesson time,
// distance marks along the surface the main body stands on (a floor, or along an incline), the
// main body's speed, and the weight's components along and across a slope (m·g·sin θ and
// m·g·cos θ, as PhET draws them). Each reads the running lesson; they are drawn into the world
// view through its label placer, so their labels keep off the lesson's own labels and arrows.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include "classroom/control_places.h"
#include "classroom/distance_marks.h"
#include "classroom/settings.h"
#include "classroom/stopwatch.h"
#include "draw/camera.h"
#include "draw/drawing.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"
#include "physics/scene_forces.h"

namespace frictionlab::classroom {

// The body the tools measure: the one the view follows, else the lesson's first moving body
// (the free-body diagram's). Null when nothing moves.
const b2Body* measured_body(const lessons::Lesson& lesson);

// What the speed tool shows beside a body: its centre of mass's speed, "v = 1.250 m/s", below
// 0.1 m/s in mm/s to three figures ("v = 92.0 mm/s", "v = 0.464 mm/s"), and "v = 0 m/s" at rest.
std::string speed_reading(const b2Body* body);
// The same saying whose speed it is when the lesson has several moving bodies (lanes, a
// stack): "hack box: v = 0.420 m/s", the body named in the class's words.
std::string speed_text(const Scene& scene, const b2Body* body);

// The weight of a body on a slope split along and across it: m·g·sin θ downhill and m·g·cos θ
// into the slope. None on a level surface (θ under half a degree) or off any fixed surface.
struct SlopeWeight {
  double angle = 0.0;   // rad
  double along = 0.0;   // N, m·g·sin θ
  double across = 0.0;  // N, m·g·cos θ
  b2Vec2 downhill{0.0f, 0.0f}, into{0.0f, 0.0f};  // unit vectors
};
std::optional<SlopeWeight> slope_weight(const Scene& scene, const b2Body* body);

// The tools in one lane of the world view. avoid() tells the placer what they draw before any
// label is placed; draw() draws them and places their labels. The body's tools go in the lane
// whose strip holds it. The stopwatch is not in the world: it reads the lesson's one clock,
// whatever the lanes, and is drawn over the title beside that clock (draw_stopwatch_strip).
class MeasuringTools {
 public:
  ToolSettings on;  // the window's, copied in each frame
  Stopwatch stopwatch;

  // Each frame before drawing: where distances count from (the main body's centre of mass
  // at t = 0, taken whenever the lesson is at t = 0), the stopwatch taken back with the lesson's
  // time, and a stopwatch shown but never used armed while the lesson is paused (Play starts it).
  // `run_ended`: paused where the lesson's run ended by itself (Playback::at_run_end).
  void follow(const lessons::Lesson& lesson, bool playing, bool run_ended = false);
  // The stopwatch shown (on.stopwatch) while the lesson is paused, and never used since its last
  // reset: armed at `now`, so that Play starts it.
  void arm_stopwatch(double now, bool playing);
  // The Tools menu, in the menu bar being drawn: which tools are on (`shown`, the window's
  // settings, kept between runs) and the stopwatch's keys, at lesson time `now`.
  void draw_menu(ToolSettings& shown, double now, bool playing, ControlPlaces& controls);
  // `lane`: the lane's number, which with lanes named by their bodies says whose tools it shows.
  void avoid(const lessons::Lesson& lesson, const draw::Camera& camera, std::size_t lane, float newtons_to_pixels, float scale,
             draw::LabelPlacer& labels) const;
  // Its part in each pass of a lane's drawing (WorldToolsPass): avoid(), then
  // place_fixed_labels(); the last pass has nothing of theirs.
  void in_world(draw::WorldToolsPass pass, ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera,
                std::size_t lane, float newtons_to_pixels, const draw::Theme& theme, const draw::Fonts& fonts, draw::LabelPlacer& labels) const;
  // The distance marks, when on, and the measured body is in this lane (none otherwise). With
  // `labels`, the placer as the marks find it when drawn: their side is chosen where the view
  // has room for their numbers (every tick numbered; number_marks chooses which).
  std::optional<DistanceMarks> distance_marks(const lessons::Lesson& lesson, const draw::Camera& camera, const draw::Fonts& fonts,
                                              const draw::LabelPlacer* labels = nullptr, std::size_t lane = 0) const;
  // The speed (above the body), there or in the nearest place free of what the placer knows,
  // or left out when none is near; called before the lesson's labels are placed
  // (WorldToolsPass::fixed_labels), which keep off it. With `preferred` (the placer with the
  // distance marks' numbers taken), only a place free there. Whether it was drawn (or is not
  // to be: off, or in another lane).
  bool draw_readings(ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera, std::size_t lane,
                     const draw::Theme& theme, const draw::Fonts& fonts, draw::LabelPlacer& labels,
                     const draw::LabelPlacer* preferred = nullptr) const;
  std::optional<b2Vec2> distance_origin() const { return origin_; }
  // The stopwatch's line as the lesson was when last followed (playing, paused, at the run's
  // end); "" while it is not shown (on.stopwatch off).
  std::string stopwatch_line(double now, std::size_t laps = 3) const {
    return on.stopwatch ? stopwatch.line(now, playing_, run_ended_, laps) : std::string();
  }
  // That line on a strip of its own over the title and its clock, right-aligned: the strip's
  // height in the current font when `shown` (the window's setting, which the Tools menu may have
  // changed since `on` was copied; 0 when not shown), and the strip.
  static float stopwatch_strip_height(bool shown, float scale);
  void draw_stopwatch_strip(ImVec2 corner, ImVec2 size, double now, const draw::Fonts& fonts) const;

 private:
  // The fixed_labels pass: the distance marks' lines, the weight's components, the speed and then
  // the marks' numbers, all placed before the lesson's force values, which keep off them.
  void place_fixed_labels(ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera, std::size_t lane,
                          float newtons_to_pixels, const draw::Theme& theme, const draw::Fonts& fonts,
                          draw::LabelPlacer& labels) const;
  // The weight's components on a slope (on.weight_components): their arrows drawn, each value
  // beside its own arrow as a force's is (draw::place_force_label), told to the placer as forces'
  // values so that every later value keeps nearer its own arrow than these.
  void draw_weight_components(ImDrawList* draw, const lessons::Lesson& lesson, const draw::Camera& camera, std::size_t lane,
                              float newtons_to_pixels, const draw::Theme& theme, const draw::Fonts& fonts,
                              draw::LabelPlacer& labels) const;

  std::optional<b2Vec2> origin_;
  long last_frame_ = 0;  // the lesson's frame when last followed
  bool playing_ = false;    // the lesson, when last followed: what the stopwatch's text says
  bool run_ended_ = false;  // paused at the run's end, when last followed
};

}  // namespace frictionlab::classroom
