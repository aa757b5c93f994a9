// The class's predictions as the window keeps them: the answers typed or picked for a lesson's
// predict{} rows and whether the theory was revealed. Plain data, with the rule that reads a
// typed number; a prepared setup file (classroom_state/setup_file.h) holds the same answers, and
// the prediction panel (classroom/prediction_panel.h) draws them.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom_state {

// The class's answers for the lesson on screen, and whether the theory has been revealed.
struct ClassPredictions {
  std::map<std::string, std::string> answers;  // by expect row: the number as typed, or the word picked
  bool revealed = false;
  // Each answered row's theory as it was when the answer was given (the window's, seen at t = 0
  // before the reveal): a value changed since that changes it (the mass) makes the answer one
  // for other values, and the class is asked again.
  std::map<std::string, std::string> theory_answered;
};

// The theory is kept back: the lesson asks for predictions, the teacher asks for them (the
// View menu), and they have not been revealed yet.
bool theory_hidden(const lessons::Lesson& lesson, const ClassPredictions& predictions, bool asking);

// The largest a numeric answer may be, either way: no lesson's quantity comes near it in its
// unit, and a setup file (classroom_state/setup_file.h) refuses the same answers the window marks.
inline constexpr double largest_answer = 1e6;

// A typed answer read as a number ("2.5", "-0.3") within ±largest_answer; nullopt with `why`
// filled when it is not one.
std::optional<double> read_answer(const std::string& typed, std::string& why);

}  // namespace frictionlab::classroom_state
