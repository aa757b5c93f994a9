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

#include "classroom_state/class_predictions.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::ui {

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
// `theory_withheld` (a mystery pair's values are in it: classroom_state/mystery.h) the theory says "hidden"
// even then, and the class is judged against the measurement alone.
void predictions_contents(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                          ClassPredictions& predictions, bool editable, const Theme& theme,
                          const PredictionControls& controls, bool theory_withheld = false);
// The height predictions_contents takes at a width (the panel's inside), in the current font.
float predictions_contents_height(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                                  const ClassPredictions& predictions, float width, bool theory_withheld = false);

}  // namespace frictionlab::ui
