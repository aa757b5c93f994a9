// The mystery's part of the window: the pair the teacher made a mystery (classroom_state/mystery.h),
// with its actions (make one, keep its values through a rebuild, reveal it, take the class's
// answers) and the Mystery menu and tab that draw it (classroom/mystery_tab.h).
//
// It owns the mystery, as each of Dear ImGui's demo windows owns its state: the classroom holds
// one, hands it the running lesson's Playback (and the Parameters panel, beside whose controls
// a refusal is shown) when it acts, and reads hidden() for every panel that must not show a
// mystery's values.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "classroom/mystery_tab.h"
#include "classroom/parameters_panel.h"
#include "classroom_state/mystery.h"
#include "classroom_state/playback.h"

namespace frictionlab::classroom {

struct MysteryPanel {
  std::optional<classroom_state::Mystery> mystery;  // chosen once when a mystery begins
  MysteryTab tab;

  // The lesson at `path` with `overrides`, and with a mystery's values when `choice` names one
  // (then made in `made`). Throws as Playback does, and InvalidInput for a pair the lesson
  // does not have or a value of the mystery's in `overrides`.
  static std::unique_ptr<classroom_state::Playback> build_playback(const std::string& path, std::map<std::string, std::string> overrides,
                                                  const StepSettings& settings, const std::optional<classroom_state::MysteryChoice>& choice,
                                                  std::optional<classroom_state::Mystery>& made);
  // The mystery a lesson opened with (the command line's, a setup's), or none: the tab asks anew.
  void begin(std::optional<classroom_state::Mystery> opened);
  // Makes a pair of the running lesson a mystery: its μs and μk drawn from the seed, hidden
  // until revealed, the lesson back at t = 0. Returns "" or why not (the lesson keeps running).
  std::string make(const classroom_state::MysteryChoice& choice, classroom_state::Playback& playback, ParametersPanel& parameters);
  // After `name` was set (from `before`): a rebuild keeps the mystery's values, and a value that
  // would take its pair away (a material chosen) is put back, with why beside its control.
  void keep(const std::string& name, double before, classroom_state::Playback& playback, ParametersPanel& parameters) const;
  void reveal();
  // The class's answers, as typed in the Mystery tab.
  void answer(std::optional<double> mu_s, std::optional<double> mu_k);
  // What the class must not see now.
  draw::HiddenValues hidden() const;
  // Whether the parameter is one of the mystery's pair (a setup saves the pair and seed instead).
  bool holds(const std::string& parameter) const;
  // What the window's title adds: " (a mystery surface)", " (mystery revealed)" or "".
  std::string title_words() const;
};

}  // namespace frictionlab::classroom
