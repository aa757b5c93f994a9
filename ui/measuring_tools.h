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

#include "lessons/runtime/lesson.h"
#include "ui/camera.h"
#include "ui/drawing.h"
#include "ui/settings.h"
#include "ui/theme.h"

namespace frictionlab::ui {

// A stopwatch on the lesson's clock: it counts the lesson time that passes while it is on, so
// slow motion, a pause or fast forward change nothing it reads. On while the lesson is paused, it
// is armed: Play starts it, and a pause or the run's end stops what it reads. Its reading is kept
// as the spans of lesson time it was on, so a step back in time (R, the time bar, a rebuild)
// shows it as it was at that time, rather than clearing it: a stopwatch on from t = 0 reads 0
// again after R, and is still armed for the next run.
class Stopwatch {
 public:
  // W: on from `now` (counting as soon as the lesson's time moves), or off.
  void start_stop(double now);
  void lap(double now);  // the reading now joins the laps (while on)
  void reset();
  // The lesson went back to `now`: the reading, whether it was on and the laps as they were then.
  void rewind(double now);
  double reading(double now) const;  // s of lesson time it was on, up to `now`
  bool running() const { return !spans_.empty() && spans_.back().on(); }  // on: counting lesson time
  // On but still at 0 s at `now`: it starts counting when the lesson's time moves (Play).
  bool armed(double now) const { return running() && reading(now) == 0.0; }
  // What W does now, in the Tools menu's words: armed, it has not started, so W disarms it.
  const char* start_stop_words(double now) const {
    return armed(now) ? "Disarm the stopwatch (it starts with Play)" : running() ? "Stop the stopwatch" : "Start the stopwatch";
  }
  // Started or lapped since the last reset (a stopwatch shown but never used is armed by the tools).
  bool used() const { return used_; }
  std::vector<double> laps() const;  // their readings, oldest first
  // "stopwatch 1.23 s" (while the lesson plays), "... (starts with Play)", "... (paused)",
  // "... (stopped at the run's end)" (on, when the lesson's run ended by itself: `run_ended`)
  // or "... (stopped)" (switched off), with its last laps on lines below.
  std::string text(double now, bool playing, bool run_ended = false) const;

 private:
  struct Span {
    double from, to;  // lesson times; `to` infinite while on
    bool on() const;
  };
  struct Lap {
    double at, reading;  // the lesson time it was taken at, and what it read
  };
  std::vector<Span> spans_;
  std::vector<Lap> laps_;
  bool used_ = false;
};

// The body the tools measure: the one the view follows, else the lesson's first moving body
// (the free-body diagram's). Null when nothing moves.
const b2Body* measured_body(const lessons::Lesson& lesson);

// The surface a body stands on: a touching contact with a fixed body, the point on it under the
// body's centre of mass, its direction along the surface (x ≥ 0, rightwards), and the normal out of it towards the body.
// At t = 0, before any contact, a body at rest stands on the face its own angle puts lowest.
struct Surface {
  b2Vec2 point, along, normal;
  // How far the fixed body reaches along the surface from `point`, m (a slope's top ends the
  // marks; a ground runs on). Unbounded when the body is not known (set down at t = 0).
  float low = -1e30f, high = 1e30f;
};
std::optional<Surface> surface_under(const Scene& scene, const b2Body* body);

// What the speed tool shows beside a body: its centre of mass's speed, "v = 0.092 m/s".
std::string speed_reading(const b2Body* body);

// The weight of a body on a slope split along and across it: m·g·sin θ downhill and m·g·cos θ
// into the slope. None on a level surface (θ under half a degree) or off any fixed surface.
struct SlopeWeight {
  double angle = 0.0;   // rad
  double along = 0.0;   // N, m·g·sin θ
  double across = 0.0;  // N, m·g·cos θ
  b2Vec2 downhill{0.0f, 0.0f}, into{0.0f, 0.0f};  // unit vectors
};
std::optional<SlopeWeight> slope_weight(const Scene& scene, const b2Body* body);

// The distance marks in a lane: a line along the surface just inside it, from where the view
// shows it to where it ends, a tick every nice length counted from where the measured body stood
// at t = 0, and each tick's number just under it: counted forward rightwards along a level
// floor and downhill on a slope, with a minus sign behind the start.
struct DistanceMark {
  ImVec2 foot;        // the tick's foot on the line
  double metres;      // from the start, forward (rightwards, or downhill) positive
  std::string text;   // "0.4 m", "−0.2 m"
  ImVec4 number_box;  // where its number goes, x0, y0, x1, y1, as the label placer pads a label
};
struct DistanceMarks {
  ImVec2 from, to;  // the line
  ImVec2 inward;    // screen direction into the surface
  std::vector<DistanceMark> ticks;
};

// The tools in one lane of the world view. avoid() tells the placer what they draw before any
// label is placed; draw() draws them and places their labels. `first_lane`: the stopwatch goes
// in the first lane only; the body's tools go in the lane whose strip holds it.
class MeasuringTools {
 public:
  ToolSettings on;  // the window's, copied in each frame
  Stopwatch stopwatch;

  // Each frame before drawing: where distances count from (the main body's place on its surface
  // at t = 0, taken whenever the lesson is at t = 0), the stopwatch taken back with the lesson's
  // time, and a stopwatch shown but never used armed while the lesson is paused (Play starts it).
  // `run_ended`: paused where the lesson's run ended by itself (Playback::at_run_end).
  void follow(const lessons::Lesson& lesson, bool playing, bool run_ended = false);
  // The stopwatch shown (on.stopwatch) while the lesson is paused, and never used since its last
  // reset: armed at `now`, so that Play starts it.
  void arm_stopwatch(double now, bool playing);
  void avoid(const lessons::Lesson& lesson, const Camera& camera, float newtons_to_pixels, float scale,
             LabelPlacer& labels) const;
  // Its part in each pass of a lane's drawing (WorldToolsPass): avoid(), draw_distance_marks()
  // and draw() in turn.
  void in_world(WorldToolsPass pass, ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera,
                float newtons_to_pixels, const Theme& theme, const Fonts& fonts, bool first_lane,
                LabelPlacer& labels) const;
  // The distance marks, when on, and the measured body is in this lane (none otherwise).
  std::optional<DistanceMarks> distance_marks(const lessons::Lesson& lesson, const Camera& camera,
                                              const Fonts& fonts) const;
  // Draws the distance marks, each number at its tick where it covers nothing the placer knows
  // (an arrow, a contact mark, a spring, a body, a label placed earlier): called before the
  // lesson's labels are placed (WorldToolsPass::fixed_labels), which then keep off the numbers.
  void draw_distance_marks(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                           const Fonts& fonts, LabelPlacer& labels) const;
  // The stopwatch (in the first lane's corner) and the speed (above the body), each there or in
  // the nearest place free of what the placer knows; called before the lesson's labels are
  // placed (WorldToolsPass::fixed_labels), which keep off them.
  void draw_readings(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, const Theme& theme,
                     const Fonts& fonts, bool first_lane, LabelPlacer& labels) const;
  // The weight's components, whose labels keep off the bodies.
  void draw(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, float newtons_to_pixels,
            const Theme& theme, const Fonts& fonts, LabelPlacer& labels) const;
  std::optional<b2Vec2> distance_origin() const { return origin_; }

 private:
  std::optional<b2Vec2> origin_;
  long last_frame_ = 0;  // the lesson's frame when last followed
  bool playing_ = false;    // the lesson, when last followed: what the stopwatch's text says
  bool run_ended_ = false;  // paused at the run's end, when last followed
};

}  // namespace frictionlab::ui
