// The classroom's side of predict first (classroom/prediction_panel.h): where the answers are typed, when
// they may change, and what stays hidden until the teacher reveals the theory.
#include "classroom/classroom.h"

namespace frictionlab::ui {

bool Classroom::theory_hidden() const {
  return ui::theory_hidden(playback_->lesson(), predictions_, window_.predictions);
}

void Classroom::predict_again() {
  predictions_ = {};
  // Answers are typed before the run: it goes back to its start.
  playback_->reset();
  status_ = "New predictions: the class's answers are cleared, the theory is hidden, and the run is back at t = 0.";
}

// An answer is the class's for the values it was given at. At t = 0 (where answers are typed,
// and where a changed value or R brings a run), a row whose theory is not what it was when the
// class answered (the mass was changed, or anything else it depends on) loses its answer; a
// value the row does not depend on keeps it. Before the reveal the class is asked again; after
// it (a teacher exploring other values) the old answer would be judged against a theory it was
// never about, so it goes too, and View > Predict again asks anew with the theory hidden.
void Classroom::forget_outdated_predictions() {
  if (playback_->lesson().scene().frame() != 0) return;
  std::vector<std::string> outdated;
  for (const auto& [row_name, answer] : predictions_.answers) {
    for (const lessons::ExpectationResult& row : playback_->readings().expectations) {
      if (row.name != row_name || row.failed) continue;
      const std::string theory = row.numeric ? exact_text(row.predicted) : row.predicted_text;
      const auto [seen, first] = predictions_.theory_answered.emplace(row_name, theory);
      if (!first && seen->second != theory) outdated.push_back(row_name);
    }
  }
  for (const std::string& row_name : outdated) {
    predictions_.answers.erase(row_name);
    predictions_.theory_answered.erase(row_name);
  }
  // Rows no longer answered (a box emptied) are seen afresh when answered again.
  std::erase_if(predictions_.theory_answered, [&](const auto& seen) { return predictions_.answers.count(seen.first) == 0; });
  if (!outdated.empty()) {
    status_ = "A value changed after the class predicted \"" + outdated.front() + "\"" + (outdated.size() > 1 ? " (and more)" : "") +
              ": that prediction was for the old values, so it is cleared. " +
              (predictions_.revealed ? "View > Predict again asks the class anew, the theory hidden." : "Ask the class again.");
  }
}

void Classroom::predictions_style(FrameStyle& style) {
  const lessons::Lesson& lesson = playback_->lesson();
  // A teacher who takes no predictions, or a lesson that asks for none, has the theory table as it was.
  if (!window_.predictions || lesson.predictions().empty()) return;
  style.theory_hidden = theory_hidden();
  style.comparing = run_played();
  style.predictions = [this] {
    // Answers are given before the run: once it has started they are what the class said.
    const bool editable = !predictions_.revealed && playback_->lesson().scene().frame() == 0;
    PredictionControls controls;
    controls.remember = [this](const std::string& name) { remember(name); };
    controls.reveal = [this] { predictions_.revealed = true; };
    // A mystery's values are in the theory: it stays hidden here too until the mystery is revealed.
    predictions_contents(playback_->lesson(), playback_->readings().expectations, predictions_, editable,
                         theme(window_.theme), controls, hidden_values().theory());
  };
  style.predictions_height = [this](float width) {
    return predictions_contents_height(playback_->lesson(), playback_->readings().expectations, predictions_, width,
                                       hidden_values().theory());
  };
}

}  // namespace frictionlab::ui
