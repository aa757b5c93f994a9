// The classroom's side of predict first (the answers and what they hand the frame are the
// prediction panel's, classroom/prediction_panel.h): whether the theory is kept back, and a new round.
#include "classroom/classroom.h"

namespace frictionlab::ui {

bool Classroom::theory_hidden() const {
  return ui::theory_hidden(playback_->lesson(), predictions_.predictions, window_.predictions);
}

void Classroom::predict_again() {
  predictions_.predictions = {};
  // Answers are typed before the run: it goes back to its start.
  playback_->reset();
  status_ = "New predictions: the class's answers are cleared, the theory is hidden, and the run is back at t = 0.";
  status_moment_ = Moment{status_, playback_->lesson().scene().frame(), theory_hidden()};
}

}  // namespace frictionlab::ui
