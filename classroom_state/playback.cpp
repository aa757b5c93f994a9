#include "classroom_state/playback.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "lessons/runtime/class_words.h"
#include "physics/validation.h"

namespace frictionlab::classroom_state {
FileStamp file_stamp(const std::string& path) {
  struct stat status {};
  if (stat(path.c_str(), &status) != 0) return std::nullopt;
  return std::make_pair(static_cast<long long>(status.st_mtim.tv_sec) * 1'000'000'000LL + status.st_mtim.tv_nsec,
                        static_cast<long long>(status.st_size));
}

namespace {

// A time as the window says it, "2.49 s": to `digits` significant digits (3 for a moment
// read off the run; 6 names a step's own time, t = 2.4875 s, to the step).
std::string seconds_text(double t, int digits = 3) {
  std::ostringstream text;
  text.precision(digits);
  text << t << " s";
  return text.str();
}

// Lesson seconds a single display frame may run: enough for 8× speed at 30 frames a second,
// little enough that a slow step rate never freezes the window.
constexpr double most_per_display_frame = 0.27;
// How often the script works out the theory table, and looks at its file, in real seconds.
constexpr double readings_period = 0.2;
constexpr double file_check_period = 0.25;
// About 8 ms of Box2D a display frame for a small lesson: room for 8× speed at 1920 Hz with 2 sub-steps.
constexpr long most_world_steps_per_display_frame = 5000;

}  // namespace

Playback::Playback(const std::string& path, std::map<std::string, std::string> overrides, StepSettings settings)
    : file_stamp_(file_stamp(path)) {
  // The stamp is taken before the file is read: a save made while it builds is seen next time.
  lesson_ = std::make_unique<lessons::Lesson>(path, std::move(overrides), settings);
  after_rebuild();
}

void Playback::after_rebuild() {
  framing_ = lessons::WorldFraming::of(*lesson_);
  initial_values_.clear();
  for (const lessons::Parameter& parameter : lesson_->parameters()) initial_values_[parameter.name] = parameter.value;
  record_.clear();
  gauge_.clear();
  next_action_ = 0;
  recorded_frames_ = 0;
  owed_ = 0.0;
  run_over_ = false;
  fallen_.clear();
  blown_ = false;
  problem_.clear();
  notice_.clear();
  notice_frame_.reset();
  refresh_readings();
}

void Playback::refresh_readings() {
  since_readings_ = 0.0;
  readings_.error.clear();
  readings_.caveat.clear();
  // Values changed during the run: the predictions use the new ones, the record holds both.
  // A change at t = 0, before anything was measured, mixes nothing.
  for (std::size_t i = 0; i < next_action_; ++i) {
    if (record_[i].kind != Action::Kind::set || record_[i].frame == 0) continue;
    std::string name = record_[i].name;
    for (const lessons::Parameter& parameter : lesson_->parameters()) {
      if (parameter.name == name) name = lessons::parameter_title(parameter);
    }
    char text[300];
    std::snprintf(text, sizeof text,
                  "%s was changed at t = %.2f s: what was measured before it ran with the old value. Press R to "
                  "measure again with the new one.",
                  name.c_str(), static_cast<double>(record_[i].frame) * lesson_->scene().frame_step());
    readings_.caveat = text;
    break;
  }
  // A row whose function fails is that row's "?" alone: the others are read as ever.
  std::exception_ptr failure;
  try {
    readings_.duration = lesson_->duration();
    readings_.expectations = lesson_->expectations(failure);
    lessons::zero_unresolved_motion(readings_.expectations, *lesson_);
    if (failure) std::rethrow_exception(failure);
  } catch (const InvalidInput& error) {
    if (!failure) readings_.expectations.clear();
    readings_.error = error.what();
  }
  // The mouse's hand pulled during the run: the rows are not judged against predictions that
  // know nothing of it, and the class is told why, and when.
  const std::vector<HandStretch> stretches = gauge_.stretches(lesson_->scene().frame_step());
  if (!stretches.empty()) {
    for (lessons::ExpectationResult& row : readings_.expectations) row.hand_pulled = !row.failed;  // a failed row reads "?" alone
    std::string why = stretches_text(stretches);
    why[0] = 'H';
    why += ": the hand's force is in no prediction, so a row that differs reads hand-pulled, not "
           "failed. Press R to measure without it.";
    readings_.caveat = readings_.caveat.empty() ? why : why + " " + readings_.caveat;
  }
}

void Playback::play() {
  // A blown-up or failed lesson stays stopped: stepping on from NaN would only crash Box2D.
  if (blown_ || lesson_->failed()) return;
  playing_ = true;
  notice_.clear();
}

void Playback::pause() {
  if (playing_) since_readings_ = readings_period;
  playing_ = false;
}

void Playback::set_speed(double speed) { speed_ = std::clamp(speed, slowest, fastest); }

void Playback::advance(double wall_seconds) {
  since_readings_ += wall_seconds;
  behind_ = false;
  if (playing_) {
    const double h = lesson_->scene().frame_step();
    owed_ += wall_seconds * speed_;
    if (owed_ > most_per_display_frame + h) {
      behind_ = true;
      owed_ = most_per_display_frame;
    }
    // Steps are whole frames of the lesson; the fraction left waits for the next display frame.
    // At most so many world steps a display frame (a 100 kHz rate with 1000 sub-steps asks for
    // millions): the lesson then runs slower than asked, and says so, instead of freezing.
    long world_steps = 0;
    const long substeps = lesson_->settings().substeps;
    while (playing_ && owed_ >= h * (1.0 - 1e-9)) {
      if (world_steps + substeps > most_world_steps_per_display_frame && world_steps > 0) {
        behind_ = true;
        owed_ = 0.0;
        break;
      }
      owed_ -= h;
      world_steps += substeps;
      step_and_check();
    }
    if (!playing_) owed_ = 0.0;
  }
  if (since_readings_ >= readings_period) refresh_readings();
}

void Playback::step_once() {
  pause();
  if (blown_ || lesson_->failed()) return;
  step_and_check();
  refresh_readings();
}

void Playback::run_to(double t) {
  pause();
  const double h = lesson_->scene().frame_step();
  // It stops where playing would pause for a body that fell: a window opened with --at 30 on
  // push showed an empty world and only the past-the-end status, the block gone 20 s before.
  const std::size_t fallen_before = fallen_.size();
  while (lesson_->scene().time() + 0.5 * h < t && !blown_ && !lesson_->failed() && fallen_.size() == fallen_before) {
    step_and_check();
  }
  pause();
  refresh_readings();
}

void Playback::step_and_check() {
  if (blown_ || lesson_->failed()) {
    pause();
    return;
  }
  apply_due();
  try {
    lesson_->step();
  } catch (const InvalidInput& error) {
    pause();
    problem_ = std::string(error.what()) + ". Fix the script and save it (it reloads), or press R to start again.";
    return;
  }
  recorded_frames_ = std::max(recorded_frames_, frame());
  gauge_.after_step(lesson_->scene());
  // What was done at this frame is done as soon as it is reached, as it was live: a moment
  // shown after scrubbing is the moment as it was.
  apply_due();
  if (std::string trouble = health(); !trouble.empty()) {
    pause();
    blown_ = true;
    problem_ = "The simulation blew up at t = " + seconds_text(lesson_->scene().time()) + ": " + trouble +
               ". Press R to reset; a smaller step (higher step rate, more sub-steps) or gentler values may hold.";
    return;
  }
  // The end of the lesson's run waits for a hand that is pulling: a teacher mid-pull, the class
  // watching the gauge, had the run pause under the mouse.
  if (!run_over_ && lesson_->scene().grabbed() == nullptr && lesson_->reached(readings_.duration)) {
    run_over_ = true;
    pause();
    notice_ = run_end_notice();
    notice_frame_ = frame();
  }
  // Played on, a pushed block leaves the floor's end and falls for ever, with plots running on
  // and nothing said: the trial's teacher saw push do it. Pause, once for each body, and say so.
  if (std::string fallen = newly_fallen(); !fallen.empty()) {
    fallen_.push_back(fallen);
    pause();
    // Short enough for the status line's two lines on a projector (about 74 characters).
    notice_ = "Paused: " + fallen + " has fallen off (t = " + seconds_text(lesson_->scene().time()) +
              "). R starts again; Space plays on.";
    notice_frame_ = frame();
  }
}

std::string Playback::past_end_words() const {
  const std::optional<double> end = lesson_->rows_kept_from_end();
  if (!end) return "";
  // The end step's own time to the millisecond, as the time bar reads ("t = 2.488 s"), not as
  // the title rounds it: t = 2.49 s shown is past tipping_box's end at 2.4875 s. (Six figures,
  // 5.44167 s beside a bar at 5.450 s, read as noise to a teacher.)
  // Two lines beside a projector's time bar hold it whole; with "R restarts." after it the
  // middle was cut ("the table keeps its … R restarts."); the bar's Reset button, which R presses, is beside it.
  char when[32];
  std::snprintf(when, sizeof when, "%.3f s", *end);
  return std::string("Past the run's end at ") + when + ": the table keeps its rows.";
}

std::string Playback::run_end_notice() const {
  return "The run ends here: Space plays on.";
}

bool Playback::at_run_end() const {
  // At the end itself: a step back (",") or the time bar leaves the run's end behind.
  return !playing_ && run_over_ && lesson_->first_to_reach(readings_.duration);
}

std::string Playback::newly_fallen() const {
  const Scene& scene = lesson_->scene();
  float lowest = INFINITY;  // the lowest point of any fixed or driven body
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) lowest = std::min(lowest, lessons::body_box(body).lowerBound.y);
  }
  if (!std::isfinite(lowest)) return "";  // nothing to fall off
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody || std::find(fallen_.begin(), fallen_.end(), name) != fallen_.end()) continue;
    if (lessons::body_box(body).upperBound.y < lowest - 1.0f) return name;
  }
  return "";
}

