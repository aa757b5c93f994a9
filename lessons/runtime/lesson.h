// A lesson: a student's Lua script turned into a running scene with parameters, probes, plots
// and expectations. The script is run again whenever the scene must be rebuilt (a structural
// parameter changed, the file changed, reset), each time in a fresh sandbox; a change that
// fails leaves the last good lesson running and says why.
#pragma once

#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lessons/runtime/sandbox.h"
#include "physics/materials.h"
#include "physics/scene.h"
#include "physics/scene_forces.h"

namespace frictionlab::lessons {

// A value the script lets a teacher or student set: a slider (min..max) or a choice.
struct Parameter {
  std::string name;
  std::string unit;
  std::string text;                  // what it is, in words, for the slider's label
  double value = 0.0;
  double default_value = 0.0;
  double min = 0.0;
  double max = 0.0;
  std::vector<std::string> choices;  // not empty: value is the index of the chosen one
  // A material pair's coefficient, its row of the pair's table (mu_s, mu_k, c or b), and the
  // pair it belongs to; nullptr for a parameter that is no pair's coefficient. A row, not its
  // name: a slider's value reaches the pair by the row's member, with no name compared.
  const PairCoefficient* coefficient = nullptr;
  std::string material_a, material_b;
  // Read while the scene was built, so changing it rebuilds the scene from t = 0. The others
  // (coefficients the script only reads later, in its functions) change the running lesson.
  bool structural = false;
  std::string declared_at;           // "path:line"

