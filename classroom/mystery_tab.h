// The Mystery tab and the Mystery menu: in the menu the teacher makes a pair a mystery (its seed
// typed there) or reveals it; in the tab the class types the μs and μk it measured, kept for the
// reveal and then judged beside the true values.
//
// It keeps its own state (the answers as typed, why one was refused, the seed) and draws
// itself, as each of Dear ImGui's demo windows does: the mystery panel (classroom/mystery_panel.h)
// holds one beside the mystery; the menu bar (classroom/menu_bar.h) calls draw_menu(), the
// classroom carries out what it chose, and calls draw_tab() inside the books' tab bar.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "classroom/control_places.h"
#include "classroom_state/mystery.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

// What the Mystery menu chose: a pair made a mystery (with the seed typed there), or the reveal.
struct MysteryMenuChoice {
  std::optional<classroom_state::MysteryChoice> make;
  bool reveal = false;
};

struct MysteryTab {
  char answer_text[2][32] = {};  // μs, μk as typed
  std::string answer_error[2];   // why a typed answer was refused
  int menu_seed = 1;
  bool select = false;           // a mystery just began: the tab (or the Predict tab) comes forward

  // A new mystery: no answers yet, and the tab comes forward.
  void begin();
  // The tab, in the tab bar being drawn: the answers go into `mystery`. `predicting`: the class's
  // predictions are asked and the theory kept back; a mystery just begun then leaves the
  // Predict tab in front when it shares this tab bar.
  void draw_tab(classroom_state::Mystery& mystery, bool predicting, const draw::Theme& colours, ControlPlaces& controls);
  // The Mystery menu in the menu bar being drawn, for `lesson` (its pairs whose μs and μk are
  // sliders) with `mystery` made or not. `lock_words`: why the teacher's lock keeps the class
  // from drawing a new one ("" when nothing is locked).
  MysteryMenuChoice draw_menu(const lessons::Lesson& lesson, const std::optional<classroom_state::Mystery>& mystery,
                              const std::string& lock_words, ControlPlaces& controls);
};

}  // namespace frictionlab::classroom
