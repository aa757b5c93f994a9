// The classroom's controls: the parameters as sliders with a box for typed values and a reset,
// material presets for a friction pair, and the transport bar along the bottom.
#define IMGUI_DEFINE_MATH_OPERATORS
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "classroom/classroom.h"
#include "classroom/text_boxes.h"
#include "draw/panels.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"
#include "physics/materials.h"

namespace frictionlab::ui {
namespace {

// "μs static" for a pair's coefficient, the parameter's own name in words otherwise.
std::string control_label(const lessons::Parameter& parameter) {
  const std::string letter = lessons::class_words(parameter.coefficient);
  if (parameter.coefficient == "mu_s") return letter + " static";
  if (parameter.coefficient == "mu_k") return letter + " kinetic";
  if (parameter.coefficient == "c") return letter + " viscous";
  if (parameter.coefficient == "b") return letter + " quadratic";
  return lessons::class_words(parameter.name);
}

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
  return lessons::class_words(parameter.coefficient.empty() ? parameter.name : parameter.coefficient);
}

// A combo box's shown choice, left in its frame before the arrow button.
void note_combo(const char* preview) {
  const ImVec2 padding = ImGui::GetStyle().FramePadding;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  note_text_in(preview, ImVec2(min.x + padding.x, min.y + padding.y),
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

std::vector<std::string> Classroom::foldable_pairs(bool opened_too) const {
  std::vector<std::string> pairs;
  for (const lessons::Parameter& parameter : playback_->lesson().parameters()) {
    const std::string pair = pair_of(parameter);
    if (pair.empty() || !shown(parameter.name)) continue;
    const auto choice = pair_open_.find(pair);
    if (choice != pair_open_.end() && !(opened_too && choice->second)) continue;
    if (std::find(pairs.begin(), pairs.end(), pair) == pairs.end()) pairs.push_back(pair);
  }
  return pairs;
}

std::vector<Classroom::ParameterRow> Classroom::parameter_rows(std::size_t step) const {
  // Pairs the teacher opened still go two a row; only those left to the layout fold.
  const std::vector<std::string> compact = foldable_pairs(true), foldable = foldable_pairs(false);
  const std::size_t two_a_row = std::min(step, compact.size());
  const std::size_t folded = step > compact.size() ? std::min(step - compact.size(), foldable.size()) : 0;
  // Whether a pair is among the last `count` of `pairs`.
  const auto among_last = [](const std::vector<std::string>& pairs, const std::string& pair, std::size_t count) {
    const auto at = std::find(pairs.begin(), pairs.end(), pair);
    return at != pairs.end() && static_cast<std::size_t>(at - pairs.begin()) >= pairs.size() - count;
  };
  std::vector<ParameterRow> rows;
  std::string last_pair;
  for (const lessons::Parameter& parameter : playback_->lesson().parameters()) {
    if (!shown(parameter.name)) continue;
    const std::string pair = pair_of(parameter);
    const bool heading = !pair.empty() && pair != last_pair;
    if (heading) last_pair = pair;
    ParameterRow row{&parameter, nullptr, heading, false, false};
    if (!pair.empty()) {
      // The teacher's own choice first; then the layout's step.
      const auto choice = pair_open_.find(pair);
      row.folded = choice != pair_open_.end() ? !choice->second : among_last(foldable, pair, folded);
      row.two_a_row = !row.folded && among_last(compact, pair, two_a_row);
    }
    // A folded pair is its heading alone, its values on that line.
    if (row.folded && !heading) continue;
    // The second of two coefficients shares the row of the first.
    if (row.two_a_row && !heading && !rows.empty() && rows.back().two_a_row && rows.back().partner == nullptr &&
        pair_of(*rows.back().parameter) == pair) {
      rows.back().partner = &parameter;
      continue;
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<float> Classroom::parameters_heights() const {
  const ImGuiStyle& style = ImGui::GetStyle();
  std::vector<float> heights;
  for (std::size_t step = 0; step <= foldable_pairs(true).size() + foldable_pairs(false).size(); ++step) {
    int rows = lock_.empty() ? 0 : 1;
    for (const ParameterRow& row : parameter_rows(step)) {
      rows += 1 + (row.pair_heading && !row.folded ? 1 : 0);
      for (const lessons::Parameter* shown : {row.parameter, row.partner}) {
        if (shown != nullptr && !row.folded && control_errors_.count(shown->name) > 0) rows += 2;
      }
    }
    heights.push_back(ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y +
                      static_cast<float>(rows) * ImGui::GetFrameHeightWithSpacing());
  }
  // Folded away: its heading alone, a line with the arrow that opens it.
  if (parameters_may_fold_away()) heights.push_back(ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y);
  return heights;
}

bool Classroom::run_played() const {
  // The record reaches the run's end (scrubbing back within it keeps it so; a reset or a rebuild does not).
  return playback_->recorded_until() + 0.5 * playback_->lesson().scene().frame_step() >= playback_->readings().duration;
}

bool Classroom::parameters_may_fold_away() const {
  const lessons::Lesson& lesson = playback_->lesson();
  return window_.predictions && !lesson.predictions().empty() && !parameters_opened_ && run_played();
}

std::size_t Classroom::parameters_folded_away_step() const {
  return foldable_pairs(true).size() + foldable_pairs(false).size() + 1;
}

void Classroom::folded_parameters_panel(ImVec2 corner, ImVec2 size) {
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar;
  if (ImGui::Begin("###parameters", nullptr, flags)) {
    // As a friction pair folds: an arrow before the heading, the heading, and why it is folded.
    if (ImGui::ArrowButton("##open parameters", ImGuiDir_Right)) parameters_opened_ = true;
    remember("parameters open");
    ImGui::SameLine();
    ImGui::AlignTextToFramePadding();
    shown_text("Parameters");
    // Why, when the line holds it: the arrow and the heading say enough alone.
    const char* why = lock_.empty() ? "folded while comparing" : "chosen by the teacher, folded";
    ImGui::SameLine();
    if (ImGui::CalcTextSize(why).x <= ImGui::GetContentRegionAvail().x) {
      ImGui::TextDisabled("%s", why);
      note_text(why);
    }
  }
  ImGui::End();
}

void Classroom::remember(const std::string& name) { remember_item(controls_, name); }

void Classroom::parameters_panel(ImVec2 corner, ImVec2 size, std::size_t step) {
  if (parameters_may_fold_away() && step >= parameters_folded_away_step()) {
    folded_parameters_panel(corner, size);
    return;
  }
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  const std::string title = lock_.empty() ? "Parameters###parameters" : "Parameters (chosen by the teacher)###parameters";
  if (ImGui::Begin(title.c_str(), nullptr, flags)) {
    note_title(title.substr(0, title.find("###")).c_str());
    const std::vector<ParameterRow> rows = parameter_rows(step);
    float widest_name = 0.0f, widest_letter = 0.0f;
    for (const ParameterRow& row : rows) {
      if (row.folded) continue;
      for (const lessons::Parameter* shown : {row.parameter, row.partner}) {
        if (shown == nullptr) continue;
        float& widest = row.two_a_row ? widest_letter : widest_name;
        widest = std::max(widest, ImGui::CalcTextSize((row.two_a_row ? coefficient_letter(*shown) : control_label(*shown)).c_str()).x);
      }
    }
    const float width = ImGui::GetContentRegionAvail().x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const ControlColumns columns = ControlColumns::of(width, fonts_->scale, widest_name);
    for (const ParameterRow& row : rows) {
      const lessons::Parameter& parameter = *row.parameter;
      if (row.pair_heading) {
        // The pair's heading, with an arrow that folds its sliders into the line or opens them.
        const std::string pair = pair_of(parameter);
        ImGui::PushID(pair.c_str());
        if (ImGui::ArrowButton("##fold", row.folded ? ImGuiDir_Right : ImGuiDir_Down)) pair_open_[pair] = row.folded;
        remember(pair + " fold");
        ImGui::PopID();
        ImGui::SameLine();
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("%s", pair.c_str());
        note_text(pair.c_str());
        if (row.folded) {
          const std::string values = pair_values(playback_->lesson(), pair, hidden_values());
          ImGui::SameLine();
          ImGui::TextUnformatted(values.c_str());
          note_text(values.c_str());
          continue;
        }
        if (parameter.coefficient == "mu_s") {
          ImGui::SameLine();
          ImGui::SetNextItemWidth(-FLT_MIN);
          preset_row(parameter);
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
                        reset, reset);
          ImGui::PopID();
        }
      } else {
        ImGui::PushID(parameter.name.c_str());
        parameter_row(parameter, control_label(parameter), 0.0f, columns.slider, columns.value, columns.reset);
        ImGui::PopID();
      }
      for (const lessons::Parameter* shown : {row.parameter, row.partner}) {
        if (shown == nullptr) continue;
        if (const auto error = control_errors_.find(shown->name); error != control_errors_.end()) {
          ImGui::PushTextWrapPos(0.0f);
          ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme(window_.theme).bad), "%s", error->second.c_str());
          ImGui::PopTextWrapPos();
          note_text(error->second.c_str());
        }
      }
    }
    if (!lock_.empty()) {
      const char* locked = "Only the controls the teacher chose are shown.";
      ImGui::TextDisabled("%s", locked);
      note_text(locked);
    }
  }
  ImGui::End();
}

void Classroom::preset_row(const lessons::Parameter& mu_s) {
  const std::string prefix = mu_s.name.substr(0, mu_s.name.size() - 4);  // "" or "name."
  const std::string mu_k = prefix + "mu_k";
  // A mystery's pair takes no presets: choosing one would end the mystery without a reveal.
  if (!shown(mu_k) || (mystery_ && mystery_->hides(mu_s.name))) {
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
        const bool falling = preset.values.mu_k < playback_->lesson().parameter(mu_k).value;
        const std::pair<std::string, std::string> s_value{mu_s.name, exact_text(preset.values.mu_s)};
        const std::pair<std::string, std::string> k_value{mu_k, exact_text(preset.values.mu_k)};
        pending_values_.push_back(falling ? k_value : s_value);
        pending_values_.push_back(falling ? s_value : k_value);
      }
    }
    ImGui::EndCombo();
  }
  remember(mu_s.name + " presets");
  ImGui::PopID();
}

void Classroom::parameter_row(const lessons::Parameter& parameter, const std::string& label, float label_x, float slider_x,
                            float value_x, float reset_x) {
  const std::string& name = parameter.name;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  // The second control of a row goes on the same line, from its own start.
  if (label_x > 0.0f) ImGui::SameLine(label_x);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(label.c_str());
  {
    // The slider starts at slider_x from the panel's edge: the name must end before it.
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    note_text_in(label.c_str(), min, ImRect(min, ImVec2(ImGui::GetWindowPos().x + slider_x, max.y)));
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s (%s)\nfrom %s to %s%s; the script gives %s\n%s", parameter.text.c_str(), name.c_str(),
                      exact_text(parameter.min).c_str(), exact_text(parameter.max).c_str(),
                      parameter.unit.empty() ? "" : (" " + parameter.unit).c_str(),
                      exact_text(parameter.default_value).c_str(), parameter.declared_at.c_str());
  }
  if (mystery_ && mystery_->hides(name)) {
    // No slider, box or reset: the value is for the class to measure. A row of two has room for "?" only.
    const char* hidden = value_x == reset_x ? "?" : hidden_value_text;
    ImGui::SameLine(slider_x);
    ImGui::TextDisabled("%s", hidden);
    note_text(hidden);
    return;
  }

