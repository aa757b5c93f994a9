// The Parameters panel (classroom/parameters_panel.h): the parameters as sliders with a box for
// typed values and a reset, material presets for a friction pair, giving way to a short column.
#define IMGUI_DEFINE_MATH_OPERATORS
#include "classroom/parameters_panel.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "classroom/knob_slider.h"
#include "classroom/text_boxes.h"
#include "classroom_state/playback.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"
#include "physics/materials.h"
#include "physics/validation.h"

namespace frictionlab::classroom {

std::string control_label(const lessons::Parameter& parameter) {
  if (const PairCoefficient* coefficient = parameter.coefficient) {
    return lessons::class_words(coefficient->name) + " " + coefficient->word;
  }
  return lessons::class_words(parameter.name);
}

std::string refusal_in_class_words(const lessons::Parameter& parameter, const std::string& error) {
  const std::string script_words = parameter.name + " = ";
  if (error.rfind(script_words, 0) != 0) return error;
  return control_label(parameter) + " = " + error.substr(script_words.size());
}

namespace {

struct Preset {
  std::string label;
  FrictionPair values;
};

// The seed articles' pairs, as the presets table has them.
const std::vector<Preset>& presets() {
  static const std::vector<Preset> list = [] {
    std::vector<Preset> found;
    const PairTable table = preset_table();
    for (int a = 0; a < table.material_count(); ++a) {
      for (int b = a; b < table.material_count(); ++b) {
        if (!table.has_pair(a, b)) continue;
        const FrictionPair& pair = table.pair(a, b);
        char label[160];
        std::snprintf(label, sizeof label, "%s on %s: \u03bcs %.2f, \u03bck %.2f", table.material(a).name.c_str(),
                      table.material(b).name.c_str(), pair.mu_s, pair.mu_k);
        found.push_back({label, pair});
      }
    }
    return found;
  }();
  return list;
}

// A pair's coefficient by its letter alone, for two sliders a row.
std::string coefficient_letter(const lessons::Parameter& parameter) {
  return lessons::class_words(parameter.coefficient == nullptr ? parameter.name : parameter.coefficient->name);
}

// A combo box's shown choice, left in its frame before the arrow button.
void note_combo(const char* preview) {
  const ImVec2 padding = ImGui::GetStyle().FramePadding;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  draw::note_text_in(preview, ImVec2(min.x + padding.x, min.y + padding.y),
               ImRect(min, ImVec2(max.x - ImGui::GetFrameHeight(), max.y)));
}

}  // namespace

// Each row: the name, the slider, a box for a typed value, and a reset; a friction pair's
// rows come under a heading with its material presets.
// The names' column is as wide as the widest name, within a third and 45 % of the panel.
struct ControlColumns {
  float slider, value, reset, end;
  static ControlColumns of(float width, float scale, float widest_name) {
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    ControlColumns columns;
    columns.end = width;
    columns.reset = width - ImGui::GetFrameHeight();
    columns.value = columns.reset - spacing - 72.0f * scale;
    // Offsets count from the panel's left edge (ImGui::SameLine), the names from its padding.
    const float names_end = ImGui::GetStyle().WindowPadding.x + widest_name + spacing;
    columns.slider = std::clamp(names_end, std::min(0.3f * width, 120.0f * scale), 0.45f * width);
    return columns;
  }
};

std::vector<std::string> ParametersPanel::foldable_pairs(const ParametersOnShow& on_show, bool opened_too) const {
  std::vector<std::string> pairs;
  for (const lessons::Parameter& parameter : on_show.lesson.parameters()) {
    const std::string pair = draw::pair_of(parameter);
    if (pair.empty() || !unlocked(on_show.lock, parameter.name)) continue;
    const auto choice = pair_open.find(pair);
    if (choice != pair_open.end() && !(opened_too && choice->second)) continue;
    if (std::find(pairs.begin(), pairs.end(), pair) == pairs.end()) pairs.push_back(pair);
  }
  return pairs;
}

std::vector<ParametersPanel::Row> ParametersPanel::rows_at(const ParametersOnShow& on_show, std::size_t step) const {
  // Pairs the teacher opened still go two a row; only those left to the layout fold.
  const std::vector<std::string> compact = foldable_pairs(on_show, true), foldable = foldable_pairs(on_show, false);
  const std::size_t two_a_row = std::min(step, compact.size());
  const std::size_t folded = step > compact.size() ? std::min(step - compact.size(), foldable.size()) : 0;
  // Whether a pair is among the last `count` of `pairs`.
  const auto among_last = [](const std::vector<std::string>& pairs, const std::string& pair, std::size_t count) {
    const auto at = std::find(pairs.begin(), pairs.end(), pair);
    return at != pairs.end() && static_cast<std::size_t>(at - pairs.begin()) >= pairs.size() - count;
  };
  std::vector<Row> rows;
  std::string last_pair;
  for (const lessons::Parameter& parameter : on_show.lesson.parameters()) {
    if (!unlocked(on_show.lock, parameter.name)) continue;
    const std::string pair = draw::pair_of(parameter);
    const bool heading = !pair.empty() && pair != last_pair;
    if (heading) last_pair = pair;
    Row row{&parameter, nullptr, heading, false, false};
    if (!pair.empty()) {
      // The teacher's own choice first; then the layout's step.
      const auto choice = pair_open.find(pair);
      row.folded = choice != pair_open.end() ? !choice->second : among_last(foldable, pair, folded);
      row.two_a_row = !row.folded && among_last(compact, pair, two_a_row);
    }
    // A folded pair is its heading alone, its values on that line.
    if (row.folded && !heading) continue;
    // The second of two coefficients shares the row of the first.
    if (row.two_a_row && !heading && !rows.empty() && rows.back().two_a_row && rows.back().partner == nullptr &&
        draw::pair_of(*rows.back().parameter) == pair) {
      rows.back().partner = &parameter;
      continue;
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<float> ParametersPanel::heights(const ParametersOnShow& on_show) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  std::vector<float> heights;
  for (std::size_t step = 0; step <= foldable_pairs(on_show, true).size() + foldable_pairs(on_show, false).size(); ++step) {
    int rows = on_show.lock.empty() ? 0 : 1;
    // A refused value's message takes no row: it is said over the rows (say_refusals).
    for (const Row& row : rows_at(on_show, step)) rows += 1 + (row.pair_heading && !row.folded ? 1 : 0);
    heights.push_back(ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y +
                      static_cast<float>(rows) * ImGui::GetFrameHeightWithSpacing());
  }
  // Folded away: its heading alone, a line with the arrow that opens it.
  if (may_fold_away(on_show)) heights.push_back(ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y);
  return heights;
}

void ParametersPanel::forget() {
  errors.clear();
  pair_open.clear();
  opened = false;
  sliding.reset();
}

bool ParametersPanel::may_fold_away(const ParametersOnShow& on_show) const {
  // A pair the teacher opened is wanted in sight: the panel does not fold away around it.
  const bool pair_opened = std::any_of(pair_open.begin(), pair_open.end(), [](const auto& choice) { return choice.second; });
  return on_show.answers_asked && !opened && !pair_opened;
}

std::size_t ParametersPanel::folded_away_step(const ParametersOnShow& on_show) const {
  return foldable_pairs(on_show, true).size() + foldable_pairs(on_show, false).size() + 1;
}

void ParametersPanel::draw_folded_away(ImVec2 corner, ImVec2 size, const ParametersOnShow& on_show, ControlPlaces& controls) {
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar;
  if (ImGui::Begin("###parameters", nullptr, flags)) {
    // As a friction pair folds: an arrow before the heading, the heading, and why it is folded.
    if (ImGui::ArrowButton("##open parameters", ImGuiDir_Right)) opened = true;
    remember_item(controls, "parameters open");
    ImGui::SameLine();
    ImGui::AlignTextToFramePadding();
    draw::shown_text("Parameters");
    // Why, when the line holds it: the arrow and the heading say enough alone.
    const char* why = on_show.lock.empty() ? "folded for the class's answers" : "chosen by the teacher, folded";
    ImGui::SameLine();
    if (ImGui::CalcTextSize(why).x <= ImGui::GetContentRegionAvail().x) {
      ImGui::TextDisabled("%s", why);
      draw::note_text(why);
    }
  }
  ImGui::End();
}

void ParametersPanel::draw(ImVec2 corner, ImVec2 size, std::size_t step, const ParametersOnShow& on_show, float scale,
                           const draw::Theme& colours, ControlPlaces& controls) {
  // A refusal is said until the teacher's next click, wherever it lands (the box again to type
  // anew, the reset, the message itself): they have read it, and it no longer covers the rows
  // under it. A value taken ends it too (Classroom::apply_asked_values).
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right)) errors.clear();
  if (may_fold_away(on_show) && step >= folded_away_step(on_show)) {
    draw_folded_away(corner, size, on_show, controls);
    say_refusals(ImVec2(corner.x, corner.y + size.y), size.x, colours);
    return;
  }
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  const std::string title = on_show.lock.empty() ? "Parameters###parameters" : "Parameters (chosen by the teacher)###parameters";
  // Under the row of the first value refused; under the panel's title when that row is not
  // shown (folded into its pair's heading, or under the teacher's lock).
  std::optional<float> refused_row_foot;
  float title_foot = corner.y;
  if (ImGui::Begin(title.c_str(), nullptr, flags)) {
    draw::note_title(title.substr(0, title.find("###")).c_str());
    title_foot = ImGui::GetWindowPos().y + ImGui::GetCurrentWindowRead()->TitleBarHeight();
    const std::vector<Row> shown_rows = rows_at(on_show, step);
    float widest_name = 0.0f, widest_letter = 0.0f;
    for (const Row& row : shown_rows) {
      if (row.folded) continue;
      for (const lessons::Parameter* shown : {row.parameter, row.partner}) {
        if (shown == nullptr) continue;
        float& widest = row.two_a_row ? widest_letter : widest_name;
        widest = std::max(widest, ImGui::CalcTextSize((row.two_a_row ? coefficient_letter(*shown) : control_label(*shown)).c_str()).x);
      }
    }
    const float width = ImGui::GetContentRegionAvail().x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const ControlColumns columns = ControlColumns::of(width, scale, widest_name);
    for (const Row& row : shown_rows) {
      const lessons::Parameter& parameter = *row.parameter;
      if (row.pair_heading) {
        // The pair's heading, with an arrow that folds its sliders into the line or opens them.
        const std::string pair = draw::pair_of(parameter);
        ImGui::PushID(pair.c_str());
        if (ImGui::ArrowButton("##fold", row.folded ? ImGuiDir_Right : ImGuiDir_Down)) pair_open[pair] = row.folded;
        remember_item(controls, pair + " fold");
        ImGui::PopID();
        ImGui::SameLine();
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("%s", pair.c_str());
        draw::note_text(pair.c_str());
        if (row.folded) {
          const std::string values = pair_values(on_show.lesson, pair, on_show.hidden);
          ImGui::SameLine();
          ImGui::TextUnformatted(values.c_str());
          draw::note_text(values.c_str());
          // A coefficient of the folded pair refused (a mystery's): said under its heading.
          for (const lessons::Parameter& coefficient : on_show.lesson.parameters()) {
            if (!refused_row_foot && draw::pair_of(coefficient) == pair && errors.count(coefficient.name) > 0) {
              refused_row_foot = ImGui::GetItemRectMax().y;
            }
          }
          continue;
        }
        if (parameter.coefficient == &static_coefficient) {
          ImGui::SameLine();
          ImGui::SetNextItemWidth(-FLT_MIN);
          preset_row(parameter, on_show, controls);
        }
      }
      if (row.two_a_row) {
        // Two coefficients a row, each its letter, slider and reset; a value is typed with
        // Ctrl+click on its slider.
        const float half = 0.5f * (width - spacing);
        for (int side = 0; side < 2; ++side) {
          const lessons::Parameter* shown = side == 0 ? row.parameter : row.partner;
          if (shown == nullptr) continue;
          // Offsets from the panel's left edge, as ImGui::SameLine takes them.
          const float start = ImGui::GetStyle().WindowPadding.x + (side == 0 ? 0.0f : half + spacing);
          const float reset = start + half - ImGui::GetFrameHeight();
          ImGui::PushID(shown->name.c_str());
          parameter_row(*shown, coefficient_letter(*shown), side == 0 ? 0.0f : start, start + widest_letter + spacing,
                        reset, reset, on_show, controls);
          ImGui::PopID();
        }
      } else {
        ImGui::PushID(parameter.name.c_str());
        parameter_row(parameter, control_label(parameter), 0.0f, columns.slider, columns.value, columns.reset, on_show,
                      controls);
        ImGui::PopID();
      }
      for (const lessons::Parameter* shown : {row.parameter, row.partner}) {
        if (shown != nullptr && !refused_row_foot && errors.count(shown->name) > 0) refused_row_foot = ImGui::GetItemRectMax().y;
      }
    }
    if (!on_show.lock.empty()) {
      const char* locked = "Only the controls the teacher chose are shown.";
      ImGui::TextDisabled("%s", locked);
      draw::note_text(locked);
    }
  }
  ImGui::End();
  say_refusals(ImVec2(corner.x, refused_row_foot.value_or(title_foot)), size.x, colours);
}

void ParametersPanel::say_refusals(ImVec2 corner, float width, const draw::Theme& colours) const {
  if (errors.empty()) return;
  // Over the panel's rows, as wide as the panel, as high as the words wrapped in it: nothing
  // gives way for it (issue 31: the message under its row folded the friction pairs and moved
  // the Predict tab 105 px down). A click on it only ends it: passed through, the click a
  // teacher gives the message to dismiss it set the slider under it (a knob takes a click).
  const ImGuiStyle& style = ImGui::GetStyle();
  // Broken between words: ImGui's wrapping broke the range "[0.1, 5]" after its point.
  std::vector<std::string> said;
  for (const auto& [name, error] : errors) {
    std::string lines;
    for (const std::string& line : draw::lines_that_fit(error, width - 2.0f * style.WindowPadding.x, 8)) {
      lines += (lines.empty() ? "" : "\n") + line;
    }
    said.push_back(std::move(lines));
  }
  float height = 2.0f * style.WindowPadding.y - style.ItemSpacing.y;
  for (const std::string& lines : said) height += ImGui::CalcTextSize(lines.c_str()).y + style.ItemSpacing.y;
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::PushStyleColor(ImGuiCol_Border, colours.bad);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, std::max(1.0f, std::round(0.1f * ImGui::GetFontSize())));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("###refused", nullptr, flags)) {
    // Over the panels drawn after the Parameters panel too (the tabs under it).
    ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
    for (const std::string& lines : said) {
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colours.bad), "%s", lines.c_str());
      draw::note_text(lines.c_str());
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
}

