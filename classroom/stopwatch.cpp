#include "classroom/stopwatch.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace frictionlab::classroom {

namespace {

constexpr double never = std::numeric_limits<double>::infinity();
// Lesson times are whole frames of the fixed step; a rounding's worth apart is the same time.
constexpr double same_time = 1e-9;

}  // namespace

bool Stopwatch::Span::on() const { return to == never; }

void Stopwatch::start_stop(double now) {
  used_ = true;
  if (running()) {
    spans_.back().to = now;
    // Switched on and off at one moment (W twice while paused): it never counted anything.
    if (spans_.back().to <= spans_.back().from + same_time) spans_.pop_back();
  } else {
    spans_.push_back({now, never});
  }
}

void Stopwatch::lap(double now) {
  if (!running() || armed(now)) return;  // armed, it has nothing to lap yet
  used_ = true;
  laps_.push_back({now, reading(now)});
}

void Stopwatch::reset() { *this = Stopwatch{}; }

void Stopwatch::rewind(double now) {
  // Spans begun after `now` had not begun then; one that held `now` was on then, and is on again.
  while (!spans_.empty() && spans_.back().from > now + same_time) spans_.pop_back();
  if (!spans_.empty() && spans_.back().to > now + same_time) spans_.back().to = never;
  while (!laps_.empty() && laps_.back().at > now + same_time) laps_.pop_back();
}

double Stopwatch::reading(double now) const {
  double counted = 0.0;
  for (const Span& span : spans_) counted += std::max(0.0, std::min(span.to, now) - span.from);
  return counted;
}

std::vector<double> Stopwatch::laps() const {
  std::vector<double> readings;
  for (const Lap& taken : laps_) readings.push_back(taken.reading);
  return readings;
}

std::string Stopwatch::text(double now, bool playing, bool run_ended) const {
  const double shown = reading(now);
  // At the run's end the stopwatch stopped with the run; "paused" told the trial's class that
  // someone had paused it.
  const char* state = !running()              ? " (stopped)"
                      : playing               ? ""
                      : armed(now)            ? " (starts with Play)"
                      : run_ended             ? " (stopped at the run's end)"
                                              : " (paused)";
  char line[64];
  std::snprintf(line, sizeof line, "stopwatch %.2f s%s", shown, state);
  std::string text = line;
  // The last three laps, numbered as the class counts them.
  const std::size_t first = laps_.size() > 3 ? laps_.size() - 3 : 0;
  for (std::size_t i = first; i < laps_.size(); ++i) {
    std::snprintf(line, sizeof line, "\nlap %zu: %.2f s", i + 1, laps_[i].reading);
    text += line;
  }
  return text;
}

std::string Stopwatch::line(double now, bool playing, bool run_ended, std::size_t laps) const {
  std::string shown = text(now, playing, run_ended);
  // text() puts the last three laps on lines of their own; `laps` of them stay, each after a
  // wide space.
  std::size_t lines = static_cast<std::size_t>(std::count(shown.begin(), shown.end(), '\n'));
  for (; lines > laps; --lines) {
    const std::size_t first = shown.find('\n'), second = shown.find('\n', first + 1);
    shown.erase(first, second == std::string::npos ? std::string::npos : second - first);
  }
  for (std::size_t at = shown.find('\n'); at != std::string::npos; at = shown.find('\n', at)) shown.replace(at, 1, "   ");
  return shown;
}

}  // namespace frictionlab::classroom
