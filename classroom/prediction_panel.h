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

#include "classroom/control_places.h"
#include "classroom_state/class_predictions.h"
#include "classroom_state/playback.h"
#include "draw/frame.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

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
// Once the theory is shown, the class's line under a predicted row's name: its answer and how
// close it came, "class: 3.5 N · −0.42 N, 11 % below the measurement" ("class: no prediction").
std::string answer_and_closeness(const lessons::Prediction& prediction, const std::string& answer, const Closeness& near);

// The class's answer to each predicted row, for its column of a projector's theory table
// (FrameStyle::class_answers), by the row's name: "3.5 N" in the good colour where close, "—"
// unanswered. The row's name is the theory table's: the class's rows came a second time above
// it, two lines each, and pushed its last rows out of a projector's column (issue 31); a line of
// words under each row still took two lines at projector text.
draw::ClassAnswers class_answers(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                                 const classroom_state::ClassPredictions& predictions);

// What the prediction panel reports for tests that click it: `remember(name)` after each
// control ("prediction NAME" a number's box, "prediction NAME: WORD" a choice, "reveal").
struct PredictionControls {
  std::function<void(const std::string& name)> remember;
  std::function<void()> reveal;
};

// The panel's contents: before the reveal the questions with the class's answers (editable
// while `editable`: at t = 0) and what the run has measured so far beside each answer given (an
// empty answer's measurement is held back: it is the answer), and the reveal button;
// after it nothing while `lines_in_table` (the class's answers are class_answers, a column of
// the theory table), else each predicted row's name and the class's line above the table; with `theory_withheld` (a mystery pair's values are in it: classroom_state/mystery.h):
// the class's answer, the theory ("hidden") and the measurement side by side, the class judged
// against the measurement alone.
void predictions_contents(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                          classroom_state::ClassPredictions& predictions, bool editable, const draw::Theme& theme,
                          const PredictionControls& controls, bool theory_withheld = false, bool lines_in_table = true);
// The height predictions_contents takes at a width (the panel's inside), in the current font;
// revealed with the theory shown and `lines_in_table`, nothing (their column is the table's).
float predictions_contents_height(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                                  const classroom_state::ClassPredictions& predictions, float width, bool theory_withheld = false,
                                  bool lines_in_table = true);

// The predictions' part of the window: the class's answers for the lesson on screen (a new
// lesson asks again) and what they hand the frame. It owns the answers, as each of Dear ImGui's
// demo windows owns its state: the classroom holds one and asks it each frame.
struct PredictionPanel {
  classroom_state::ClassPredictions predictions;
  // The answers' height the column was planned for, kept from the lesson's opening: a slider's
  // value changes what "measured:" says (stacked_blocks at its slowest pull: "runs off the floor
  // first", a line longer), and a height worked out anew folded the Parameters panel under the
  // teacher's pointer as the slider was let go. A taller text scrolls in its tab instead.
  // A lesson opened, or its script read again (F5, the file watcher: its questions may read
  // otherwise), is planned anew.
  struct PlannedHeight {
    std::string lesson_path;
    long script_loads = 0;
    std::size_t questions = 0;
    float width = 0.0f, font_size = 0.0f;
    draw::FrameStyle::AnswersHeight height;  // before the reveal and after it
    bool outgrown = false;  // the answers need more than `height` now
  };
  std::optional<PlannedHeight> planned;

  // A lesson opens (the command line's, another from the Lesson menu, a setup's): its answers (a
  // setup's, or none) and the column planned anew for its questions.
  void begin(classroom_state::ClassPredictions opened) {
    predictions = std::move(opened);
    planned.reset();
  }
  // Whether the theory is kept from the class now. `asking`: the teacher asks for predictions.
  bool theory_hidden(const lessons::Lesson& lesson, bool asking) const;
  // T: reveals the theory; T again hides it, the answers as they were (a reveal by mistake, a
  // click that landed on the button before the class answered, undone with one key).
  void reveal_key(const lessons::Lesson& lesson, bool asking);
  // View > Predict again: the answers cleared, the theory hidden, the run back at t = 0 (answers
  // are typed before the run). Returns what the status line says of that moment.
  std::string predict_again(classroom_state::Playback& playback);
  // Its items in the View menu (ask for predictions first, reveal, predict again). Returns what
  // the status line says of the moment when Predict again was chosen.
  std::optional<std::string> menu_items(bool& asking, classroom_state::Playback& playback, ControlPlaces& controls);

  // An answer is the class's for the values it was given at. At t = 0 (where answers are typed,
  // and where a changed value or R brings a run), a row whose theory is not what it was when the
  // class answered (the mass was changed, or anything else it depends on) loses its answer; a
  // value the row does not depend on keeps it. Before the reveal the class is asked again; after
  // it (a teacher exploring other values) the old answer would be judged against a theory it was
  // never about, so it goes too, and View > Predict again asks anew with the theory hidden.
  // Returns what the status line should say ("" when no answer went).
  std::string forget_outdated(const classroom_state::Playback& playback);
  // Its part of the frame: the contents and height in the theory panel, and what they hide.
  // `asking`: the teacher asks for predictions (the View menu). `theory_withheld` is asked as the panel is drawn: a mystery's values are in the
  // theory, which stays hidden until the mystery is revealed.
  void style(draw::FrameStyle& style, const classroom_state::Playback& playback, bool asking, const draw::Theme& colours,
             ControlPlaces& controls, std::function<bool()> theory_withheld);
};

}  // namespace frictionlab::classroom
