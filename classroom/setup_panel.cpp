// Prepared setups in the classroom (classroom/setup_panel.h): the window's state as a setup file
// (classroom_state/setup_file.h), saving it, and opening one in place of the running lesson.
#include "classroom/setup_panel.h"

#include "classroom/classroom.h"

namespace frictionlab::ui {

std::string Classroom::open_setup(const std::string& path) {
  try {
    ClassroomOptions base;
    base.window = window_;
    const ClassroomOptions options = setup_options(path, base);
    std::optional<Mystery> mystery;
    auto next = MysteryPanel::build_playback(options.lesson, options.overrides, options.settings, options.mystery, mystery);
    next->set_speed(playback_->speed());
    // Paused at t = 0, as a lesson opens; the setup's lock in place of the one before.
    playback_ = std::move(next);
    lock_ = std::set<std::string>(options.lock.begin(), options.lock.end());
    setups_.lock_from = options.lock_from;
    // The setup's predictions, never the last lesson's; asked or not as it says (else as before).
    predictions_.predictions = options.predictions;
    window_.predictions = options.window.predictions;
    forget_interaction();
    mystery_.begin(std::move(mystery));
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

PreparedSetup SetupPanel::of_window(const std::string& path, const lessons::Lesson& lesson, const std::set<std::string>& lock,
                                   const MysteryPanel& mystery, bool ask_predictions, const ClassPredictions& predictions) {
  PreparedSetup setup;
  setup.lesson = setup_lesson_name(lesson.path(), path);
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    // A mystery is saved as its pair and seed: its values are drawn again when it opens.
    if (mystery.holds(parameter.name)) continue;
    setup.values.push_back({parameter.name, parameter_text(parameter), 0});
  }
  setup.lock.assign(lock.begin(), lock.end());
  if (mystery.mystery) setup.mystery = mystery.mystery->choice();
  setup.settings = lesson.settings();
  setup.ask_predictions = ask_predictions;
  // In the lesson's order; a box the class typed in and emptied again is no answer.
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    const auto answer = predictions.answers.find(prediction.expectation);
    if (answer != predictions.answers.end() && !answer->second.empty()) setup.answers.push_back({prediction.expectation, answer->second, 0});
  }
  setup.revealed = predictions.revealed;
  return setup;
}

std::string SetupPanel::save(const std::string& path, const PreparedSetup& setup, const lessons::Lesson& lesson) {
  try {
    // What the window marks as no number is refused here too: the file would not open again.
    for (const PreparedSetup::Answer& answer : setup.answers) {
      const std::string problem = prediction_problem(lesson, answer.row, answer.text);
      if (!problem.empty()) {
        throw InvalidInput(path + ": the class's prediction of " + answer.row + " is " + answer.text + ": " + problem +
                           "; correct it or clear it in the theory panel, then save");
      }
    }
    write_setup(path, setup);
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

PreparedSetup Classroom::current_setup(const std::string& path) const {
  return SetupPanel::of_window(path, playback_->lesson(), lock_, mystery_, window_.predictions, predictions_.predictions);
}

std::string Classroom::save_setup(const std::string& path) {
  std::string why = SetupPanel::save(path, current_setup(path), playback_->lesson());
  if (why.empty()) status_ = "Setup saved to " + path;
  return why;
}

}  // namespace frictionlab::ui
