// The lesson as the window runs it: play, pause, single steps, slow motion and fast forward
// on the lesson's fixed step; a record of what was done to it (values set, the mouse's hand),
// so that any earlier moment can be shown again by replaying from t = 0, which the fixed step
// makes exact; the script's file watched; and a simulation that blows up stopped, not shown.
// No drawing here: the window's panels read and drive it.
#pragma once

#include <box2d/box2d.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "classroom_state/gauge_record.h"
#include "lessons/runtime/framing.h"
#include "lessons/runtime/lesson.h"
#include "lessons/runtime/readings.h"

namespace frictionlab::classroom_state {

// A file's modification time (ns) and size, to notice that it was saved; nothing when it
// cannot be read.
using FileStamp = std::optional<std::pair<long long, long long>>;
FileStamp file_stamp(const std::string& path);

class Playback {
 public:
  static constexpr double slowest = 0.1, fastest = 8.0;

  // Throws as lessons::Lesson does (ScriptError, InvalidInput) when the first build fails.
  Playback(const std::string& path, std::map<std::string, std::string> overrides, StepSettings settings);

  lessons::Lesson& lesson() { return *lesson_; }
  const lessons::Lesson& lesson() const { return *lesson_; }
  const lessons::WorldFraming& framing() const { return framing_; }
  // Worked out a few times a second, not every frame, and never thrown mid-frame.
  const lessons::LessonReadings& readings() const { return readings_; }

  // Real time passing: `wall_seconds` times the speed, in whole frames of the lesson. A
  // display frame runs at most a quarter of a second of lesson; what is left over is dropped
  // (the lesson then runs slower than asked, and behind() says so).
  void advance(double wall_seconds);
  bool playing() const { return playing_; }
  // Paused where the lesson's run ended by itself (not played on past it since).
  bool at_run_end() const;
  void play();
  // Paused (or stopped by itself: the run's end, a fall, a failure), the rows are read again
  // at the next frame, whatever the wall clock says: a paused window waits for input and
  // passes no time, and the table would keep what it read up to a fifth of a second before.
  void pause();
  void toggle() { playing_ ? pause() : play(); }
  // Exactly one frame of the lesson (1/hz s), paused.
  void step_once();
  // Whole frames until the lesson's time is the frame nearest `t`, paused there, or until a
  // body falls off, where playing would pause too (the notice says which and when).
  void run_to(double t);
  double speed() const { return speed_; }
  void set_speed(double speed);
  bool behind() const { return behind_; }

  // Back to t = 0 with the values as they are now.
  void reset();
  // The recorded run: from 0 to recorded_until(). Moving to an earlier time replays the run
  // from t = 0 with everything that was done to it; a change made there starts a new record.
  double recorded_until() const;
  void scrub_to(double t);

  // Parameters and settings. Throw InvalidInput (the message says what and the range) and
  // change nothing when the value is refused. A structural value or a setting rebuilds the
  // scene from t = 0; the others change the running lesson and join the record.
  // A number (a choice: its place in the list) reaches the lesson as it is (a slider's, a
  // preset's, the mystery's); text (a typed value) is read first, as --set's is.
  void set_parameter(const std::string& name, double value);
  void set_parameter(const std::string& name, const std::string& text);
  void set_settings(const StepSettings& settings);

  // The mouse's hand on a body (by name) at a point in its own frame, pulled to `target`.
  void grab(const std::string& body, b2Vec2 local_point, b2Vec2 target);
  void move_grab(b2Vec2 target);
  void release();
  // What the force gauge read each frame the hand held a body, in the run as it now stands (a
  // step back replays it), and the stretches the theory table marks hand-pulled.
  const GaugeRecord& gauge() const { return gauge_; }

