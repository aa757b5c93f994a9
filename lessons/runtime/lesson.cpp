#include "lessons/runtime/lesson.h"

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "lessons/runtime/build.h"

namespace frictionlab::lessons {
namespace {

std::string format_value(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

std::string Parameter::shown() const {
  if (is_choice()) return choices[static_cast<size_t>(value)];
  return format_value(value) + (unit.empty() ? "" : " " + unit);
}

void require_top_level(lua_State* state, const std::string& what) {
  if (!build_of(state).building || build_of(state).sandbox.depth() > 1) {
    throw InvalidInput(what + "; call it at the top level of the script, not from a function that runs during the lesson");
  }
}

void require_script_function(lua_State* state, int index, const std::string& what) {
  if (lua_iscfunction(state, index)) {
    throw InvalidInput(what + ": give a function written in the script, as in function(t) ... end, not a "
                       "library one such as print or math.sin");
  }
}

LessonBuild& build_of(lua_State* state) { return *static_cast<LessonBuild*>(sandbox_of(state).owner()); }

LessonBuild::LessonBuild(std::string chunk, std::map<std::string, GivenValue> given, bool strict_overrides,
                         StepSettings step)
    : chunk_name(std::move(chunk)), overrides(std::move(given)), strict(strict_overrides), settings(step),
      presets(preset_table()) {
  scene = std::make_unique<Scene>(PairTable{}, settings);
  lua_State* state = sandbox.state();
  sandbox.set_owner(this);
  scene->set_before_probes([this] { after_frame(); });
  register_lesson_api(state);
  register_world_api(state);
  register_view_api(state);
  register_theory_api(state);
  register_predict_api(state);
}

Parameter* LessonBuild::find_parameter(const std::string& name) {
  for (Parameter& parameter : parameters) {
    if (parameter.name == name) return &parameter;
  }
  return nullptr;
}

std::string LessonBuild::parameter_names() const {
  std::string names;
  for (const Parameter& parameter : parameters) names += (names.empty() ? "" : ", ") + parameter.name;
  return names.empty() ? "(none)" : names;
}

void LessonBuild::use_material(const std::string& name) {
  PairTable& table = scene->pairs();
  const int preset = presets.find_material(name);
  if (table.find_material(name) >= 0) return;
  if (preset < 0) {
    const std::string known = table.material_names(), presets_named = presets.material_names();
    throw InvalidInput("unknown material '" + name + "'; declare it first with material{ \"" + name +
                       "\", density = ... }, or use a preset: " + presets_named +
                       (known.empty() ? "" : "; declared here: " + known));
  }
  table.add_material(presets.material(preset));
  for (int id = 0; id < table.material_count(); ++id) {
    const int other = presets.find_material(table.material(id).name);
    if (other >= 0 && presets.has_pair(preset, other)) table.set_pair(name, table.material(id).name, presets.pair(preset, other));
  }
}

namespace {

// The body of LessonBuild::after_frame, run inside one protected call: plain calls here are
// protected by it.
int measure_frame(lua_State* state) {
  return guarded(state, [&] {
    LessonBuild& build = build_of(state);
    for (ProbeInfo& probe : build.probes) {
      if (probe.function == LUA_NOREF) continue;  // the scene reads it itself
      lua_rawgeti(state, LUA_REGISTRYINDEX, probe.function);
      lua_call(state, 0, 1);
      build.numbers_returned(probe.function, 1, probe.what, &probe.value, build.scene->time());
    }
    const double now = build.scene->time();
    build.in_every_step = true;  // after_frame clears it, whatever happens here
    for (const int reference : build.every_step) {
      lua_rawgeti(state, LUA_REGISTRYINDEX, reference);
      lua_pushnumber(state, now);
      lua_call(state, 1, 0);
    }
    return 0;
  });
}

}  // namespace

void LessonBuild::after_frame() {
  if (!lua_probes && every_step.empty()) return;
  struct Clear {
    bool& flag;
    ~Clear() { flag = false; }
  } clear{in_every_step};
  lua_pushcfunction(sandbox.state(), measure_frame);
  sandbox.call(0, 0);
}

void LessonBuild::call(int reference, std::initializer_list<double> arguments, int results) {
  lua_State* state = sandbox.state();
  lua_rawgeti(state, LUA_REGISTRYINDEX, reference);
  for (const double argument : arguments) lua_pushnumber(state, argument);
  sandbox.call(static_cast<int>(arguments.size()), results);
}

void LessonBuild::push_value(int reference) {
  lua_State* state = sandbox.state();
  lua_rawgeti(state, LUA_REGISTRYINDEX, reference);
  if (lua_isfunction(state, -1)) sandbox.call(0, 1);
}

std::string LessonBuild::defined_at(int reference) {
  lua_State* state = sandbox.state();
  lua_rawgeti(state, LUA_REGISTRYINDEX, reference);
  lua_Debug debug;
  lua_getinfo(state, ">S", &debug);
  return std::string(debug.source + 1) + ":" + std::to_string(debug.linedefined);  // source is "@path"
}

void LessonBuild::numbers_returned(int reference, int count, const std::string& what, double* numbers, double t,
                                   double limit) {
  lua_State* state = sandbox.state();
  std::string problem;
  for (int i = 0; i < count; ++i) {
    const int index = -count + i;
    numbers[i] = lua_type(state, index) == LUA_TNUMBER ? lua_tonumber(state, index) : NAN;
    if (!(std::abs(numbers[i]) <= limit) && problem.empty()) {
      problem = describe(state, index) + (count > 1 ? (i == 0 ? " as its first number" : " as its second number") : "");
    }
  }
  lua_pop(state, count);
  if (problem.empty()) return;
  std::ostringstream message;
  message << defined_at(reference) << ": " << what << " returned " << problem << " at t = " << t << " s; it must return "
          << (count == 1 ? "a finite number" : std::to_string(count) + " finite numbers");
  if (std::isfinite(limit)) message << " within ±1e" << std::lround(std::log10(limit));  // limits are powers of ten
  lua_Debug running;
  if (lua_getstack(state, 0, &running)) {
    // Inside a C function (an API function asking for a hand, or the frame's probes): the
    // message, placed already, goes on as a Lua error, which guarded() passes through
    // instead of placing it a second time.
    lua_pushstring(state, message.str().c_str());
    lua_error(state);
  }
  throw ScriptError(message.str());
}

namespace {
double duration_of(LessonBuild& build);

// Every probe an axis lists in the same unit (the names are known by now).
void require_one_unit(const Plot& plot, const std::vector<std::string>& names, const char* axis,
                      const std::vector<ProbeInfo>& probes) {
  const auto unit_of = [&](const std::string& name) {
    for (const ProbeInfo& probe : probes) {
      if (probe.name == name) return probe.unit;
    }
    return std::string();
  };
  for (const std::string& name : names) {
    if (unit_of(name) == unit_of(names.front())) continue;
    const auto shown = [&](const std::string& probe) {
      const std::string unit = unit_of(probe);
      return probe + (unit.empty() ? std::string(" (no unit)") : " (" + unit + ")");
    };
    throw ScriptError(plot.declared_at + ": plot '" + plot.title + "': its " + axis + " probes " + shown(names.front()) +
                      " and " + shown(name) + " differ in unit, and one axis has one scale; give each unit a plot of its own");
  }
}
}  // namespace

// Read in blocks, not through a stream buffer's characters: in WebAssembly a lesson's start
// spent more time in istreambuf_iterator than in Lua's parser (web_bench.sh).
std::string read_script(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw InvalidInput("cannot read the lesson script " + path + ": " + std::strerror(errno));
  std::string text;
  char block[16384];
  std::size_t got = 0;
  while ((got = std::fread(block, 1, sizeof block, file.get())) > 0) text.append(block, got);
  if (std::ferror(file.get())) throw InvalidInput("cannot read the lesson script " + path + ": " + std::strerror(errno));
  return text;
}

Lesson::Lesson(std::string path, std::map<std::string, std::string> overrides, StepSettings settings)
    : Lesson(ScriptText(path, read_script(path)), std::move(overrides), settings) {}

Lesson::Lesson(const ScriptText& script, std::map<std::string, std::string> overrides, StepSettings settings)
    : path_(script.path), source_(script.source),
      compiled_(script.compiled_from_ == script.source ? script.compiled_ : std::string()), settings_(settings) {
  for (auto& [name, text] : overrides) overrides_[name] = GivenValue{std::move(text), std::nullopt};
  validate(settings_);
  replace(build(source_, compiled_, true));
  revise();
}

void Lesson::revise() {
  // Counted over every lesson of the program, so that two lessons never share one: a cache keyed
  // by it cannot take one lesson's values for another's.
  static std::atomic<std::uint64_t> last{0};
  revision_ = ++last;
}

Lesson::~Lesson() = default;

ScriptText Lesson::script() const {
  ScriptText text(path_, source_);
  text.compiled_ = compiled_;
  text.compiled_from_ = source_;
  return text;
}

std::unique_ptr<LessonBuild> Lesson::build(const std::string& source, std::string& compiled, bool strict) {
  auto next = std::make_unique<LessonBuild>(path_, overrides_, strict, settings_);
  if (compiled.empty()) {
    next->sandbox.load(source, path_);
    compiled = next->sandbox.compiled();
  } else {
    next->sandbox.load_compiled(compiled, path_);
  }
  next->sandbox.call(0, 0);
  next->building = false;
  declare_preset_pairs(*next);
  if (!next->override_error.empty()) throw InvalidInput("--set " + next->override_error);
  for (auto given = next->overrides.begin(); given != next->overrides.end();) {
    if (next->find_parameter(given->first) != nullptr) {
      ++given;
    } else if (strict) {
      throw InvalidInput("--set " + given->first + ": " + path_ + " has no parameter of that name; its parameters: " +
                         next->parameter_names());
    } else {
      given = next->overrides.erase(given);
    }
  }
  if (next->title.empty()) {
    // Placed at line 1, where lesson{} belongs, so that editors can jump there like to any other error.
    throw ScriptError(path_ + ":1: the script never says what it is; begin it with lesson{ title = \"...\", question = "
                      "\"...\" }");
  }
  // At the defaults a moment past the end is warned of (a student's changed default may shorten
  // the run); with other values the lesson may be shorter, and such a moment is not reached.
  check_moments(*next, next->at_the_defaults() && !next->moments.empty() ? std::optional(duration_of(*next)) : std::nullopt);
  for (const Plot& plot : next->plots) {
    std::vector<std::string> names = plot.y;
    if (plot.x != "time") names.push_back(plot.x);
    names.insert(names.end(), plot.xs.begin(), plot.xs.end());
    if (!plot.shade.empty()) names.push_back(plot.shade);
    for (const std::string& name : names) {
      bool known = false;
      std::string probes;
      for (const ProbeInfo& probe : next->probes) {
        known = known || probe.name == name;
        probes += " " + probe.name;
      }
      if (known) continue;
      const std::string listed = probes.empty() ? " (none)" : probes;
      if (name == plot.shade) {
        throw ScriptError(plot.declared_at + ": plot '" + plot.title + "': shade names no probe '" + name + "'; probes:" +
                          listed + " (a contact's slipping, say)");
      }
      throw ScriptError(plot.declared_at + ": plot '" + plot.title + "': no probe is named '" + name + "'; probes:" + listed +
                        ", and x may also be \"time\"");
    }
    // One axis has one scale: a tilt in degrees beside a slide in metres (tipping_box's first
    // plot once) drew the slide as a flat line at 0, and a class read it as "it never slides".
    require_one_unit(plot, plot.y, "y", next->probes);
    require_one_unit(plot, plot.xs, "x", next->probes);
  }
  try_theory_curves(*next);
  check_predictions(*next);
  return next;
}

void Lesson::replace(std::unique_ptr<LessonBuild> next) {
  overrides_ = next->overrides;  // what the new build kept of them
  current_ = std::move(next);
  failed_ = false;
  last_error_.clear();
}

const std::string& Lesson::title() const { return current_->title; }
const std::string& Lesson::question() const { return current_->question; }
// Read once a build and kept until a live value changes it (set()): a duration function may be
// costly (tipping_box integrates the tipping in 1 ms steps), and a rehearsal that read it at each
// of 8 400 steps took 13 s before push_rate's lowest value showed its first frame.
double Lesson::duration() const {
  if (!current_->end_time) current_->end_time = duration_of(*current_);
  return *current_->end_time;
}

namespace {

double duration_of(LessonBuild& build) {
  if (build.duration_function == LUA_NOREF) return build.duration;
  build.call(build.duration_function, {}, 1);
  double seconds = 0.0;
  build.numbers_returned(build.duration_function, 1, "lesson's duration function", &seconds, build.scene->time());
  if (!(seconds > 0.0 && seconds <= 86400.0)) {
    throw ScriptError(build.defined_at(build.duration_function) + ": the lesson's duration function gave " +
                      format_value(seconds) + " s; it must be in (0, 86400]");
  }
  return seconds;
}

// A row's number on the stack's top that is infinite or NaN would print as "inf" and fail as if
// the world were wrong; it is the script's mistake (a division by zero at these values), said
// where the row is declared (`side`: "…: expect 'name': predicted"), with what to give instead.
void refuse_non_finite(lua_State* state, const std::string& side, const char* instead) {
  if (std::isfinite(lua_tonumber(state, -1))) return;
  const std::string got = describe(state, -1);
  lua_pop(state, 1);
  throw ScriptError(side + " gave " + got + "; " + instead);
}

}  // namespace

std::optional<double> Lesson::order() const { return current_->order; }
const std::vector<Moment>& Lesson::moments() const { return current_->moments; }
const std::vector<Prediction>& Lesson::predictions() const { return current_->predictions; }

const Moment& Lesson::moment(const std::string& name) const {
  for (const Moment& moment : current_->moments) {
    if (moment.name == name) return moment;
  }
  std::string names;
  for (const Moment& moment : current_->moments) names += (names.empty() ? "" : ", ") + moment.name;
  throw InvalidInput("no moment '" + name + "' in " + path_ + "; its moments: " + (names.empty() ? "(none)" : names));
}

std::optional<bool> Lesson::shows(const std::string& name) {
  const Moment& wanted = moment(name);
  LessonBuild& build = *current_;
  const int reference = build.moment_shows[static_cast<size_t>(&wanted - build.moments.data())];
  if (reference == LUA_NOREF) return std::nullopt;
  build.call(reference, {}, 1);
  lua_State* state = build.sandbox.state();
  if (lua_type(state, -1) != LUA_TBOOLEAN) {
    const std::string got = describe(state, -1);
    lua_pop(state, 1);
    throw ScriptError(build.defined_at(reference) + ": moment '" + name + "': shows returned " + got +
                      "; it must return true or false");
  }
  const bool shown = lua_toboolean(state, -1) != 0;
  lua_pop(state, 1);
  return shown;
}
Scene& Lesson::scene() { return *current_->scene; }
const Scene& Lesson::scene() const { return *current_->scene; }
const std::vector<Parameter>& Lesson::parameters() const { return current_->parameters; }
const std::vector<Plot>& Lesson::plots() const { return current_->plots; }
const View& Lesson::view() const { return current_->view; }
void Lesson::time_script(bool on) { current_->sandbox.set_timing(on); }
double Lesson::seconds_in_script() const { return std::chrono::duration<double>(current_->sandbox.time_in_lua()).count(); }
const std::vector<std::string>& Lesson::warnings() const { return current_->warnings; }

const Parameter& Lesson::parameter(const std::string& name) const {
  if (Parameter* found = current_->find_parameter(name)) return *found;
  throw InvalidInput("no parameter '" + name + "' in " + path_ + "; its parameters: " + current_->parameter_names());
}

namespace {

// What the script declared of a probe, by its name.
const ProbeInfo& probe_named(const LessonBuild& build, const std::string& probe, const std::string& path) {
  for (const ProbeInfo& info : build.probes) {
    if (info.name == probe) return info;
  }
  throw InvalidInput("no probe '" + probe + "' in " + path);
}

}  // namespace

const std::string& Lesson::probe_unit(const std::string& probe) const {
  return probe_named(*current_, probe, path_).unit;
}

const std::string& Lesson::probe_label(const std::string& probe) const {
  return probe_named(*current_, probe, path_).label;
}

std::optional<ForceKind> Lesson::probe_force(const std::string& probe) const {
  return probe_named(*current_, probe, path_).force;
}

const std::string& Lesson::probe_like(const std::string& probe) const {
  return probe_named(*current_, probe, path_).like;
}

void Lesson::step_to(double t) {
  while (!reached(t)) step();
}

bool Lesson::reached(double t) const { return step_reaches(scene().time(), scene().frame_step(), t); }

bool Lesson::first_to_reach(double t) const {
  const double h = scene().frame_step();
  return reached(t) && !step_reaches(scene().time() - h, h, t);
}

void Lesson::step() {
  if (failed_) return;
  try {
    current_->scene->step();  // the probes and every_step functions run at its end
  } catch (const ScriptError& error) {
    failed_ = true;
    last_error_ = error.what();
    throw;
  } catch (const InvalidInput& error) {
    // The scene refused what a script function gave it (a hand at infinity, say).
    failed_ = true;
    last_error_ = path_ + ": " + error.what();
    throw ScriptError(last_error_);
  }
  keep_rows_at_end();
}

void Lesson::keep_rows_at_end() {
  LessonBuild& build = *current_;
  if (build.rows_at_end) return;
  double end_time = 0.0;
  try {
    end_time = duration();
  } catch (const InvalidInput&) {
    return;  // a duration function that fails is said where the duration is read
  }
  // The step that reaches the end (as step_to(duration) would stop there), and only that one:
  // rows forgotten with a value changed past the end are not taken again on a record gone on.
  if (!first_to_reach(end_time)) return;
  LessonBuild::RowsAtEnd end;
  try {
    end.rows = rows_now(end.failure);
  } catch (const InvalidInput&) {
    return;  // an error outside every row: said as ever where the rows are read
  }
  end.frame = scene().frame();
  build.rows_at_end = std::move(end);
}

std::vector<ExpectationResult> Lesson::expectations() {
  std::exception_ptr failure;
  std::vector<ExpectationResult> rows = expectations(failure);
  if (failure) std::rethrow_exception(failure);
  return rows;
}

std::optional<double> Lesson::rows_kept_from_end() const {
  const auto& end = current_->rows_at_end;
  if (!end || scene().frame() <= end->frame) return std::nullopt;
  return static_cast<double>(end->frame) * scene().frame_step();
}

std::vector<ExpectationResult> Lesson::expectations(std::exception_ptr& failure) {
  if (const auto& end = current_->rows_at_end; end && scene().frame() >= end->frame) {
    failure = end->failure;
    return end->rows;
  }
  return rows_now(failure);
}

std::vector<ExpectationResult> Lesson::rows_now(std::exception_ptr& failure) {
  failure = nullptr;
  LessonBuild& build = *current_;
  lua_State* state = build.sandbox.state();
  std::vector<ExpectationResult> rows;
  for (const Expectation& expectation : build.expectations) {
    ExpectationResult row;
    row.name = expectation.name;
    row.unit = expectation.unit;
    const int top = lua_gettop(state);
    try {
      const std::string where = expectation.declared_at + ": expect '" + expectation.name + "': ";
      build.push_value(expectation.predicted);
      row.numeric = lua_type(state, -1) == LUA_TNUMBER;
      if (row.numeric) {
        refuse_non_finite(state, where + "predicted",
                          "where theory has no number at these values, say why in words, as in predicted = \"never slides\"");
      }
      if (row.numeric) {
        row.predicted = lua_tonumber(state, -1);
      } else if (lua_type(state, -1) == LUA_TSTRING || lua_type(state, -1) == LUA_TBOOLEAN) {
        row.predicted_text = luaL_tolstring(state, -1, nullptr);
        lua_pop(state, 1);
      } else {
        const std::string got = describe(state, -1);
        lua_pop(state, 1);
        throw ScriptError(where + "predicted gave " + got + "; it must be a number, a word such as \"slides\", or true/false");
      }
      lua_pop(state, 1);
      build.push_value(expectation.measured);
      row.measured_yet = !lua_isnil(state, -1);
      if (!row.measured_yet) {
        row.measured_text = "not measured";
      } else if (row.numeric && lua_type(state, -1) == LUA_TNUMBER) {
        refuse_non_finite(state, where + "measured",
                          "a reading must be a finite number, or a word saying why there is none, as in \"still sliding\"");
        row.measured = lua_tonumber(state, -1);
      } else if (row.numeric && lua_type(state, -1) == LUA_TSTRING) {
        // A word where a number is due says why there is no number yet ("still sliding"): the
        // row is not measured, and shows the word instead of "not measured".
        row.measured_yet = false;
        row.measured_text = lua_tostring(state, -1);
      } else if (!row.numeric && (lua_type(state, -1) == LUA_TSTRING || lua_type(state, -1) == LUA_TBOOLEAN)) {
        row.measured_text = luaL_tolstring(state, -1, nullptr);
        lua_pop(state, 1);
      } else {
        const std::string got = describe(state, -1);
        lua_pop(state, 1);
        throw ScriptError(where + "measured gave " + got + " but predicted gave " +
                          (row.numeric ? "a number" : "a word") + "; they must be alike (or nil: not measured yet)");
      }
      lua_pop(state, 1);
      if (row.numeric) {
        build.push_value(expectation.tolerance);
        if (lua_type(state, -1) != LUA_TNUMBER || !(lua_tonumber(state, -1) >= 0.0) || std::isinf(lua_tonumber(state, -1))) {
          const std::string got = describe(state, -1);
          lua_pop(state, 1);
          throw ScriptError(where + "a number needs a tolerance >= 0 in its unit, as in tolerance = 0.05; got " + got);
        }
        row.tolerance = lua_tonumber(state, -1);
        lua_pop(state, 1);
        row.passes = row.measured_yet && std::abs(row.error()) <= row.tolerance;  // false for NaN
      } else {
        row.passes = row.measured_yet && row.measured_text == row.predicted_text;
      }
    } catch (const InvalidInput&) {
      // This row's function failed: the row is marked, the rows after it are still read.
      lua_settop(state, top);
      if (!failure) failure = std::current_exception();
      row = ExpectationResult{};
      row.name = expectation.name;
      row.unit = expectation.unit;
      row.failed = true;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void Lesson::set(const std::string& name, const std::string& text) { set(name, parse_parameter_value(parameter(name), text)); }

namespace {

// What a set value is kept as through rebuilds and reloads: a number as the double it is, a
// choice as its name. A choice kept by its place picked another one silently after a student
// added a choice before it and saved; by its name it stays, or is said to no longer fit.
GivenValue kept_value(const Parameter& parameter, double value) {
  if (parameter.is_choice()) return GivenValue{parameter.choices[static_cast<std::size_t>(value)], std::nullopt};
  return GivenValue{"", value};
}

}  // namespace

void Lesson::set(const std::string& name, double number) {
  Parameter* found = current_->find_parameter(name);
  if (found == nullptr) parameter(name);  // throws, listing the parameters
  Parameter& changed = *found;
  const double value = check_parameter_value(changed, number);
  if (!changed.structural && changed.coefficient != nullptr) {
    // A coefficient the script reads only while running: the pair table changes under the
    // running lesson, as a teacher moving a slider expects.
    // From the pair as it is: a coefficient with no slider of its own keeps the script's value.
    FrictionPair values = scene().pairs().pair(changed.material_a, changed.material_b);
    for (const Parameter& sibling : current_->parameters) {
      if (sibling.material_a != changed.material_a || sibling.material_b != changed.material_b) continue;
      if (sibling.coefficient != nullptr) values.*sibling.coefficient->value = &sibling == &changed ? value : sibling.value;
    }
    scene().pairs().set_pair(changed.material_a, changed.material_b, values);
    scene().wake();  // a block resting on static friction may slide with the new values
    changed.value = value;
    for (const auto& memory : current_->remembered) memory->filled = 0;  // functions may read param
    current_->rows_at_end.reset();
    current_->end_time.reset();
    overrides_[name] = kept_value(changed, value);
    revise();
    return;
  }
  const auto saved = overrides_;
  overrides_[name] = kept_value(changed, value);
  try {
    rebuild();
  } catch (...) {
    overrides_ = saved;
    throw;
  }
  revise();
}

bool Lesson::reload() {
  try {
    std::string source = read_script(path_);
    std::string compiled;
    replace(build(source, compiled, false));
    source_ = std::move(source);
    compiled_ = std::move(compiled);
    revise();
    return true;
  } catch (const InvalidInput& error) {
    last_error_ = error.what();
    return false;
  }
}

void Lesson::rebuild() { replace(build(source_, compiled_, false)); }

void Lesson::reset() { rebuild(); }

void Lesson::set_settings(const StepSettings& settings) {
  validate(settings);
  const StepSettings saved = settings_;
  settings_ = settings;
  try {
    rebuild();
  } catch (...) {
    settings_ = saved;
    throw;
  }
  revise();
}

}  // namespace frictionlab::lessons
