// The mystery's part of the window (classroom/mystery_panel.h): making a pair a mystery, keeping it
// through rebuilds, the reveal and the class's answers (the menu and the tab that ask for them:
// classroom/mystery_tab.h). What stays hidden until the reveal is decided by hidden(), which
// every panel reads.
#include "classroom/mystery_panel.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "draw/panels.h"

namespace frictionlab::classroom {

std::unique_ptr<classroom_state::Playback> MysteryPanel::build_playback(const std::string& path, std::map<std::string, std::string> overrides,
                                                       const StepSettings& settings,
                                                       const std::optional<classroom_state::MysteryChoice>& choice,
                                                       std::optional<classroom_state::Mystery>& made) {
  auto playback = std::make_unique<classroom_state::Playback>(path, overrides, settings);
  if (!choice) return playback;
  // The pair is found in the lesson as built, then the lesson is built again with the drawn values.
  classroom_state::Mystery drawn(*choice, playback->lesson());
  for (const auto& [name, value] : drawn.settings()) {
    if (overrides.count(name) > 0) {
      throw InvalidInput("--set " + name + ": " + name + " is the mystery's (--mystery " + choice->pair + "); leave it out");
    }
    overrides[name] = value;
  }
  playback = std::make_unique<classroom_state::Playback>(path, overrides, settings);
  made = std::move(drawn);
  return playback;
}

void MysteryPanel::begin(std::optional<classroom_state::Mystery> opened) {
  mystery = std::move(opened);
  if (mystery) tab.begin();
}

std::string MysteryPanel::make(const classroom_state::MysteryChoice& choice, classroom_state::Playback& playback, ParametersPanel& parameters) {
  try {
    classroom_state::Mystery next(choice, playback.lesson());
    // μk first when it falls, so the pair never passes through μk > μs on the way (as the presets).
    std::vector<std::pair<std::string, double>> values = next.numbers();
    if (next.values().mu_k < playback.lesson().parameter(next.mu_k_name()).value) std::swap(values[0], values[1]);
    for (const auto& [name, value] : values) playback.set_parameter(name, value);
    // A fresh run with the new surface: nothing measured on the old one counts.
    playback.reset();
    mystery = std::move(next);
    tab.begin();
    parameters.errors.erase(mystery->mu_s_name());
    parameters.errors.erase(mystery->mu_k_name());
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

void MysteryPanel::keep(const std::string& name, double before, classroom_state::Playback& playback, ParametersPanel& parameters) const {
  if (!mystery) return;
  const lessons::Lesson& lesson = playback.lesson();
  try {
    if (classroom_state::mystery_parameters(lesson, mystery->choice().pair) != std::make_pair(mystery->mu_s_name(), mystery->mu_k_name())) {
      throw InvalidInput("another pair");
    }
  } catch (const InvalidInput&) {
    playback.set_parameter(name, before);
    parameters.errors[name] = "The mystery is " + mystery->choice().pair + ": this " + name +
                              " would take that pair away. Open the lesson again to end the mystery first.";
    return;
  }
  // A rebuild reads the pair's values from the script again: the drawn ones are put back.
  for (const auto& [coefficient, value] : mystery->numbers()) {
    if (lesson.parameter(coefficient).value != value) playback.set_parameter(coefficient, value);
  }
}

void MysteryPanel::reveal() {
  if (mystery) mystery->reveal();
}

void MysteryPanel::answer(std::optional<double> mu_s, std::optional<double> mu_k) {
  if (!mystery) return;
  mystery->answer_mu_s = mu_s;
  mystery->answer_mu_k = mu_k;
}

draw::HiddenValues MysteryPanel::hidden() const {
  draw::HiddenValues hidden;
  if (mystery) hidden.parameters = mystery->hidden();
  return hidden;
}

bool MysteryPanel::holds(const std::string& parameter) const {
  return mystery && (parameter == mystery->mu_s_name() || parameter == mystery->mu_k_name());
}

std::string MysteryPanel::title_words() const {
  if (!mystery) return "";
  return mystery->revealed() ? " (mystery revealed)" : " (a mystery surface)";
}

}  // namespace frictionlab::classroom
