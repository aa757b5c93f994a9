// The Mystery menu and tab (classroom/mystery_tab.h).
#include "classroom/mystery_tab.h"

#include <algorithm>
#include <cstdio>

#include "classroom/text_boxes.h"
#include "draw/panels.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"
#include "physics/materials.h"
#include "physics/validation.h"

namespace frictionlab::classroom {
namespace {

// What an answer's line says for a value out of range.
constexpr const char* answer_refused = "type a number from 0 to 2, as 0.45";

// The pair's two coefficients, as the pair table names them (physics/materials.h).
const PairCoefficient* const coefficients[2] = {&static_coefficient, &kinetic_coefficient};

// "μs and μk", as every other panel writes them.
std::string both_letters() {
  return lessons::class_words(static_coefficient.name) + " and " + lessons::class_words(kinetic_coefficient.name);
}

// The theory's tab in the tab bar being drawn, when it was drawn there this frame: a column too
// short for the theory's own panel puts it first among the tabs (draw/frame.cpp names it
// "Predict###theory tab" while the class predicts; a tab's id is made from what follows "###").
ImGuiTabItem* theory_tab_beside() {
  ImGuiTabBar* bar = ImGui::GetCurrentContext()->CurrentTabBar;
  if (bar == nullptr) return nullptr;
  ImGuiTabItem* tab = ImGui::TabBarFindTabByID(bar, ImGui::GetID("###theory tab"));
  return tab != nullptr && tab->LastFrameVisible == ImGui::GetFrameCount() ? tab : nullptr;
}

}  // namespace

void MysteryTab::begin() {
  for (int k = 0; k < 2; ++k) {
    answer_text[k][0] = '\0';
    answer_error[k].clear();
  }
  select = true;
}

MysteryMenuChoice MysteryTab::draw_menu(const lessons::Lesson& lesson, const std::optional<classroom_state::Mystery>& mystery,
                                        const std::string& lock_words, ControlPlaces& controls) {
  MysteryMenuChoice choice;
  const bool open = ImGui::BeginMenu("Mystery");
  remember_item(controls, "Mystery menu");
  if (!open) return choice;
  const std::vector<std::string> pairs = classroom_state::mystery_pairs(lesson);
  if (pairs.empty()) {
    const std::string none =
        "This lesson has no friction pair whose " + both_letters() + " are sliders.";
    ImGui::TextDisabled("%s", none.c_str());
  } else {
    // A new mystery changes a pair's values: under the teacher's lock the class cannot draw one
    // (the trial's locked setup still let a student replace its mystery). The reveal stays the
    // teacher's, as T's reveal of the theory does.
    const std::string& locked = lock_words;
    if (!locked.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 24.0f * ImGui::GetFontSize());
      ImGui::TextDisabled("%s", locked.c_str());
      draw::note_text(locked.c_str());
      ImGui::PopTextWrapPos();
      ImGui::Separator();
    }
    ImGui::BeginDisabled(!locked.empty());
    // The seed of the next mystery drawn, never the current one's: with that a student could
    // draw the values at home (a teacher read 1 here for a mystery drawn with 42).
    ImGui::TextDisabled("Seed for a new mystery (the same seed draws the same values)");
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("0000000").x + 2.0f * ImGui::GetFrameHeight());
    ImGui::InputInt("##seed", &menu_seed);
    takes_a_number();
    remember_item(controls, "mystery seed");
    menu_seed = std::clamp(menu_seed, 0, static_cast<int>(classroom_state::mystery_seed_max));
    for (const std::string& pair : pairs) {
      const bool current = mystery && mystery->choice().pair == pair;
      const std::string label = "Make " + pair + " a mystery";
      if (ImGui::MenuItem(label.c_str(), nullptr, current)) {
        choice.make = classroom_state::MysteryChoice{pair, static_cast<std::uint64_t>(menu_seed)};
      }
      remember_item(controls, "mystery " + pair);
    }
    ImGui::EndDisabled();
    ImGui::Separator();
    if (ImGui::MenuItem("Reveal the true values", nullptr, false, mystery && !mystery->revealed())) choice.reveal = true;
    remember_item(controls, "mystery reveal menu");
  }
  ImGui::EndMenu();
  return choice;
}