  bool is_choice() const { return !choices.empty(); }
  std::string shown() const;         // "0.6", "25 °", "plastic"
};

// A value for the parameter, checked: a number within its range, or a choice's place in its
// list. Returns it; throws InvalidInput naming the parameter and the range or the choices.
double check_parameter_value(const Parameter& parameter, double value);
// The same read from text (--set, a typed value): a decimal number, or one of its choices by name.
double parse_parameter_value(const Parameter& parameter, const std::string& text);
// The value of a parameter as text that sets it again exactly: "0.45", "plastic".
std::string parameter_text(const Parameter& parameter);

// A value given from outside the script: the text --set gave, read when its parameter is
// declared, or a number the window set (a slider's, a preset's, the mystery's), kept as the
// double it was: never written out and read back.
struct GivenValue {
  std::string text;
  std::optional<double> number;  // set: `text` is unused
  std::string shown() const;     // the text, or the number as exact_text writes it
};

// A plot's kind: probes against time, or probes against another probe.
enum class PlotKind { time, xy };

// A law drawn beside the measured points: a function of the plot's x (of t on a time plot)
// that gives y, two numbers (a vertical segment, such as static friction's range at v = 0) or
// nil where the branch does not apply.
struct TheoryCurve {
  std::string label;
  std::string declared_at;  // "path:line" of the function
  bool says_when_active = false;  // it has an active = function() ... end
};

// A level a plot marks across its data (a thin solid line, labelled with its value): μs·N, the
// most static friction can answer, and μk·N, what it drops to once the block slides. Theory,
// shown with the theory curves. Its function takes no argument and gives y, or nil for none now.
struct PlotLevel {
  std::string label;
  std::string declared_at;  // "path:line" of the function
};

struct Plot {
  std::string title;
  // The plot's answer to the lesson's question ("θc = 30.96°"): the window adds it to the title
  // once the theory is shown, and keeps the title without it while the class predicts.
  std::string answer;
  std::string declared_at;
  PlotKind kind = PlotKind::time;
  std::string x;  // "time" on a time plot; the first of `xs` when each y has its own x
  std::vector<std::string> y;
  // An X–Y plot may pair each y with an x of its own (x = { ... } as long as y): three blocks'
  // friction each against its own speed. Empty: every y is against x.
  std::vector<std::string> xs;
  const std::string& x_of(std::size_t k) const { return xs.empty() ? x : xs[k]; }
  std::vector<TheoryCurve> theory;
  std::vector<PlotLevel> levels;
  // A time plot shades the stretches when a contact was slipping: any contact, or (shade =
  // "probe") the steps where that probe, a contact's "slipping" say, reads other than 0.
  std::string shade;
};

// A plot's theory curves sampled across its x range, one list of pieces a curve. A piece is a
// polyline where the function gave numbers; nil ends it. Jumps are kept as (near-)vertical
// steps, found by bisection, not slanted lines between samples.
struct TheoryPoint {
  double x, y;
};
struct TheorySamples {
  double x_low = 0.0, x_high = 0.0;
  std::vector<std::vector<std::vector<TheoryPoint>>> curves;  // [curve][piece][point]
};

// One row of the theory-against-simulation table.
struct ExpectationResult {
  std::string name;
  std::string unit;
  bool numeric = true;
  double predicted = 0.0;
  double measured = 0.0;
  double tolerance = 0.0;
  std::string predicted_text;  // for outcomes such as "tips" or "slides"
  std::string measured_text;   // "not measured" until the script's measure has an answer
  bool measured_yet = false;
  bool passes = false;
  // Its own function raised an error (expectations(failure) below): nothing of it is known.
  bool failed = false;
  // The window: the mouse's hand pulled a body during the run, a force no prediction knows of,
  // so a row that differs is marked hand-pulled rather than failed.
  bool hand_pulled = false;
  double error() const { return measured - predicted; }
};

// What the class is asked to predict before the run (predict{}): one of the lesson's expect
// rows, so that the class's answer is set beside that row's theory and measurement, with no
// second copy of either.
struct Prediction {
  std::string expectation;           // the expect row's name
  std::string question;              // as the class is asked it
  std::string unit;                  // the row's unit; empty for a word
  std::vector<std::string> choices;  // not empty: the class picks one of these words
  std::string declared_at;           // "path:line"
  bool is_choice() const { return !choices.empty(); }
};

// A teaching moment the lesson declares in lesson{ moments = { ... } }: a time worth a
// picture (its golden snapshot; one of them is the README's frame), with the parameters and
// theme to show it in.
struct Moment {
  std::string name;                         // a word: it names the golden, <lesson>_<name>.png
  double at = 0.0;                          // s
  std::map<std::string, std::string> set;   // parameter values, as --set NAME=VALUE gives them
  std::string theme = "light";              // "light" or "dark"
  bool readme = false;                      // the lesson's frame in the README
  bool has_shows = false;                   // a function says whether it shows what its name says
  std::string declared_at;                  // "path:line" of lesson{}
};

// What the world view shows, as the script's view{} asks. The window's wheel and drag then
// zoom and pan from there; every kind keeps moving bodies big enough to read, except a window
// the script fixed in metres.
struct View {
  enum class Kind {
    whole,   // no view{}: the lesson's bodies as they stand at t = 0, framed with room around
    follow,  // view{ follow = body [, width = m] }: centred on one body as it moves
    window,  // view{ window = { left, bottom, right, top } }: a fixed part of the world, m
    lanes,   // view{ lanes = { a, b, ... } [, width = m] }: a strip per body, top first, one scale
  };
  Kind kind = Kind::whole;
  // Names, not pointers: a rebuild (a mass changed, a reload) makes new bodies of the same names.
  std::vector<std::string> bodies;    // follow: the one; lanes: one per strip
  std::vector<std::string> titles;    // lanes: what each strip is called (its body's name if none)
  double width = 0.0;                 // m across the view (follow, lanes); 0: the framing chooses
  b2Vec2 low{0.0f, 0.0f}, high{0.0f, 0.0f};  // window: its lower-left and upper-right corners
  std::string declared_at;            // "path:line" of view{}, empty when the lesson has none
};

struct LessonBuild;  // one run of the script: its sandbox, scene and declarations

class Lesson;

// A lesson script's text and the path it was read from (its messages name the path). A Lesson
// run from it hands it back compiled (Lesson::script()), for more runs of the same text: only a
// Lesson compiles it, and the bytecode is used only with the very text it was compiled from.
class ScriptText {
 public:
  ScriptText(std::string path_read, std::string text) : path(std::move(path_read)), source(std::move(text)) {}
  std::string path;
  std::string source;

