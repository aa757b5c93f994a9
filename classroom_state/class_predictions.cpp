#include "classroom_state/class_predictions.h"

#include <cmath>

#include "physics/validation.h"

namespace frictionlab::classroom_state {

bool theory_hidden(const lessons::Lesson& lesson, const ClassPredictions& predictions, bool asking) {
  return asking && !lesson.predictions().empty() && !predictions.revealed;
}

std::optional<double> read_answer(const std::string& as_typed, std::string& why) {
  // Spaces around a number are no part of it ("40 " from a box typed into before Play).
  const std::size_t first = as_typed.find_first_not_of(" \t");
  const std::string typed =
      first == std::string::npos ? std::string() : as_typed.substr(first, as_typed.find_last_not_of(" \t") - first + 1);
  const std::optional<double> value = validation::parse_decimal(typed, why);
  if (value && std::abs(*value) > largest_answer) {
    why = "outside the range a prediction takes, from -1000000 to 1000000";
    return std::nullopt;
  }
  if (value) return value;
  if (why.empty()) {
    why = typed.find(',') != std::string::npos ? "not a number: write decimals with a point, as in 0.5"
                                               : "not a number: type it as 2.5 or -0.3";
  }
  return std::nullopt;
}

}  // namespace frictionlab::classroom_state