void ParametersPanel::preset_row(const lessons::Parameter& mu_s, const ParametersOnShow& on_show, ControlPlaces& controls) {
  // "" or "name.", before the coefficient's own name.
  const std::string prefix = mu_s.name.substr(0, mu_s.name.size() - std::strlen(mu_s.coefficient->name));
  const std::string mu_k = prefix + kinetic_coefficient.name;
  // A mystery's pair takes no presets: choosing one would end the mystery without a reveal.
  if (!unlocked(on_show.lock, mu_k) || (on_show.mystery && on_show.mystery->hides(mu_s.name))) {
    ImGui::NewLine();
    return;
  }
  ImGui::PushID(mu_s.name.c_str());
  // As much of the name as the box holds.
  const float room = ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2.0f * ImGui::GetStyle().FramePadding.x;
  const char* preview = "material presets (seed tables)\u2026";
  for (const char* shorter : {"material presets\u2026", "presets\u2026"}) {
    if (ImGui::CalcTextSize(preview).x > room) preview = shorter;
  }
  const bool open = ImGui::BeginCombo("##preset", preview);
  note_combo(preview);
  if (open) {
    for (const Preset& preset : presets()) {
      if (ImGui::Selectable(preset.label.c_str())) {
        // mu_k first when it falls, so the pair never passes through mu_k > mu_s on the way.
        const bool falling = preset.values.mu_k < on_show.lesson.parameter(mu_k).value;
        const std::pair<std::string, lessons::GivenValue> s_value{mu_s.name, {"", preset.values.mu_s}};
        const std::pair<std::string, lessons::GivenValue> k_value{mu_k, {"", preset.values.mu_k}};
        asked.push_back(falling ? k_value : s_value);
        asked.push_back(falling ? s_value : k_value);
      }
    }
    ImGui::EndCombo();
  }
  remember_item(controls, mu_s.name + " presets");
  ImGui::PopID();
}

