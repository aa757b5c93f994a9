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
#include "classroom/settings.h"
#include "draw/camera.h"
#include "draw/drawing.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"
#include "physics/scene_forces.h"

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
  // The same on one line, its laps after it ("stopwatch 1.23 s (paused)   lap 1: 0.62 s"), as
  // the window shows it beside the lesson's clock; `laps`: at most this many of the last.
  std::string line(double now, bool playing, bool run_ended = false, std::size_t laps = 3) const;

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

// What the speed tool shows beside a body: its centre of mass's speed, "v = 0.092 m/s".
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

// The distance marks in a lane: a line along the surface just inside it, from where the view
// shows it to where it ends, a tick every nice length counted from where the measured body stood
// at t = 0, and each tick's number just under it: counted forward rightwards along a level
// floor and downhill on a slope, with a minus sign behind the start. Where the view has no room
// under the surface for the numbers (a lane's thin strip of ground), the line lies on the
// surface with its ticks and numbers over it; and where fewer than two numbers find room at their
// ticks (nor across the line from them), only every 2nd, 5th or 10th tick is numbered, so
// that the scale can be read.
struct DistanceMark {
  ImVec2 foot;        // the tick's foot on the line
  double metres;      // from the start, forward (rightwards, or downhill) positive
  std::string text;   // "0.4 m", "−0.2 m"
  ImVec4 number_box;  // where its number goes, x0, y0, x1, y1, as the label placer pads a label
  ImVec4 across_box;  // or across the line from its tick, where that side has no room
  bool numbered;      // one of the ticks whose numbers are drawn (where they are free)
};
struct DistanceMarks {
  ImVec2 from, to;  // the line
  ImVec2 inward;    // screen direction of the ticks and the numbers: into the surface, or out of it
  double step;      // m between ticks
  std::vector<DistanceMark> ticks;
};
// Whether a tick is one of every `every`-th, counted from the start (0 m is always one).
bool counted(const DistanceMark& mark, std::size_t every, double step);
// Chooses the ticks whose numbers are drawn: every one, else every 2nd, 5th or 10th, the first
// that gives at least two numbers room where `labels` has it free.
// `fewest_every`: not every tick, but every 2nd at least (and so on).
void number_marks(DistanceMarks& marks, const LabelPlacer& labels, std::size_t fewest_every = 1);

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
  void avoid(const lessons::Lesson& lesson, const Camera& camera, std::size_t lane, float newtons_to_pixels, float scale,
             LabelPlacer& labels) const;
  // Its part in each pass of a lane's drawing (WorldToolsPass): avoid(), draw_distance_marks()
  // and draw() in turn.
  void in_world(WorldToolsPass pass, ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera,
                std::size_t lane, float newtons_to_pixels, const Theme& theme, const Fonts& fonts, LabelPlacer& labels) const;
  // The distance marks, when on, and the measured body is in this lane (none otherwise). With
  // `labels`, the placer as the marks find it when drawn: their side is chosen where the view
  // has room for their numbers (every tick numbered; number_marks chooses which).
  std::optional<DistanceMarks> distance_marks(const lessons::Lesson& lesson, const Camera& camera, const Fonts& fonts,
                                              const LabelPlacer* labels = nullptr, std::size_t lane = 0) const;
  // The speed (above the body), there or in the nearest place free of what the placer knows,
  // or left out when none is near; called before the lesson's labels are placed
  // (WorldToolsPass::fixed_labels), which keep off it. With `preferred` (the placer with the
  // distance marks' numbers taken), only a place free there. Whether it was drawn (or is not
  // to be: off, or in another lane).
  bool draw_readings(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, std::size_t lane,
                     const Theme& theme, const Fonts& fonts, LabelPlacer& labels,
                     const LabelPlacer* preferred = nullptr) const;
  // The weight's components, whose labels keep off the bodies.
  void draw(ImDrawList* draw, const lessons::Lesson& lesson, const Camera& camera, std::size_t lane, float newtons_to_pixels,
            const Theme& theme, const Fonts& fonts, LabelPlacer& labels) const;
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
  void draw_stopwatch_strip(ImVec2 corner, ImVec2 size, double now, const Fonts& fonts) const;

 private:
  std::optional<b2Vec2> origin_;
  long last_frame_ = 0;  // the lesson's frame when last followed
  bool playing_ = false;    // the lesson, when last followed: what the stopwatch's text says
  bool run_ended_ = false;  // paused at the run's end, when last followed
};

}  // namespace frictionlab::ui