  ImGui::SameLine(slider_x);
  if (parameter.is_choice()) {
    // A choice has no number to type: its list takes the box's place too.
    ImGui::SetNextItemWidth(reset_x - spacing - slider_x);
    const std::string& chosen = parameter.choices[static_cast<std::size_t>(parameter.value)];
    const bool open = ImGui::BeginCombo("##choice", chosen.c_str());
    note_combo(chosen.c_str());
    if (open) {
      for (const std::string& choice : parameter.choices) {
        if (ImGui::Selectable(choice.c_str(), choice == chosen) && choice != chosen) pending_values_.push_back({name, choice});
        remember(name + " choice " + choice);
      }
      ImGui::EndCombo();
    }
    remember(name + " slider");
  } else {
    ImGui::SetNextItemWidth(value_x - spacing - slider_x);
    const bool sliding_this = sliding_ && sliding_->first == name;
    double value = sliding_this ? sliding_->second : parameter.value;
    // A unit is text, not format: a script's "%" is written "%%".
    std::string unit;
    for (const char c : parameter.unit) unit += c == '%' ? std::string("%%") : std::string(1, c);
    const std::string format = "%.3g" + (unit.empty() ? "" : " " + unit);
    // A wide range (0 to 1000 N·s/m) is easier to set on a logarithmic scale.
    const bool wide = parameter.max > 10.0 && parameter.max >= 100.0 * std::max(parameter.min, 1e-9);
    const bool moved = ImGui::SliderScalar("##slider", ImGuiDataType_Double, &value, &parameter.min, &parameter.max,
                                           format.c_str(), wide ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    remember(name + " slider");
    {
      char shown[96];
      std::snprintf(shown, sizeof shown, format.c_str(), value);
      note_text_centred(shown, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
    }
    if (moved) {
      // A value the scene is built from restarts the lesson: wait until the slider is let go.
      if (parameter.structural) {
        sliding_ = {name, value};
      } else {
        pending_values_.push_back({name, exact_text(value)});
      }
    }
    if (ImGui::IsItemDeactivated() && sliding_ && sliding_->first == name) {
      pending_values_.push_back({name, exact_text(sliding_->second)});
      sliding_.reset();
    }
    if (value_x < reset_x) {
    ImGui::SameLine(value_x);
    ImGui::SetNextItemWidth(reset_x - spacing - value_x);
    char typed[64];
    std::snprintf(typed, sizeof typed, "%s", parameter_text(parameter).c_str());
    // A number, read here (to say why "0,5" is refused): no blank joins it, and Space ends the
    // typing as Enter does and plays (classroom/text_boxes.h).
    if (ImGui::InputText("##value", typed, sizeof typed,
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll |
                             ImGuiInputTextFlags_CharsNoBlank)) {
      pending_values_.push_back({name, typed});
    }
    takes_a_number();
    remember(name + " value");
    {
      const ImVec2 padding = ImGui::GetStyle().FramePadding;
      const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
      note_text_in(typed, ImVec2(min.x + padding.x, min.y + padding.y), ImRect(min, max));
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type an exact value and press Enter");
    }
  }

  ImGui::SameLine(reset_x);
  ImGui::BeginDisabled(parameter.value == parameter.default_value);
  if (ImGui::Button("\u21ba", ImVec2(ImGui::GetFrameHeight(), 0.0f))) {
    const std::string back = parameter.is_choice() ? parameter.choices[static_cast<std::size_t>(parameter.default_value)]
                                                   : exact_text(parameter.default_value);
    pending_values_.push_back({name, back});
  }
  ImGui::EndDisabled();
  remember(name + " reset");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Back to the script's value, %s", exact_text(parameter.default_value).c_str());
  }
}

std::string Classroom::transport_words() const {
  // Notices (the run is over, the file reloaded) and what was saved where, on one line.
  std::string said = script_words(playback_->notice());
  if (!status_.empty()) said += (said.empty() ? "" : "  ") + script_words(status_);
  if (playback_->behind()) said = "running slower than asked  " + said;
  return said;
}

Classroom::TransportShape Classroom::transport_shape(float width) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float s = fonts_->scale;
  TransportShape shape;
  // The controls before the time bar, and the time bar's own words at their longest.
  shape.controls = 3.0f * 80.0f * s + 150.0f * s + 4.0f * style.ItemSpacing.x;
  shape.bar = ImGui::CalcTextSize("t = 0000.000 s of 0000.00 s recorded").x + 2.0f * style.FramePadding.x;
  const std::string said = transport_words();
  const float inside = width - 2.0f * style.WindowPadding.x;
  const float said_width = said.empty() ? 0.0f : ImGui::CalcTextSize(said.c_str()).x + style.ItemSpacing.x;
  // The words beside the bar when they fit there, else on lines of their own under it.
  shape.words_below = shape.controls + shape.bar + said_width > inside;
  const float words = shape.words_below ? ImGui::CalcTextSize(said.c_str(), nullptr, false, inside).y + style.ItemSpacing.y : 0.0f;
  shape.height = ImGui::GetFrameHeight() + words + 2.0f * style.WindowPadding.y + 2.0f * s;
  return shape;
}

void Classroom::transport_bar(ImVec2 corner, ImVec2 size) {
  const float s = fonts_->scale;
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (ImGui::Begin("###transport", nullptr, flags)) {
    const TransportShape shape = transport_shape(size.x);
    const float button = 80.0f * s;
    const auto noted_button = [&](const char* label, const char* name) {
      const bool pressed = ImGui::Button(label, ImVec2(button, 0.0f));
      remember(name);
      note_text_centred(label, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
      return pressed;
    };
    if (noted_button(playback_->playing() ? "Pause" : "Play", "play")) playback_->toggle();
    ImGui::SameLine();
    if (noted_button("Step", "step")) playback_->step_once();
    ImGui::SameLine();
    if (noted_button("Reset", "reset")) playback_->reset();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(150.0f * s);
    float speed = static_cast<float>(playback_->speed());
    if (ImGui::SliderFloat("##speed", &speed, static_cast<float>(Playback::slowest), static_cast<float>(Playback::fastest),
                           "speed \u00d7%.2g", ImGuiSliderFlags_Logarithmic)) {
      // Real time is a speed a teacher comes back to: near ×1 (within 10 %) the slider gives
      // exactly ×1, which a logarithmic slider's pixels otherwise seldom land on.
      if (std::abs(std::log(speed)) < 0.1f) speed = 1.0f;
      playback_->set_speed(speed);
      window_.speed = playback_->speed();
    }
    remember("speed");
    {
      char shown[32];
      std::snprintf(shown, sizeof shown, "speed \u00d7%.2g", static_cast<double>(speed));
      note_text_centred(shown, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
    }
    ImGui::SameLine();
    const Scene& scene = playback_->lesson().scene();
    const std::string said = transport_words();
    const float said_width =
        said.empty() || shape.words_below ? 0.0f : ImGui::CalcTextSize(said.c_str()).x + ImGui::GetStyle().ItemSpacing.x;
    ImGui::SetNextItemWidth(std::max(shape.bar, ImGui::GetContentRegionAvail().x - said_width));
    double t = scrubbing_to_ ? *scrubbing_to_ : scene.time();
    const double start = 0.0, end = std::max(playback_->recorded_until(), scene.frame_step());
    char format[64];
    std::snprintf(format, sizeof format, "t = %%.3f s of %.2f s recorded", playback_->recorded_until());
    // Forward is a few steps a frame; back is a replay from t = 0, which on a long run takes a
    // while: it waits until the bar is let go.
    if (ImGui::SliderScalar("##scrub", ImGuiDataType_Double, &t, &start, &end, format)) {
      if (t >= scene.time() && !scrubbing_to_) {
        playback_->scrub_to(t);
      } else {
        scrubbing_to_ = t;
        playback_->pause();
      }
    }
    if (ImGui::IsItemDeactivated() && scrubbing_to_) {
      playback_->scrub_to(*scrubbing_to_);
      scrubbing_to_.reset();
    }
    remember("scrub");
    {
      char shown[96];
      std::snprintf(shown, sizeof shown, format, t);
      note_text_centred(shown, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
    }
    if (!said.empty()) {
      if (!shape.words_below) ImGui::SameLine();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", said.c_str());
      ImGui::PopTextWrapPos();
      note_text(said.c_str());
    }
  }
  ImGui::End();
}

}  // namespace frictionlab::ui