namespace {

// A control's name, from `label_x` (0: the row's start), ending before its slider at `slider_x`
// from the panel's edge; hovered, the parameter's words, name, range and where the script sets it.
void name_label(const lessons::Parameter& parameter, const std::string& label, float label_x, float slider_x) {
  // The second control of a row goes on the same line, from its own start.
  if (label_x > 0.0f) ImGui::SameLine(label_x);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(label.c_str());
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  draw::note_text_in(label.c_str(), min, ImRect(min, ImVec2(ImGui::GetWindowPos().x + slider_x, max.y)));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s (%s)\nfrom %s to %s%s; the script gives %s\n%s", parameter.text.c_str(), parameter.name.c_str(),
                      validation::exact_text(parameter.min).c_str(), validation::exact_text(parameter.max).c_str(),
                      parameter.unit.empty() ? "" : (" " + parameter.unit).c_str(),
                      validation::exact_text(parameter.default_value).c_str(), parameter.declared_at.c_str());
  }
}

}  // namespace

void ParametersPanel::choice_list(const lessons::Parameter& parameter, ControlPlaces& controls) {
  const std::string& chosen = parameter.choices[static_cast<std::size_t>(parameter.value)];
  const bool open = ImGui::BeginCombo("##choice", chosen.c_str());
  note_combo(chosen.c_str());
  if (open) {
    for (std::size_t place = 0; place < parameter.choices.size(); ++place) {
      const std::string& choice = parameter.choices[place];
      if (ImGui::Selectable(choice.c_str(), choice == chosen) && choice != chosen) {
        asked.push_back({parameter.name, {"", static_cast<double>(place)}});
      }
      remember_item(controls, parameter.name + " choice " + choice);
    }
    ImGui::EndCombo();
  }
  remember_item(controls, parameter.name + " slider");
}