std::string Playback::health() const {
  const Scene& scene = lesson_->scene();
  for (const auto& [name, body] : scene.bodies()) {
    const b2Vec2 p = body->GetPosition(), v = body->GetLinearVelocity();
    const float angle = body->GetAngle(), spin = body->GetAngularVelocity();
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(angle) && std::isfinite(v.x) && std::isfinite(v.y) &&
          std::isfinite(spin))) {
      return "body '" + name + "' has a position or velocity that is not a number";
    }
    if (p.Length() > 1e5f) return "body '" + name + "' flew off beyond 100 km";
    if (v.Length() > 1e4f) return "body '" + name + "' moves faster than 10 km/s";
  }
  // Energy from nowhere ten times larger than every honest entry in the books. Integrators'
  // errors stay far below that; Box2D pushing overlapping bodies apart at the start can give as
  // much as the potential energy it adds (once); a diverging method passes it within steps.
  const EnergyLedger& books = scene.ledger();
  const double honest = std::max({1.0, std::abs(books.initial), std::abs(books.work_applied),
                                  std::abs(books.work_drivers), std::abs(books.potential), books.dissipated()});
  const double residual = books.residual();
  if (!std::isfinite(residual)) return "the energy is not a number";
  if (residual > 10.0 * honest) {
    std::ostringstream text;
    text.precision(3);
    text << "the energy ran away (" << residual << " J from nowhere, against at most " << honest
         << " J in any entry of the books)";
    return text.str();
  }
  return "";
}

