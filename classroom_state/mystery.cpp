#include "classroom_state/mystery.h"

#include <cmath>
#include <cstdio>
#include <random>

#include "physics/materials.h"
#include "physics/validation.h"

namespace frictionlab::classroom_state {
namespace {

// A whole number from 0 to count − 1, each equally likely: the engine's 64 bits, with the
// top part that would favour the small numbers thrown away and drawn again.
std::uint64_t uniform_below(std::mt19937_64& engine, std::uint64_t count) {
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % count;  // a multiple of count
  std::uint64_t draw = engine();
  while (draw >= limit) draw = engine();
  return draw % count;
}

std::string pair_name(const lessons::Parameter& parameter) { return parameter.material_a + "/" + parameter.material_b; }

}  // namespace

MysteryValues mystery_values(std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  const auto mu_s = static_cast<std::uint64_t>(mystery_mu_s_low) +
                    uniform_below(engine, static_cast<std::uint64_t>(mystery_mu_s_high - mystery_mu_s_low + 1));
  const auto ratio = static_cast<std::uint64_t>(mystery_ratio_low) +
                     uniform_below(engine, static_cast<std::uint64_t>(mystery_ratio_high - mystery_ratio_low + 1));
  // In whole hundredths, rounded half up: exact, whatever the machine's floating point.
  const std::uint64_t mu_k = (mu_s * ratio + 50) / 100;
  return {static_cast<double>(mu_s) / 100.0, static_cast<double>(mu_k) / 100.0};
}

std::uint64_t parse_mystery_seed(const std::string& option, const std::string& text) {
  const std::string allowed = "a whole number from 0 to " + std::to_string(mystery_seed_max);
  bool digits = !text.empty() && text.size() <= 7;
  for (const char c : text) digits = digits && c >= '0' && c <= '9';
  if (!digits) throw InvalidInput(option + " " + text + ": give " + allowed);
  const std::uint64_t seed = std::stoull(text);
  if (seed > mystery_seed_max) throw InvalidInput(option + " " + text + ": outside the allowed range; give " + allowed);
  return seed;
}

std::vector<std::string> mystery_pairs(const lessons::Lesson& lesson) {
  std::vector<std::string> pairs;
  for (const lessons::Parameter& mu_s : lesson.parameters()) {
    if (mu_s.coefficient != &static_coefficient) continue;
    for (const lessons::Parameter& mu_k : lesson.parameters()) {
      if (mu_k.coefficient == &kinetic_coefficient && mu_k.material_a == mu_s.material_a && mu_k.material_b == mu_s.material_b) {
        pairs.push_back(pair_name(mu_s));
        break;
      }
    }
  }
  return pairs;
}

std::pair<std::string, std::string> mystery_parameters(const lessons::Lesson& lesson, const std::string& pair,
                                                       const std::string& option) {
  for (const lessons::Parameter& mu_s : lesson.parameters()) {
    if (mu_s.coefficient != &static_coefficient) continue;
    const std::string name = pair_name(mu_s), reversed = mu_s.material_b + "/" + mu_s.material_a;
    if (pair != name && pair != reversed) continue;
    for (const lessons::Parameter& mu_k : lesson.parameters()) {
      if (mu_k.coefficient == &kinetic_coefficient && mu_k.material_a == mu_s.material_a && mu_k.material_b == mu_s.material_b) {
        return {mu_s.name, mu_k.name};
      }
    }
  }
  const std::vector<std::string> pairs = mystery_pairs(lesson);
  if (pairs.empty()) {
    throw InvalidInput(option + " " + pair + ": " + lesson.path() +
                       " has no friction pair whose μs and μk are sliders, so none can be a mystery");
  }
  std::string listed;
  for (const std::string& name : pairs) listed += (listed.empty() ? "" : ", ") + name;
  throw InvalidInput(option + " " + pair + ": " + lesson.path() + " has no such friction pair; its pairs: " + listed);
}

double percent_off(double answer, double truth) { return 100.0 * std::abs(answer - truth) / truth; }

std::string closeness_text(double answer, double truth) {
  char text[48];
  std::snprintf(text, sizeof text, "%.1f %% off", percent_off(answer, truth));
  return text;
}

Mystery::Mystery(MysteryChoice choice, const lessons::Lesson& lesson)
    : choice_(std::move(choice)), values_(mystery_values(choice_.seed)) {
  std::tie(mu_s_name_, mu_k_name_) = mystery_parameters(lesson, choice_.pair);
}

std::vector<std::pair<std::string, std::string>> Mystery::settings() const {
  return {{mu_s_name_, validation::exact_text(values_.mu_s)}, {mu_k_name_, validation::exact_text(values_.mu_k)}};
}

std::vector<std::pair<std::string, double>> Mystery::numbers() const {
  return {{mu_s_name_, values_.mu_s}, {mu_k_name_, values_.mu_k}};
}

std::set<std::string> Mystery::hidden() const {
  if (revealed_) return {};
  return {mu_s_name_, mu_k_name_};
}

}  // namespace frictionlab::classroom_state