void ParametersPanel::value_slider(const lessons::Parameter& parameter, ControlPlaces& controls) {
  const std::string& name = parameter.name;
  const bool sliding_this = sliding && sliding->first == name;
  double value = sliding_this ? sliding->second : parameter.value;
  // A unit is text, not format: a script's "%" is written "%%".
  std::string unit;
  for (const char c : parameter.unit) unit += c == '%' ? std::string("%%") : std::string(1, c);
  const std::string format = "%.3g" + (unit.empty() ? "" : " " + unit);
  // A wide range (0 to 1000 N·s/m) is easier to set on a logarithmic scale.
  const bool wide = parameter.max > 10.0 && parameter.max >= 100.0 * std::max(parameter.min, 1e-9);
  const bool moved = knob_slider("##slider", ImGuiDataType_Double, &value, &parameter.min, &parameter.max, format.c_str(),
                                 wide ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None, controls, name + " slider");
  if (moved) value = round_slider_value(value, parameter.min, parameter.max, ImGui::GetItemRectSize().x, wide);
  {
    char shown[96];
    std::snprintf(shown, sizeof shown, format.c_str(), value);
    draw::note_text_centred(shown, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
  }
  if (moved) {
    // A value the scene is built from restarts the lesson: wait until the slider is let go.
    if (parameter.structural) {
      sliding = {name, value};
    } else {
      asked.push_back({name, {"", value}});
    }
  }
  if (ImGui::IsItemDeactivated() && sliding && sliding->first == name) {
    asked.push_back({name, {"", sliding->second}});
    sliding.reset();
  }
}

void ParametersPanel::typed_value(const lessons::Parameter& parameter, ControlPlaces& controls) {
  char typed[64];
  std::snprintf(typed, sizeof typed, "%s", lessons::parameter_text(parameter).c_str());
  // A number, read here (to say why "0,5" is refused): no blank joins it, and Space ends the
  // typing as Enter does and plays (classroom/text_boxes.h).
  if (ImGui::InputText("##value", typed, sizeof typed,
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll |
                           ImGuiInputTextFlags_CharsNoBlank)) {
    asked.push_back({parameter.name, {typed, std::nullopt}});
  }
  takes_a_number();
  remember_item(controls, parameter.name + " value");
  const ImVec2 padding = ImGui::GetStyle().FramePadding;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  draw::note_text_in(typed, ImVec2(min.x + padding.x, min.y + padding.y), ImRect(min, max));
  // Not over a refusal's message, which stands under the box the pointer is still on.
  if (ImGui::IsItemHovered() && errors.empty()) ImGui::SetTooltip("Type an exact value and press Enter");
}

void ParametersPanel::reset_button(const lessons::Parameter& parameter, ControlPlaces& controls) {
  ImGui::BeginDisabled(parameter.value == parameter.default_value);
  if (ImGui::Button("\u21ba", ImVec2(ImGui::GetFrameHeight(), 0.0f))) {
    asked.push_back({parameter.name, {"", parameter.default_value}});  // a choice's place, as its value is
  }
  ImGui::EndDisabled();
  remember_item(controls, parameter.name + " reset");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Back to the script's value, %s", validation::exact_text(parameter.default_value).c_str());
  }
}