void Playback::reset() {
  pause();
  try {
    lesson_->reset();
  } catch (const InvalidInput& error) {
    problem_ = error.what();
    return;
  }
  after_rebuild();
}

double Playback::recorded_until() const {
  return static_cast<double>(recorded_frames_) * lesson_->scene().frame_step();
}

void Playback::scrub_to(double t) {
  pause();
  const double h = lesson_->scene().frame_step();
  const long target = std::clamp(std::lround(t / h), 0L, recorded_frames_);
  if (target == frame()) return;
  if (target < frame()) {
    // Replay from the start: the values the record began with, then every action at its frame.
    for (const lessons::Parameter& parameter : lesson_->parameters()) {
      const auto initial = initial_values_.find(parameter.name);
      if (initial != initial_values_.end() && !parameter.structural && parameter.value != initial->second) {
        lesson_->set(parameter.name, initial->second);
      }
    }
    try {
      lesson_->reset();
    } catch (const InvalidInput& error) {
      problem_ = error.what();
      return;
    }
    framing_ = lessons::WorldFraming::of(*lesson_);
    next_action_ = 0;
    gauge_.clear();  // recorded again as the run is replayed
    blown_ = false;
    problem_.clear();
    apply_due();
  }
  while (frame() < target && !blown_ && !lesson_->failed()) step_and_check();
  pause();
  refresh_readings();
}

