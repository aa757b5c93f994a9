// The classroom's mystery surface: making a pair a mystery, keeping it through rebuilds, the
// reveal and the class's answers (the menu and the tab that ask for them: classroom/mystery_tab.h).
// What stays hidden until the reveal is decided by hidden_values(), which every panel reads.
#include <algorithm>

#include "classroom/classroom.h"
#include "draw/panels.h"

namespace frictionlab::ui {

std::string Classroom::make_mystery(const MysteryChoice& choice) {
  try {
    Mystery next(choice, playback_->lesson());
    // μk first when it falls, so the pair never passes through μk > μs on the way (as the presets).
    std::vector<std::pair<std::string, std::string>> settings = next.settings();
    if (next.values().mu_k < playback_->lesson().parameter(next.mu_k_name()).value) std::swap(settings[0], settings[1]);
    for (const auto& [name, value] : settings) playback_->set_parameter(name, value);
    // A fresh run with the new surface: nothing measured on the old one counts.
    playback_->reset();
    mystery_ = std::move(next);
    mystery_tab_.begin();
    parameters_.errors.erase(mystery_->mu_s_name());
    parameters_.errors.erase(mystery_->mu_k_name());
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

void Classroom::keep_mystery(const std::string& name, const std::string& before) {
  if (!mystery_) return;
  const lessons::Lesson& lesson = playback_->lesson();
  try {
    if (mystery_parameters(lesson, mystery_->choice().pair) != std::make_pair(mystery_->mu_s_name(), mystery_->mu_k_name())) {
      throw InvalidInput("another pair");
    }
  } catch (const InvalidInput&) {
    playback_->set_parameter(name, before);
    parameters_.errors[name] = "The mystery is " + mystery_->choice().pair + ": this " + name +
                            " would take that pair away. Open the lesson again to end the mystery first.";
    return;
  }
  // A rebuild reads the pair's values from the script again: the drawn ones are put back.
  for (const auto& [coefficient, value] : mystery_->settings()) {
    if (parameter_text(lesson.parameter(coefficient)) != value) playback_->set_parameter(coefficient, value);
  }
}

void Classroom::reveal_mystery() {
  if (mystery_) mystery_->reveal();
}

void Classroom::answer_mystery(std::optional<double> mu_s, std::optional<double> mu_k) {
  if (!mystery_) return;
  mystery_->answer_mu_s = mu_s;
  mystery_->answer_mu_k = mu_k;
}

HiddenValues Classroom::hidden_values() const {
  HiddenValues hidden;
  if (mystery_) hidden.parameters = mystery_->hidden();
  return hidden;
}

std::string Classroom::window_title() const {
  std::string title = "FrictionLab: " + playback_->lesson().title();
  if (mystery_) title += mystery_->revealed() ? " (mystery revealed)" : " (a mystery surface)";
  return title;
}

}  // namespace frictionlab::ui
