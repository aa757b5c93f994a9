// The classroom's side of predict first (ui/predictions.h): where the answers are typed, when
// they may change, and what stays hidden until the teacher reveals the theory.
#include "ui/classroom.h"

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
