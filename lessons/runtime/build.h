// Inside the runtime: one run of a lesson script and the state its API functions fill in.
// Not for use outside lessons/runtime/.
#pragma once

#include <array>
#include <exception>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

// Scripts give angles in degrees.
inline constexpr double degrees = std::numbers::pi / 180.0;

struct ProbeInfo {
  std::string name;
  std::string unit;
  int function = LUA_NOREF;  // LUA_NOREF: read by the runtime itself (probe{ read = ... })
  std::string what;    // "probe 'name'", made once for error messages
  double value = 0.0;  // measured after the latest frame
  std::string label;   // probe{ label = ... }: what plots call it; "" leaves it to the window
  // The kind of force it reads, where its read = { ... } says (a contact's friction or normal
  // force, an applied force, a spring, a rope), or its probe{ force = "friction" } states for a
  // function: plots draw it in the arrows' colour.
  std::optional<ForceKind> force;
  // probe{ like = "grass" }: a material of the lesson whose colour plots draw it in (terrain's
  // distances, each in its lane's surface's colour); "" for the plot's own colours.
  std::string like;
};

// Each part is a Lua value kept in the registry: a constant or a function to call.
struct Expectation {
  std::string name;
  std::string unit;
  std::string declared_at;
  int predicted = LUA_NOREF;
  int measured = LUA_NOREF;
  int tolerance = LUA_NOREF;
};

// The last two answers of a script's function of time. The scene asks for a hand's position
// at t and t + h several times a step (force, work, energy, probes); asking Lua once each
// keeps the script's share of the step small.
struct RememberedValues {
  double times[2] = {0.0, 0.0};
  std::array<double, 2> values[2] = {};
  int filled = 0;
  int next = 0;
};

// A plot's theory curves as the registry keeps them, with the samples last drawn.
struct PlotFunctions {
  std::vector<int> curves;  // function(x) per curve
  std::vector<int> active;  // active = function() per curve, LUA_NOREF when not given
  std::vector<int> levels;  // function() per level
  TheorySamples samples;
  int sample_count = 0;
  std::vector<double> sampled_with;  // the parameters' values when sampled
  // The script error the last sampling, the last asking which curve is active, and the last
  // reading of the levels raised
  // (a slider gave the curve's function a value it fails on); "" when they ran.
  std::string samples_error, active_error, levels_error;
};

struct LessonBuild {
  LessonBuild(std::string chunk_name, std::map<std::string, GivenValue> overrides, bool strict, StepSettings settings);

  Sandbox sandbox;
  std::string chunk_name;
  // The values set from outside (--set, sliders), this build's own copy: a build that fails
  // leaves the lesson's untouched. Not strict (a reload), a value that no longer fits is
  // dropped with a warning instead of failing the build.
  std::map<std::string, GivenValue> overrides;
  bool strict = true;
  StepSettings settings;
  // Nothing set from outside and the default step: the settings a script's author ran it at,
  // where its own promises (a moment before the end, a typed answer for a typed prediction) are
  // checked. A coarser step may rightly turn a row's theory into words ("jitters at this step").
  bool at_the_defaults() const { return overrides.empty() && settings == StepSettings{}; }
  std::unique_ptr<Scene> scene;
  PairTable presets;
  // Pairs a script gave fixed values with pair{ ..., sliders = false }: declared, with no
  // coefficient parameters of their own, so declare_preset_pairs leaves them alone.
  std::vector<std::pair<std::string, std::string>> fixed_pairs;
  // A box on feet (box{ ..., feet = n }): its foot fixtures from left to right, for contact(a, b, k).
  std::map<const b2Body*, std::vector<const b2Fixture*>> feet;

