// A mystery surface: the teacher makes one of a lesson's friction pairs a mystery, its μs and
// μk drawn from a seeded range and hidden from the class until revealed; the class measures
// them from the run and types its answers, and the window says how far off each is.
//
// The draw is the same on every machine: std::mt19937_64's output is fixed by the C++
// standard, and the numbers are made from it here (not by a std:: distribution, whose
// results differ between standard libraries).
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom_state {

// The range the coefficients are drawn from, in hundredths: μs from 0.20 to 0.90, and μk
// from 0.50 to 0.90 of μs (rounded to a hundredth), so μk < μs always and both are values a
// class can tell apart by measuring.
inline constexpr int mystery_mu_s_low = 20, mystery_mu_s_high = 90;          // hundredths
inline constexpr int mystery_ratio_low = 50, mystery_ratio_high = 90;        // hundredths of μs
inline constexpr std::uint64_t mystery_seed_max = 999999;                    // seeds are 0 to this

// What the teacher chose: the pair as "material/material" and the seed.
struct MysteryChoice {
  std::string pair;
  std::uint64_t seed = 0;
  bool operator==(const MysteryChoice&) const = default;
};

struct MysteryValues {
  double mu_s = 0.0, mu_k = 0.0;
};

// The coefficients a seed gives (each a whole number of hundredths).
MysteryValues mystery_values(std::uint64_t seed);

// --seed's text as a seed; throws InvalidInput naming `option` and the allowed range.
std::uint64_t parse_mystery_seed(const std::string& option, const std::string& text);

// The pairs of a lesson that can be a mystery (both μs and μk are its sliders), as
// "material/material".
std::vector<std::string> mystery_pairs(const lessons::Lesson& lesson);

// The names of the μs and μk parameters of `pair` ("a/b" or "b/a"); throws InvalidInput
// naming `option` and listing the lesson's pairs.
std::pair<std::string, std::string> mystery_parameters(const lessons::Lesson& lesson, const std::string& pair,
                                                       const std::string& option = "--mystery");

// How far an answer is from the true value, in percent of the true value.
double percent_off(double answer, double truth);
// The same in words for the class: "3.2 % off".
std::string closeness_text(double answer, double truth);

// The mystery as the window keeps it: which pair, its values, the class's answers, revealed or not.
class Mystery {
 public:
  // Throws InvalidInput (as mystery_parameters) when the lesson has no such pair.
  Mystery(MysteryChoice choice, const lessons::Lesson& lesson);

  const MysteryChoice& choice() const { return choice_; }
  const MysteryValues& values() const { return values_; }
  const std::string& mu_s_name() const { return mu_s_name_; }
  const std::string& mu_k_name() const { return mu_k_name_; }
  // The values as --set would give them, to build the lesson with.
  std::vector<std::pair<std::string, std::string>> settings() const;
  // The same as numbers, to set the running lesson's sliders with.
  std::vector<std::pair<std::string, double>> numbers() const;

  bool revealed() const { return revealed_; }
  void reveal() { revealed_ = true; }
  // Whether the named parameter's value must not be shown now.
  bool hides(const std::string& parameter) const {
    return !revealed_ && (parameter == mu_s_name_ || parameter == mu_k_name_);
  }
  // The parameters hidden now (empty once revealed).
  std::set<std::string> hidden() const;

  // The class's answers, as typed.
  std::optional<double> answer_mu_s, answer_mu_k;

 private:
  MysteryChoice choice_;
  MysteryValues values_;
  std::string mu_s_name_, mu_k_name_;
  bool revealed_ = false;
};

}  // namespace frictionlab::classroom_state