void MysteryTab::draw_tab(classroom_state::Mystery& mystery, bool predicting, const draw::Theme& colours, ControlPlaces& controls) {
  ImGuiTabItemFlags flags = 0;
  if (select) {
    // The class predicts before it measures: while the predictions are asked and their tab is
    // beside this one, that tab comes forward (whatever tab the last lesson left open), not this.
    if (ImGuiTabItem* predict = predicting ? theory_tab_beside() : nullptr) {
      ImGui::GetCurrentContext()->CurrentTabBar->NextSelectedTabId = predict->ID;
    } else {
      flags = ImGuiTabItemFlags_SetSelected;
    }
    select = false;
  }
  const bool open = draw::begin_tab("Mystery###mystery", flags);
  remember_item(controls, "Mystery tab");
  if (!open) return;
  ImGui::PushTextWrapPos(0.0f);
  // Not the seed: with it a student could draw the values at home. Short: in projector mode
  // the column shows four lines of a tab before it scrolls, and the reveal must be among them.
  // The pair's materials stay, but not their book values: a class that knows wood on wood's
  // would be misled (the trial's class was).
  const std::string heading = "Measure " + both_letters() + " of the mystery " +
                              mystery.choice().pair +
                              " surface (its values drawn at random, not the book's):";
  draw::shown_text(heading.c_str());
  const double truths[2] = {mystery.values().mu_s, mystery.values().mu_k};
  std::optional<double>* answers[2] = {&mystery.answer_mu_s, &mystery.answer_mu_k};
  const ImGuiStyle& style = ImGui::GetStyle();
  const float box = ImGui::CalcTextSize("0.0000").x + 2.0f * style.FramePadding.x;
  float answer_box_end = 0.0f;  // the μk box's right edge: what the reveal's place is measured from
  for (int k = 0; k < 2; ++k) {
    ImGui::PushID(k);
    ImGui::AlignTextToFramePadding();
    draw::shown_text(lessons::class_words(coefficients[k]->name).c_str());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(box);
    const bool entered = ImGui::InputText("##answer", answer_text[k], sizeof answer_text[k],
                                          ImGuiInputTextFlags_CharsDecimal | ImGuiInputTextFlags_EnterReturnsTrue);
    takes_a_number();
    remember_item(controls, std::string("mystery answer ") + coefficients[k]->name);
    answer_box_end = ImGui::GetItemRectMax().x;
    if (entered || ImGui::IsItemDeactivatedAfterEdit()) {
      std::string why;
      const std::string typed = answer_text[k];
      const std::optional<double> value = typed.empty() ? std::nullopt : validation::parse_decimal(typed, why);
      answer_error[k].clear();
      if (!typed.empty() && !(value && *value >= 0.0 && *value <= 2.0)) {
        answer_error[k] = answer_refused;
        answers[k]->reset();
      } else {
        *answers[k] = value;
      }
    }
    ImGui::SameLine();
    // How far off, once revealed, with the true value beside it. Not before: a class told how
    // far off each guess is finds the hidden value in two guesses.
    std::string said = !answers[k]->has_value() ? "not yet"
                       : mystery.revealed()     ? classroom_state::closeness_text(**answers[k], truths[k])
                                                : "kept for the reveal";
    if (mystery.revealed()) said += (answers[k]->has_value() ? ", true " : ", true value ") + validation::exact_text(truths[k]);
    if (!answer_error[k].empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, colours.bad);
      draw::shown_text(answer_error[k].c_str());
      ImGui::PopStyleColor();
    } else if (answers[k]->has_value() || mystery.revealed()) {
      draw::shown_text(said.c_str());
    } else {
      ImGui::TextDisabled("%s", said.c_str());
      draw::note_text(said.c_str());
    }
    ImGui::PopID();
  }
  if (!mystery.revealed()) {
    // At the end of the μk line when it has room, past the widest word that line can show, so
    // that it keeps its place while answers are typed: placed after the word shown, it moved
    // right as "not yet" became "kept for the reveal", and a teacher's click landed on the text.
    const char* reveal = "Reveal";
    const float button = ImGui::CalcTextSize(reveal).x + 2.0f * style.FramePadding.x;
    float widest = 0.0f;
    for (const char* word : {"not yet", "kept for the reveal", answer_refused}) {
      widest = std::max(widest, ImGui::CalcTextSize(word).x);
    }
    const float after = answer_box_end + style.ItemSpacing.x + widest + 2.0f * style.ItemSpacing.x;
    if (after + button <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
      ImGui::SameLine(after - ImGui::GetWindowPos().x);
    }
    if (ImGui::Button(reveal)) mystery.reveal();
    remember_item(controls, "mystery reveal");
    draw::note_text_centred(reveal, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
  }
  ImGui::PopTextWrapPos();
  ImGui::EndTabItem();
}

}  // namespace frictionlab::classroom