  std::string title, question;
  std::string lesson_declared_at;  // "path:line" of lesson{}, once given
  double duration = 10.0;
  int duration_function = LUA_NOREF;
  std::optional<double> order;
  std::vector<Moment> moments;
  std::vector<int> moment_shows;  // one per moment: its shows function, or LUA_NOREF
  std::vector<Parameter> parameters;
  std::string override_error;  // the first bad --set value, reported after the build
  std::vector<std::string> warnings;
  std::vector<Plot> plots;
  std::vector<PlotFunctions> plot_functions;  // beside plots, one for one
  std::vector<ProbeInfo> probes;
  std::vector<Expectation> expectations;
  // The rows as they stood when the run reached the lesson's end (Lesson::step takes them
  // there): a run played on past its end keeps them, since a row such as "time slipping in
  // 5 s" read on a record gone on to 100 s said 54 s (check_the_article). Forgotten with a
  // value changed live; a rebuild starts without them.
  struct RowsAtEnd {
    std::vector<ExpectationResult> rows;
    std::exception_ptr failure;
    long frame = 0;
  };
  std::optional<RowsAtEnd> rows_at_end;
  std::optional<double> end_time;  // the lesson's duration, read once (until a live value changes it)
  std::vector<Prediction> predictions;
  std::vector<int> every_step;
  bool lua_probes = false;  // some probe is a Lua function
  View view;
  std::vector<std::shared_ptr<RememberedValues>> remembered;  // forgotten when a parameter changes live
  // The force functions' among them, also forgotten when the script sets a velocity: a force
  // may read the state, and the next step must apply its answer for the state as it now is.
  std::vector<std::shared_ptr<RememberedValues>> force_memories;
  bool in_every_step = false;  // an every_step function is running: velocities may be set
  // What the scene does at the start of every sub-step (pairs' coefficients that are functions
  // of time take their values); each pair{} that needs it wraps the one before.
  std::function<void(double t)> before_substep;
  // The metatables of the handle types (body, spring, force, contact, rope), by HandleType.
  const void* metatables[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
  bool building = true;

  Parameter* find_parameter(const std::string& name);
  std::string parameter_names() const;
  // Makes a preset material (and its preset pairs with materials already here) available the
  // first time a script names it. Throws InvalidInput for a name that is neither declared nor
  // a preset, listing both.
  void use_material(const std::string& name);

  // After each frame: every probe, then every every_step function, in one protected call
  // (one per function would cost more than the physics of a small lesson).
  void after_frame();

  // Calls the Lua function kept at `reference` with numeric arguments, under the sandbox's
  // budgets; its `results` values are left on the stack for the caller to read and pop.
  void call(int reference, std::initializer_list<double> arguments, int results);
  // "path:line" of a kept function's definition, for errors about what it returned.
  std::string defined_at(int reference);
  // Reads the `count` numbers a kept function returned (on the stack top) and pops them;
  // throws ScriptError placed at the function's definition when they are not finite numbers.
  // Fills `numbers` with them.
  // `t`: the time the function was asked about, for the message; `limit`: the largest size
  // allowed (a function of time's answers must stay within what the scene accepts).
  void numbers_returned(int reference, int count, const std::string& what, double* numbers, double t,
                        double limit = std::numeric_limits<double>::infinity());
  // Pushes the value kept at `reference`, calling it first when it is a function.
  void push_value(int reference);
};

LessonBuild& build_of(lua_State* state);

// A script's function of time kept at `reference` (in the registry), asked for `count` numbers
// at t; its last two answers are remembered (RememberedValues). `what` names it in errors.
// `is_force`: a force's, forgotten also when the script sets a velocity.
std::function<std::array<double, 2>(double)> function_of_time(LessonBuild& build, int reference, int count,
                                                              std::string what, bool is_force = false);

// probe{ samples = function(t) return list end, every = s, delay = d }: the value at the
// probe's time t is the list read at t − d, entry k + 1 being the value at k·s, straight
// between entries. The function (kept at `function` in the registry) is asked for the list
// at the first reading and again whenever the run passes its end; a list no longer than the
// one before is held at its last value from then on. `what` names the probe in errors, which
// are ScriptError placed at the function.
std::function<double()> sampled_reading(LessonBuild& build, int function, double every, double delay, std::string what);

// Asks every plot's theory curves for x (or t) from 0 to 1, and their active functions once,
// so that a curve that cannot work is refused with the script rather than first seen drawn.
// Throws ScriptError placed at the curve.
void try_theory_curves(LessonBuild& build);

// "path:line" of the script line that called the running API function.
std::string caller(lua_State* state);

// A table argument such as box{ "block", width = 0.4 }: typed reads whose errors name the
// call, the field and what was expected. Unknown fields are refused, so a typo such as
// `widht` is reported instead of silently ignored.
class Fields {
 public:
  Fields(lua_State* state, int index, std::string call, std::initializer_list<const char*> known);
  // The same, for a list of known fields made at run time (theory.*'s table of arguments).
  Fields(lua_State* state, int index, std::string call, std::span<const char* const> known);
  // The name in the first position, when the call takes one; it then names the thing in errors.
  std::string name();
  const std::string& what() const { return what_; }