void ParametersPanel::parameter_row(const lessons::Parameter& parameter, const std::string& label, float label_x,
                                    float slider_x, float value_x, float reset_x, const ParametersOnShow& on_show,
                                    ControlPlaces& controls) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  name_label(parameter, label, label_x, slider_x);
  if (on_show.mystery && on_show.mystery->hides(parameter.name)) {
    // No slider, box or reset: the value is for the class to measure. A row of two has room for "?" only.
    const char* hidden = value_x == reset_x ? "?" : draw::hidden_value_text;
    ImGui::SameLine(slider_x);
    ImGui::TextDisabled("%s", hidden);
    draw::note_text(hidden);
    return;
  }
  ImGui::SameLine(slider_x);
  if (parameter.is_choice()) {
    // A choice has no number to type: its list takes the box's place too.
    ImGui::SetNextItemWidth(reset_x - spacing - slider_x);
    choice_list(parameter, controls);
  } else {
    ImGui::SetNextItemWidth(value_x - spacing - slider_x);
    value_slider(parameter, controls);
    if (value_x < reset_x) {
      ImGui::SameLine(value_x);
      ImGui::SetNextItemWidth(reset_x - spacing - value_x);
      typed_value(parameter, controls);
    }
  }
  ImGui::SameLine(reset_x);
  reset_button(parameter, controls);
}

}  // namespace frictionlab::classroom
