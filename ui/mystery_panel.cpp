// The classroom's mystery surface: the Mystery menu where the teacher makes a pair a mystery or
// reveals it, and the Mystery tab where the class types what it measured and sees how far off
// it is. What stays hidden until the reveal is decided by hidden_values(), which every panel reads.
#include <algorithm>
#include <cstdio>

#include "physics/validation.h"
#include "ui/classroom.h"
#include "ui/panels.h"
#include "ui/text_record.h"

namespace frictionlab::ui {
namespace {

const char* const coefficient_letters[2] = {"\u03bcs", "\u03bck"};

}  // namespace

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
    for (int k = 0; k < 2; ++k) {
      answer_text_[k][0] = '\0';
      answer_error_[k].clear();
    }
    control_errors_.erase(mystery_->mu_s_name());
    control_errors_.erase(mystery_->mu_k_name());
    select_mystery_tab_ = true;
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
    control_errors_[name] = "The mystery is " + mystery_->choice().pair + ": this " + name +
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

void Classroom::mystery_menu() {
  const bool open = ImGui::BeginMenu("Mystery");
  remember("Mystery menu");
  if (!open) return;
  const std::vector<std::string> pairs = mystery_pairs(playback_->lesson());
  if (pairs.empty()) {
    ImGui::TextDisabled("This lesson has no friction pair whose \u03bcs and \u03bck are sliders.");
  } else {
    ImGui::TextDisabled("Seed (the same seed draws the same values)");
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("0000000").x + 2.0f * ImGui::GetFrameHeight());
    ImGui::InputInt("##seed", &menu_seed_);
    remember("mystery seed");
    menu_seed_ = std::clamp(menu_seed_, 0, static_cast<int>(mystery_seed_max));
    for (const std::string& pair : pairs) {
      const bool current = mystery_ && mystery_->choice().pair == pair;
      const std::string label = "Make " + pair + " a mystery";
      if (ImGui::MenuItem(label.c_str(), nullptr, current)) {
        status_ = make_mystery({pair, static_cast<std::uint64_t>(menu_seed_)});
      }
      remember("mystery " + pair);
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Reveal the true values", nullptr, false, mystery_ && !mystery_->revealed())) reveal_mystery();
    remember("mystery reveal menu");
  }
  ImGui::EndMenu();
}

void Classroom::mystery_tab() {
  if (!mystery_) return;
  const bool open = begin_tab("Mystery###mystery", select_mystery_tab_ ? ImGuiTabItemFlags_SetSelected : 0);
  select_mystery_tab_ = false;
  remember("Mystery tab");
  if (!open) return;
  Mystery& mystery = *mystery_;
  const Theme& colours = theme(window_.theme);
  ImGui::PushTextWrapPos(0.0f);
  // Not the seed: with it a student could draw the values at home. Short: in projector mode
  // the column shows four lines of a tab before it scrolls, and the reveal must be among them.
  const std::string heading = "Measure \u03bcs and \u03bck of " + mystery.choice().pair + ":";
  shown_text(heading.c_str());
  const double truths[2] = {mystery.values().mu_s, mystery.values().mu_k};
  std::optional<double>* answers[2] = {&mystery.answer_mu_s, &mystery.answer_mu_k};
  const ImGuiStyle& style = ImGui::GetStyle();
  const float box = ImGui::CalcTextSize("0.0000").x + 2.0f * style.FramePadding.x;
  for (int k = 0; k < 2; ++k) {
    ImGui::PushID(k);
    ImGui::AlignTextToFramePadding();
    shown_text(coefficient_letters[k]);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(box);
    const bool entered = ImGui::InputText("##answer", answer_text_[k], sizeof answer_text_[k],
                                          ImGuiInputTextFlags_CharsDecimal | ImGuiInputTextFlags_EnterReturnsTrue);
    remember(std::string("mystery answer ") + (k == 0 ? "mu_s" : "mu_k"));
    if (entered || ImGui::IsItemDeactivatedAfterEdit()) {
      std::string why;
      const std::string typed = answer_text_[k];
      const std::optional<double> value = typed.empty() ? std::nullopt : validation::parse_decimal(typed, why);
      answer_error_[k].clear();
      if (!typed.empty() && !(value && *value >= 0.0 && *value <= 2.0)) {
        answer_error_[k] = "type a number from 0 to 2, as 0.45";
        answers[k]->reset();
      } else {
        *answers[k] = value;
      }
    }
    ImGui::SameLine();
    // How far off, once revealed, with the true value beside it. Not before: a class told how
    // far off each guess is finds the hidden value in two guesses.
    std::string said = !answers[k]->has_value() ? "not yet"
                       : mystery.revealed()     ? closeness_text(**answers[k], truths[k])
                                                : "kept for the reveal";
    if (mystery.revealed()) said += (answers[k]->has_value() ? ", true " : ", true value ") + exact_text(truths[k]);
    if (!answer_error_[k].empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, colours.bad);
      shown_text(answer_error_[k].c_str());
      ImGui::PopStyleColor();
    } else if (answers[k]->has_value() || mystery.revealed()) {
      shown_text(said.c_str());
    } else {
      ImGui::TextDisabled("%s", said.c_str());
      note_text(said.c_str());
    }
    ImGui::PopID();
  }
  if (!mystery.revealed()) {
    // At the end of the μk line when it has room.
    const char* reveal = "Reveal";
    const float button = ImGui::CalcTextSize(reveal).x + 2.0f * style.FramePadding.x;
    const float after = ImGui::GetItemRectMax().x + 2.0f * style.ItemSpacing.x;
    if (after + button <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
      ImGui::SameLine(after - ImGui::GetWindowPos().x);
    }
    if (ImGui::Button(reveal)) reveal_mystery();
    remember("mystery reveal");
    note_text_centred(reveal, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
  }
  ImGui::PopTextWrapPos();
  ImGui::EndTabItem();
}

}  // namespace frictionlab::ui
