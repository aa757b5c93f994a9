// The readings the lesson commands (the window, run, check, render) share: numbers in a range,
// --set, the step settings and the mystery. Which options each command takes, and their
// ranges, are app/command_line.h's table.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "classroom_state/mystery.h"
#include "physics/scene.h"

namespace frictionlab {

// The whole of `text` as a number within [low, high] (low excluded when low_open); throws
// InvalidInput naming the option and the allowed range.
double option_number(const std::string& option, const std::string& text, double low, double high, bool low_open,
                     const char* unit);
// --set NAME=VALUE into `overrides`.
void add_override(const std::string& text, std::map<std::string, std::string>& overrides);
// --hz, --substeps or --friction into `settings`, within the table's ranges; false if `option`
// is none of them.
bool step_option(const Option& option, const std::string& value, StepSettings& settings);

// --mystery PAIR and --seed N, as the window, render and run take them: gathered one option at
// a time, then checked together.
struct MysteryOptions {
  std::string pair;
  std::optional<std::uint64_t> seed;
  // Takes --mystery or --seed; false if `option` is neither. Throws InvalidInput for a bad seed.
  bool take(const Option& option, const std::string& value);
  // The choice, or none when neither was given; throws InvalidInput when only one was.
  std::optional<classroom_state::MysteryChoice> choice() const;
};
// Makes the lesson's pair a mystery: its coefficients set to the seed's values. Throws
// InvalidInput naming --mystery when the lesson has no such pair, or --set when `overrides`
// set one of its coefficients.
classroom_state::Mystery apply_mystery(lessons::Lesson& lesson, const classroom_state::MysteryChoice& choice,
                          const std::map<std::string, std::string>& overrides);

// Every probe keeps a value a step in memory: refuses, before any step, a run of `duration`
// seconds at `hz` whose record would pass 1.6 GB. `advice` says which options make it smaller.
void require_record_fits(double duration, double hz, std::size_t probes, const std::string& advice);

}  // namespace frictionlab