 private:
  friend class Lesson;
  std::string compiled_;       // Sandbox::compiled() of compiled_from_
  std::string compiled_from_;  // the text it came from
};

class Lesson {
 public:
  // Loads and builds the script at `path`. `overrides` are --set NAME=VALUE pairs. Throws
  // ScriptError (path:line: message) or InvalidInput (a bad setting or --set).
  Lesson(std::string path, std::map<std::string, std::string> overrides = {}, StepSettings settings = {});
  // The same from a script already read: many runs of one script (check --random) read it
  // once, and all of them run the same text even if the file changes meanwhile.
  Lesson(const ScriptText& script, std::map<std::string, std::string> overrides, StepSettings settings);
  // The script as this lesson runs it, its text compiled (for more runs of it: check --random).
  ScriptText script() const;
  ~Lesson();
  Lesson(const Lesson&) = delete;
  Lesson& operator=(const Lesson&) = delete;

  const std::string& path() const { return path_; }
  const std::string& title() const;
  const std::string& question() const;
  double duration() const;  // how long `run` and `check` run it, s
  // Its place in the teaching order (lesson{ order = 10 }), if it gives one.
  std::optional<double> order() const;
  const std::vector<Moment>& moments() const;
  // What the class predicts before the run, in the order declared.
  const std::vector<Prediction>& predictions() const;
  // The moment of that name; throws InvalidInput listing the lesson's moments.
  const Moment& moment(const std::string& name) const;
  // Runs the moment's shows function now (step the lesson to the moment, with the moment's
  // parameters, first): true when it shows what its name says, nullopt when it has no such
  // function. Throws ScriptError when the function fails or returns anything but a boolean.
  std::optional<bool> shows(const std::string& moment);
  // The settings the lesson was given. The scene's own (scene().settings()) are those in force:
  // a lesson may ask for fewer solver passes (lesson{ velocity_iterations = 4 }).
  const StepSettings& settings() const { return settings_; }
  // A number for what a whole run of the lesson depends on: its script's text, its values and
  // its step settings. A new one each time one of them changes (not at a step or a reset), and
  // no two lessons ever share one: what is worked out from those (the plots' planned axes) is
  // known again by it, without reading the script's text.
  std::uint64_t revision() const { return revision_; }

  // The scene, parameters, plots and ropes belong to the current build: set() on a structural
  // parameter, reload() and reset() replace it, so do not keep references across those calls.
  Scene& scene();
  const Scene& scene() const;
  const std::vector<Parameter>& parameters() const;
  const Parameter& parameter(const std::string& name) const;  // throws InvalidInput listing them
  const std::vector<Plot>& plots() const;
  const View& view() const;
  // Doubts about the values, such as mu_k above mu_s, placed at the script line.
  const std::vector<std::string>& warnings() const;
  // Probes with the unit the script gave them, in the order declared.
  const std::string& probe_unit(const std::string& probe) const;
  // What the script calls the probe for the class (probe{ label = ... }), "" when it gives no
  // label (the window then says its name in words).
  const std::string& probe_label(const std::string& probe) const;
  // The kind of force a probe reads, where its read = { handle, "field" } tells (a contact's
  // fx, fy or friction is friction; its normal, nx, ny or loads the normal force; a force's fx
  // or fy an applied force; a spring's, a rope's pull); nothing for a probe computed by a
  // function or sampled, whose kind no reading says, nor for what is no force.
  std::optional<ForceKind> probe_force(const std::string& probe) const;
  // The material a probe is drawn like (probe{ like = ... }), "" for none.
  const std::string& probe_like(const std::string& probe) const;

