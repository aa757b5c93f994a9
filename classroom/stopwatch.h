// The Tools menu's stopwatch: a clock that reads lesson time, not the wall's. It knows nothing
// of drawing; MeasuringTools shows its line over the title and offers its keys in the Tools menu.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace frictionlab::classroom {

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

}  // namespace frictionlab::classroom