  bool has(const char* key);
  double number(const char* key, const char* unit);
  double number(const char* key, const char* unit, double fallback);
  // Required, and within [low, high] (or (low, high]).
  double number_in(const char* key, const char* unit, double low, double high, bool low_open = false);
  double number_in(const char* key, const char* unit, double fallback, double low, double high,
                   bool low_open = false);
  std::string text(const char* key, const std::string& fallback);
  std::optional<bool> flag(const char* key);
  b2Vec2 point(const char* key, b2Vec2 fallback);
  // Pushes the field's value when it is a function and returns true; false when absent.
  bool push_function(const char* key);
  // Pushes the field's value, whatever it is (nil when absent).
  void push(const char* key);

 private:
  [[noreturn]] void wrong(const char* key, const std::string& expected, int value_index);

  lua_State* state_;
  int index_;
  std::string call_;
  std::string what_;
};

// Declarations are taken only from the script's own top level while it builds: from a
// function it gave (a hand, a force) a declaration could add to the very list the runtime is
// reading. Throws InvalidInput starting with `what` ("box adds to the world") otherwise.
void require_top_level(lua_State* state, const std::string& what);

// Throws InvalidInput naming `what` unless the value at `index` is a function the script
// wrote: a library function (print, math.sin) has no line to report errors at, and takes
// other arguments than the runtime gives.
void require_script_function(lua_State* state, int index, const std::string& what);

// Declares a pair's μs, μk, c and b as parameters (named with `prefix`), applying --set values,
// and returns the values the pair table gets. `only`, when not empty, holds the coefficients'
// rows (physics/materials.h) that get parameters; the others keep `values`.
FrictionPair declare_coefficients(LessonBuild& build, const std::string& a, const std::string& b, FrictionPair values,
                                  const std::string& prefix, const std::string& declared_at,
                                  const std::set<const PairCoefficient*>& only = {});
// After the script: a pair that can rub but that no pair{} declared (its values came from the
// presets) gets its coefficients as parameters too, so every lesson has its sliders.
void declare_preset_pairs(LessonBuild& build);

// lesson{ moments = { ... } }, the value on the stack top: reads and checks each moment
// (everything that can be checked before the parameters exist) into build.moments.
void read_moments(lua_State* state, LessonBuild& build);
// After the script: each moment's set names parameters and gives values within their ranges,
// and, at the lesson's defaults, warns of each moment that sets no parameter and comes after
// its duration (`duration`, in s).
// Throws ScriptError placed at lesson{}.
void check_moments(LessonBuild& build, std::optional<double> duration);

void register_lesson_api(lua_State* state);
void register_world_api(lua_State* state);
// view{}: what the world view shows.
void register_view_api(lua_State* state);
void register_theory_api(lua_State* state);
// predict{}: what the class predicts, one of the expect rows declared above it.
void register_predict_api(lua_State* state);
// After the script: each prediction's row, at the lesson's defaults, answers as the
// prediction asks (a number, or one of its choices). Throws ScriptError placed at predict{}.
void check_predictions(LessonBuild& build);

// A number read from a handle without Lua, for probe{ read = { handle, "field" } }. The
// table is at `index`; throws InvalidInput naming `what` and the handle's fields. `force`, when
// given, is set to the kind of force the field is (nothing where it is no force: a speed, a
// contact's slipping or points, a force's torque).
std::function<double()> reading(lua_State* state, int index, const std::string& what,
                                std::optional<ForceKind>* force = nullptr);


}  // namespace frictionlab::lessons