  // One frame: the scene's step, then the script's every-step functions. A script error stops
  // the lesson (failed() is true until a rebuild) and is thrown as ScriptError.
  void step();
  bool failed() const { return failed_; }
  // Whole steps until the scene's time is the step nearest `t` (never before the present).
  void step_to(double t);
  // Whether a step at time `now`, of `h` seconds, has reached the time `t`: it is the step
  // nearest `t` (the earlier of two as near) or a later one. The one line drawn by step_to,
  // the end of the window's run and the rows kept at the lesson's end.
  static bool step_reaches(double now, double h, double t) { return now + 0.5 * h >= t; }
  // The same for the scene's step now.
  bool reached(double t) const;
  // Whether the scene's step now is the first to reach `t` (the one before it did not): the
  // step that ends a run of duration `t`, and only that one.
  bool first_to_reach(double t) const;
  // The expectations as they stand now; past the lesson's end (a run played on), as they stood
  // at its end. Throws the error of the first row whose function fails.
  std::vector<ExpectationResult> expectations();
  // The same, row by row: a row whose function fails is given marked `failed`, the other rows
  // as they stand, and the first row's error is kept in `failure` (the window says it once
  // and shows "?" for that row alone).
  std::vector<ExpectationResult> expectations(std::exception_ptr& failure);
  // When the run is past the lesson's end, so that expectations() gives the rows kept from it:
  // the time of the step that reached the end (the step nearest the lesson's duration, which a
  // time such as --at 2.49 may pass by a step); nullopt before it and at it.
  std::optional<double> rows_kept_from_end() const;
  // The theory curves of plot `plot` sampled at `count` points across [x_low, x_high] (more
  // where a branch ends or jumps). Kept and given again until the range, the count or a
  // parameter changes. A script error throws ScriptError placed at the curve's function.
  const TheorySamples& theory_samples(std::size_t plot, double x_low, double x_high, int count);
  // For each curve of the plot: whether its active = function() says it applies now; -1 when
  // the curve does not say (the plot then takes the branch nearest the latest point).
  std::vector<int> theory_active(std::size_t plot);
  // Each of the plot's levels at the parameters' values now: a number, or NaN where its
  // function gave nil. A script error throws ScriptError placed at the level's function.
  std::vector<double> plot_levels(std::size_t plot);
  // The script error a plot's theory curve raised the last time it was sampled or asked
  // whether it is active (the chart shows it in place of the curves); "" when none did.
  std::string theory_error() const;

  // Sets a parameter to a number (a choice: its place in the list). Throws InvalidInput (naming
  // the parameter and its range, or listing the parameters) and changes nothing when the value
  // is wrong. A structural parameter rebuilds the scene from t = 0 with the number as it is;
  // the others apply at once (a pair's coefficient goes straight into the pair table).
  void set(const std::string& name, double value);
  // The same from text ("0.45", "plastic"): a typed value, the command line's: read, then set.
  void set(const std::string& name, const std::string& value);
  // Runs the script again from disk (the file changed, or the student asked). Returns false on
  // failure, with the reason in last_error(), and the last good lesson keeps running.
  bool reload();
  // Builds the scene again from t = 0 with the current parameters (after a script error).
  void reset();
  // Another step rate, sub-step count or friction treatment: the scene is built again from
  // t = 0 with it. Throws InvalidInput naming the setting and changes nothing when invalid.
  void set_settings(const StepSettings& settings);
  const std::string& last_error() const { return last_error_; }

  // Time spent inside the script's Lua since timing was switched on, for the benchmark.
  void time_script(bool on);
  double seconds_in_script() const;

 private:
  // Runs the script in a fresh sandbox. With `strict`, a --set naming no parameter is an
  // error; a reload after an edit instead forgets values for parameters that are gone.
  // `compiled` is the source's bytecode, or "" to read the text and fill it in.
  std::unique_ptr<LessonBuild> build(const std::string& source, std::string& compiled, bool strict);
  void replace(std::unique_ptr<LessonBuild> next);
  void rebuild();  // from the same text, after a value or setting changed
  // The rows as they stand now, whatever the time.
  std::vector<ExpectationResult> rows_now(std::exception_ptr& failure);
  // After a step: the rows taken as the run reaches the lesson's end (LessonBuild::rows_at_end).
  void keep_rows_at_end();

  std::string path_;
  std::string source_;    // the text of the last good build
  std::string compiled_;  // source_ compiled (Sandbox::compiled)
  std::map<std::string, GivenValue> overrides_;  // --set's texts, then the numbers set
  StepSettings settings_;
  std::uint64_t revision_ = 0;  // revision()
  // A revision no lesson has had: the text, a value or the settings changed.
  void revise();
  std::unique_ptr<LessonBuild> current_;
  bool failed_ = false;
  std::string last_error_;
};

// Reads a script file; throws InvalidInput naming the path when it cannot.
std::string read_script(const std::string& path);

}  // namespace frictionlab::lessons