  // The script's file: call every frame with the wall time; it looks at the file a few times
  // a second and reloads it when it changed. A failed reload leaves the last good lesson
  // running and its message in script_error(). True when what it found changes what the
  // window shows (a reload, the file gone or back): a sleeping window then draws a frame.
  bool watch_file(double wall_seconds);
  bool reload();  // now (F5); false with script_error() set on failure
  // How many times the script was read: 1 as the lesson opens, one more for each reload that
  // built (F5, the file watcher, the page's Apply), after which what was planned for the
  // script's words (the predictions' column) is planned anew.
  long script_loads() const { return script_loads_; }
  // The file as it is now is the one the lesson knows: whoever wrote it (the web page's
  // editor, which reloads it itself and puts the last good text back after a failed Apply)
  // has already reloaded it, and the watcher must not run it again from t = 0 on its next look.
  void file_written() { file_stamp_ = file_stamp(lesson_->path()); }
  const std::string& script_error() const { return script_error_; }
  // Why the lesson stopped by itself: the simulation blew up or the script failed while it
  // ran. Empty while neither happened; only a reset, a reload or a new value clears it.
  const std::string& problem() const { return problem_; }
  // Something worth saying that is not a fault: the lesson's run is over, the file was reloaded.
  // A notice about a moment of the run (it is over, a body fell) is said only while the run is
  // at that moment: rewound from the end, "the run ends at 3.46 s" (as it was worded) read as if it
  // were still there.
  std::string notice() const { return notice_frame_ && *notice_frame_ != frame() ? std::string() : notice_; }
  // Played on past the lesson's end, the theory table keeps the rows the run ended with; said on
  // the status line with the end step's own time ("" before the end). (Said above the table, its
  // three lines pushed push's last row out of sight: the column moved under the class's eyes.)
  std::string past_end_words() const;
  // The notice the run's end gives, known before the run gets there: the transport bar keeps its
  // room from the lesson's opening, so that it does not grow (and push the frame) as the run ends.
  std::string run_end_notice() const;

  // Recomputes the readings now (after a change while paused, say).
  void refresh_readings();

 private:
  struct Action {
    enum class Kind { set, grab, move, release } kind;
    long frame;        // applied just before this frame is stepped
    std::string name;  // parameter or body
    double value = 0.0;  // the parameter's
    b2Vec2 local_point{0.0f, 0.0f}, target{0.0f, 0.0f};
  };
  void after_rebuild();
  void apply(const Action& action);
  // Applies the record's actions made at or before the present frame and not yet applied.
  void apply_due();
  void record(Action action);
  void step_and_check();
  // What is wrong with the simulation (a value that is not a number, a body flown off, energy
  // from nowhere); "" when the state is sound.
  std::string health() const;
  // A moving body that has fallen more than a metre below every fixed and driven body, so
  // that nothing can catch it any more, and was not named yet in this run: its name, or "".
  // Once a run: going back with the time bar and playing the fall again does not pause again.
  std::string newly_fallen() const;
  long frame() const { return lesson_->scene().frame(); }

  std::unique_ptr<lessons::Lesson> lesson_;
  lessons::WorldFraming framing_;
  lessons::LessonReadings readings_;
  std::map<std::string, double> initial_values_;  // the values the record starts from
  std::vector<Action> record_;
  long recorded_frames_ = 0;
  bool playing_ = false;
  double speed_ = 1.0;
  double owed_ = 0.0;  // lesson seconds due but not yet stepped
  bool behind_ = false;
  bool run_over_ = false;  // the lesson's duration was reached once in this run
  // Bodies that fell past everything that could hold them in this run, each said once.
  std::vector<std::string> fallen_;
  bool blown_ = false;     // stays stopped until a reset or a rebuild
  double since_readings_ = 0.0;
  double since_file_check_ = 0.0;
  FileStamp file_stamp_;
  long script_loads_ = 1;
  std::size_t next_action_ = 0;  // the first action of the record not yet applied
  std::string script_error_;
  bool file_missing_ = false;  // script_error_ says the file is gone, not why a reload failed
  std::string problem_;
  std::string notice_;
  std::optional<long> notice_frame_;  // the frame notice_ tells of, when it tells of one
  GaugeRecord gauge_;
};

}  // namespace frictionlab::classroom_state
