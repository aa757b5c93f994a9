// Predict first: before Play the class says what it expects (the lesson's predict{} rows, a
// number with its unit or one of a few words), the theory stays hidden, and once the teacher
// reveals it the class's answer is set beside the theory and the measurement. The answers are
// the window's state; what each is compared with is the lesson's expect row of the same name.
#pragma once

#include <imgui.h>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"
#include "ui/theme.h"

namespace frictionlab::ui {

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
// unit, and a setup file (ui/setup_file.h) refuses the same answers the window marks.
inline constexpr double largest_answer = 1e6;

// A typed answer read as a number ("2.5", "-0.3") within ±largest_answer; nullopt with `why`
// filled when it is not one.
std::optional<double> read_answer(const std::string& typed, std::string& why);

// How close the class came, in words, against the measurement once there is one and the
// theory before: "class: +0.12 N, 4 % above the measurement", "class: ✓ right", "class: ✗ the
// theory says tips".
// `close`: within 10 % of it, or the same word.
struct Closeness {
  std::string words;
  bool close = false;
};
Closeness closeness(const lessons::Prediction& prediction, const std::string& answer,
                    const lessons::ExpectationResult& row);

// What the prediction panel reports for tests that click it: `remember(name)` after each
// control ("prediction NAME" a number's box, "prediction NAME: WORD" a choice, "reveal").
struct PredictionControls {
  std::function<void(const std::string& name)> remember;
  std::function<void()> reveal;
};

// The panel's contents: before the reveal the questions with the class's answers (editable
// while `editable`: at t = 0) and what the run has measured so far, and the reveal button;
// after it, the class's answer, the theory and the measurement side by side. With
// `theory_withheld` (a mystery pair's values are in it: ui/mystery.h) the theory says "hidden"
// even then, and the class is judged against the measurement alone.
void predictions_contents(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                          ClassPredictions& predictions, bool editable, const Theme& theme,
                          const PredictionControls& controls, bool theory_withheld = false);
// The height predictions_contents takes at a width (the panel's inside), in the current font.
float predictions_contents_height(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                                  const ClassPredictions& predictions, float width, bool theory_withheld = false);

}  // namespace frictionlab::ui