void Playback::apply_due() {
  while (next_action_ < record_.size() && record_[next_action_].frame <= frame()) apply(record_[next_action_++]);
}

void Playback::record(Action action) {
  action.frame = frame();
  apply(action);  // a refused value throws here, before anything is recorded
  // A change made back in the record starts a new one from here: the old future is gone.
  if (frame() < recorded_frames_ || next_action_ < record_.size()) {
    record_.erase(record_.begin() + static_cast<std::ptrdiff_t>(next_action_), record_.end());
    recorded_frames_ = frame();
  }
  record_.push_back(std::move(action));
  next_action_ = record_.size();
}

void Playback::apply(const Action& action) {
  Scene& scene = lesson_->scene();
  switch (action.kind) {
    case Action::Kind::set: lesson_->set(action.name, action.value); break;
    case Action::Kind::grab: scene.grab(scene.body(action.name), action.local_point, action.target); break;
    case Action::Kind::move: scene.move_grab(action.target); break;
    case Action::Kind::release: scene.release(); break;
  }
}

void Playback::set_parameter(const std::string& name, const std::string& text) {
  set_parameter(name, lessons::parse_parameter_value(lesson_->parameter(name), text));  // throws for an unknown name
}

void Playback::set_parameter(const std::string& name, double value) {
  const lessons::Parameter& parameter = lesson_->parameter(name);  // throws for an unknown name
  if (parameter.structural) {
    lesson_->set(name, value);  // throws and changes nothing when refused
    after_rebuild();
    return;
  }
  record({Action::Kind::set, 0, name, value});
  if (!blown_ && !lesson_->failed()) problem_.clear();
  refresh_readings();
}

void Playback::set_settings(const StepSettings& settings) {
  pause();
  lesson_->set_settings(settings);
  after_rebuild();
}

void Playback::grab(const std::string& body, b2Vec2 local_point, b2Vec2 target) {
  record({Action::Kind::grab, 0, body, 0.0, local_point, target});
}

void Playback::move_grab(b2Vec2 target) {
  if (lesson_->scene().grabbed() == nullptr) return;
  record({Action::Kind::move, 0, "", 0.0, {0.0f, 0.0f}, target});
}

void Playback::release() {
  if (lesson_->scene().grabbed() == nullptr) return;
  record({Action::Kind::release, 0, "", 0.0, {0.0f, 0.0f}, {0.0f, 0.0f}});
}

bool Playback::reload() {
  // Playing or paused, the lesson goes on as it was: a student who saves while it plays sees
  // the new one play.
  if (!lesson_->reload()) {
    script_error_ = lesson_->last_error();
    notice_.clear();
    return false;
  }
  script_error_.clear();
  ++script_loads_;
  after_rebuild();
  notice_ = "Reloaded " + lesson_->path() + ".";
  notice_frame_.reset();
  return true;
}

bool Playback::watch_file(double wall_seconds) {
  since_file_check_ += wall_seconds;
  if (since_file_check_ < file_check_period) return false;
  since_file_check_ = 0.0;
  const auto stamp = file_stamp(lesson_->path());
  if (!stamp) {
    // Moved, deleted, or half-way through an editor's save: say so (unless a failed reload
    // already says more), keep the lesson running.
    if (script_error_.empty() || file_missing_) {
      const std::string said = "cannot read " + lesson_->path() + " (moved or deleted?)";
      const bool news = script_error_ != said;
      script_error_ = said;
      file_missing_ = true;
      return news;
    }
    return false;
  }
  const bool was_missing = file_missing_;
  file_missing_ = false;
  if (stamp == file_stamp_) {
    if (was_missing) script_error_.clear();  // back as it was
    return was_missing;
  }
  file_stamp_ = stamp;
  reload();
  return true;
}

}  // namespace frictionlab::classroom_state
