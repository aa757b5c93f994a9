#include "app/options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/validation.h"

namespace frictionlab {

double option_number(const std::string& option, const std::string& text, double low, double high, bool low_open,
                     const char* unit) {
  // The same reading as --set's (validation::parse_decimal): decimal only, so "0x10" and "inf"
  // are refused by both.
  std::string why;
  const std::optional<double> value = validation::parse_decimal(text, why);
  if (!value) throw InvalidInput(option + " " + text + ": " + (why.empty() ? "not a number" : why));
  validation::require_in_range(option, *value, low, high, low_open, unit);
  return *value;
}

void add_override(const std::string& text, std::map<std::string, std::string>& overrides) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw InvalidInput("--set " + text + ": write it as NAME=VALUE, as in --set mu_s=0.5");
  const std::string name = text.substr(0, equals), value = text.substr(equals + 1);
  const auto given = overrides.find(name);
  // As any option given twice: which one was meant is not for the program to guess.
  if (given != overrides.end() && given->second != value) {
    throw InvalidInput("--set " + name + " given twice (" + given->second + " and " + value + "); give each parameter once");
  }
  overrides[name] = value;
}

bool step_option(const Option& option, const std::string& value, StepSettings& settings) {
  if (option.name == "--hz") {
    settings.hz = option.number(value);
  } else if (option.name == "--substeps") {
    settings.substeps = option.whole_number(value);
  } else if (option.name == "--friction") {
    settings.treatment = parse_treatment(value);
  } else {
    return false;
  }
  return true;
}

bool MysteryOptions::take(const Option& option, const std::string& value) {
  if (option.name == "--mystery") {
    if (value.find('/') == std::string::npos) {
      throw InvalidInput("--mystery " + value + ": name a friction pair as MATERIAL/MATERIAL, as in --mystery aluminium/wood");
    }
    pair = value;
  } else if (option.name == "--seed") {
    seed = classroom_state::parse_mystery_seed(std::string(option.name), value);
  } else {
    return false;
  }
  return true;
}

std::optional<classroom_state::MysteryChoice> MysteryOptions::choice() const {
  const std::string range = "a whole number from 0 to " + std::to_string(classroom_state::mystery_seed_max);
  if (pair.empty() && !seed) return std::nullopt;
  if (pair.empty()) throw InvalidInput("--seed draws a mystery pair's values: give --mystery MATERIAL/MATERIAL with it");
  if (!seed) throw InvalidInput("--mystery " + pair + " needs --seed N (" + range + "): the same seed draws the same values");
  return classroom_state::MysteryChoice{pair, *seed};
}

classroom_state::Mystery apply_mystery(lessons::Lesson& lesson, const classroom_state::MysteryChoice& choice,
                          const std::map<std::string, std::string>& overrides) {
  classroom_state::Mystery mystery(choice, lesson);
  std::vector<std::pair<std::string, std::string>> settings = mystery.settings();
  for (const auto& [name, value] : settings) {
    if (overrides.count(name) > 0) {
      throw InvalidInput("--set " + name + ": " + name + " is the mystery's (--mystery " + choice.pair + "); leave it out");
    }
  }
  // μk first when it falls, so the pair never passes through μk > μs on the way.
  if (mystery.values().mu_k < lesson.parameter(mystery.mu_k_name()).value) std::swap(settings[0], settings[1]);
  for (const auto& [name, value] : settings) lesson.set(name, value);
  return mystery;
}

void require_record_fits(double duration, double hz, std::size_t probes, const std::string& advice) {
  const double values = duration * hz * static_cast<double>(probes + 1);  // and the time itself
  if (values <= 2e8) return;
  char text[256];
  std::snprintf(text, sizeof text, "a run of %.4g s at %.6g Hz with %zu probes would record %.3g values (more than 1.6 GB); ",
                duration, hz, probes, values);
  throw InvalidInput(text + advice);
}

}  // namespace frictionlab
