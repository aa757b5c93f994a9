// The sandbox's controls: the parameters as sliders with a box for typed values and a reset,
// material presets for a friction pair, and the transport bar along the bottom.
#define IMGUI_DEFINE_MATH_OPERATORS
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "lessons/runtime/lesson_benchmark.h"
#include "physics/materials.h"
#include "ui/sandbox.h"

namespace frictionlab::ui {
namespace {

// "μs" for a pair's coefficient, the parameter's own name otherwise.
std::string control_label(const lessons::Parameter& parameter) {
  if (parameter.coefficient == "mu_s") return "\u03bcs static";
  if (parameter.coefficient == "mu_k") return "\u03bck kinetic";
  if (parameter.coefficient == "c") return "c viscous";
  if (parameter.coefficient == "b") return "b quadratic";
  return parameter.name;
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

}  // namespace

// Each row: the name, the slider, a box for a typed value, and a reset; a friction pair's
// rows come under a heading with its material presets.
struct ControlColumns {
  float slider, value, reset, end;
  static ControlColumns of(float width, float scale) {
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    ControlColumns columns;
    columns.end = width;
    columns.reset = width - ImGui::GetFrameHeight();
    columns.value = columns.reset - spacing - 72.0f * scale;
    columns.slider = std::min(0.3f * width, 120.0f * scale);
    return columns;
  }
};

std::vector<Sandbox::ParameterRow> Sandbox::parameter_rows() const {
  std::vector<ParameterRow> rows;
  std::string last_pair;
  for (const lessons::Parameter& parameter : playback_->lesson().parameters()) {
    if (!shown(parameter.name)) continue;
    const std::string pair = parameter.material_a + " on " + parameter.material_b;
    const bool heading = !parameter.coefficient.empty() && pair != last_pair;
    if (heading) last_pair = pair;
    rows.push_back({&parameter, heading});
  }
  return rows;
}

float Sandbox::parameters_height() const {
  int rows = lock_.empty() ? 0 : 1;
  for (const ParameterRow& row : parameter_rows()) {
    rows += 1 + (row.pair_heading ? 1 : 0) + (control_errors_.count(row.parameter->name) ? 2 : 0);
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y + static_cast<float>(rows) * ImGui::GetFrameHeightWithSpacing();
}

void Sandbox::remember(const std::string& name) {
  controls_[name] = ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
}

void Sandbox::parameters_panel(ImVec2 corner, ImVec2 size) {
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  const std::string title = lock_.empty() ? "Parameters###parameters" : "Parameters (chosen by the teacher)###parameters";
  if (ImGui::Begin(title.c_str(), nullptr, flags)) {
    const ControlColumns columns = ControlColumns::of(ImGui::GetContentRegionAvail().x, fonts_->scale);
    for (const ParameterRow& row : parameter_rows()) {
      const lessons::Parameter& parameter = *row.parameter;
      if (row.pair_heading) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("%s on %s", parameter.material_a.c_str(), parameter.material_b.c_str());
        if (parameter.coefficient == "mu_s") {
          ImGui::SameLine();
          ImGui::SetNextItemWidth(-FLT_MIN);
          preset_row(parameter);
        }
      }
      ImGui::PushID(parameter.name.c_str());
      parameter_row(parameter, columns.slider, columns.value, columns.reset);
      ImGui::PopID();
    }
    if (!lock_.empty()) ImGui::TextDisabled("Only the controls the teacher chose are shown.");
  }
  ImGui::End();
}

void Sandbox::preset_row(const lessons::Parameter& mu_s) {
  const std::string prefix = mu_s.name.substr(0, mu_s.name.size() - 4);  // "" or "name."
  const std::string mu_k = prefix + "mu_k";
  if (!shown(mu_k)) {
    ImGui::NewLine();
    return;
  }
  ImGui::PushID(mu_s.name.c_str());
  if (ImGui::BeginCombo("##preset", "material presets (seed tables)...")) {
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

void Sandbox::parameter_row(const lessons::Parameter& parameter, float slider_x, float value_x, float reset_x) {
  const std::string& name = parameter.name;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(control_label(parameter).c_str());
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s (%s)\nfrom %s to %s%s; the script gives %s\n%s", parameter.text.c_str(), name.c_str(),
                      exact_text(parameter.min).c_str(), exact_text(parameter.max).c_str(),
                      parameter.unit.empty() ? "" : (" " + parameter.unit).c_str(),
                      exact_text(parameter.default_value).c_str(), parameter.declared_at.c_str());
  }

  ImGui::SameLine(slider_x);
  if (parameter.is_choice()) {
    // A choice has no number to type: its list takes the box's place too.
    ImGui::SetNextItemWidth(reset_x - spacing - slider_x);
    const std::string& chosen = parameter.choices[static_cast<std::size_t>(parameter.value)];
    if (ImGui::BeginCombo("##choice", chosen.c_str())) {
      for (const std::string& choice : parameter.choices) {
        if (ImGui::Selectable(choice.c_str(), choice == chosen) && choice != chosen) pending_values_.push_back({name, choice});
      }
      ImGui::EndCombo();
    }
    remember(name + " slider");
  } else {
    ImGui::SetNextItemWidth(value_x - spacing - slider_x);
    const bool sliding_this = sliding_ && sliding_->first == name;
    double value = sliding_this ? sliding_->second : parameter.value;
    const std::string format = "%.3g" + (parameter.unit.empty() ? "" : " " + parameter.unit);
    // A wide range (0 to 1000 N·s/m) is easier to set on a logarithmic scale.
    const bool wide = parameter.max > 10.0 && parameter.max >= 100.0 * std::max(parameter.min, 1e-9);
    const bool moved = ImGui::SliderScalar("##slider", ImGuiDataType_Double, &value, &parameter.min, &parameter.max,
                                           format.c_str(), wide ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    remember(name + " slider");
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
    ImGui::SameLine(value_x);
    ImGui::SetNextItemWidth(reset_x - spacing - value_x);
    char typed[64];
    std::snprintf(typed, sizeof typed, "%s", parameter_text(parameter).c_str());
    if (ImGui::InputText("##value", typed, sizeof typed,
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
      pending_values_.push_back({name, typed});
    }
    remember(name + " value");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type an exact value and press Enter");
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

  if (const auto error = control_errors_.find(name); error != control_errors_.end()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme(window_.theme).bad), "%s", error->second.c_str());
    ImGui::PopTextWrapPos();
  }
}

void Sandbox::transport_bar(ImVec2 corner, ImVec2 size) {
  const float s = fonts_->scale;
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (ImGui::Begin("###transport", nullptr, flags)) {
    const float button = 80.0f * s;
    if (ImGui::Button(playback_->playing() ? "Pause" : "Play", ImVec2(button, 0.0f))) playback_->toggle();
    remember("play");
    ImGui::SameLine();
    if (ImGui::Button("Step", ImVec2(button, 0.0f))) playback_->step_once();
    remember("step");
    ImGui::SameLine();
    if (ImGui::Button("Reset", ImVec2(button, 0.0f))) playback_->reset();
    remember("reset");
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
    ImGui::SameLine();
    const Scene& scene = playback_->lesson().scene();
    // Notices (the run is over, the file reloaded) and what was saved where, on one line.
    std::string said = playback_->notice();
    if (!status_.empty()) said += (said.empty() ? "" : "  ") + status_;
    if (playback_->behind()) said = "running slower than asked  " + said;
    const float said_width = said.empty() ? 0.0f : std::min(ImGui::CalcTextSize(said.c_str()).x, 0.35f * size.x) + 8.0f * s;
    ImGui::SetNextItemWidth(std::max(100.0f * s, ImGui::GetContentRegionAvail().x - said_width));
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
    if (!said.empty()) {
      ImGui::SameLine();
      ImGui::TextDisabled("%s", said.c_str());
    }
  }
  ImGui::End();
}

void Sandbox::cheapest_setting_tab() {
  const bool open = ImGui::BeginTabItem("Cheapest setting");
  remember("Cheapest setting tab");
  if (!open) return;
  const std::string& path = playback_->lesson().path();
  const char* unit = "\u00d7 the lesson's tolerances";
  ImGui::TextDisabled("Runs this lesson at each setting, judged by its table (?)");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Every friction treatment at 30 to 1920 Hz with 1, 2 or 4 sub-steps, each a fresh run of this\n"
                      "lesson's script with its sliders as they are now. Error: the largest |measured - predicted| over\n"
                      "the table's rows, each in its tolerance at the default setting (stick-slip, 240 Hz, 1 sub-step);\n"
                      "a word row that differs is wrong. Within 1: the lesson's own table passes; 0.1: ten times tighter.");
  }
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("within");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f * fonts_->scale);
  ImGui::InputDouble("##tolerance", &recommend_tolerance_, 0.0, 0.0, "%g");
  remember("tolerance");
  ImGui::SameLine();
  ImGui::TextUnformatted(unit);
  // "1e999" reads as infinity and "-1" as less than nothing: neither is a tolerance.
  const bool valid = recommend_tolerance_ > 0.0 && std::isfinite(recommend_tolerance_);
  ImGui::SameLine();
  const bool mine = recommender_ && recommend_path_ == path;
  const bool measuring = mine && !recommender_->done();
  ImGui::BeginDisabled(measuring || !valid);
  if (ImGui::Button("Measure")) {
    // Its own Lesson instances, built from the script with the sliders' values: the running
    // lesson is not touched.
    try {
      recommender_ = std::make_unique<Recommender>(
          lessons::lesson_problem(path, lessons::parameter_values(playback_->lesson())), recommend_tolerance_, 1);
      recommend_path_ = path;
      recommend_error_.clear();
    } catch (const std::exception& error) {
      recommender_.reset();
      recommend_error_ = error.what();
    }
  }
  ImGui::EndDisabled();
  remember("measure");
  const ImVec4 bad = ImGui::ColorConvertU32ToFloat4(theme(window_.theme).bad);
  if (!valid) ImGui::TextColored(bad, "The tolerance must be a positive number (%s).", unit);
  if (!recommend_error_.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(bad, "%s", recommend_error_.c_str());
    ImGui::PopTextWrapPos();
  }
  if (recommender_ && recommend_path_ == path) {
    if (!recommender_->done()) {
      ImGui::ProgressBar(static_cast<float>(recommender_->progress()));
    } else if (const std::optional<Trial> best = recommender_->cheapest()) {
      if (ImGui::Button("Use it")) change_settings(best->settings);
      remember("use it");
      ImGui::SameLine();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::Text("Cheapest within %g %s: %s, error %.3g, %.3g ms CPU per simulated s.", recommender_->tolerance(), unit,
                  describe(best->settings).c_str(), best->error, best->cost * 1e3);
      ImGui::PopTextWrapPos();
    } else {
      ImGui::TextColored(bad, "No setting tried answers within %g %s.", recommender_->tolerance(), unit);
    }
    if (const std::string failed = recommender_->failures(); recommender_->done() && !failed.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", failed.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  ImGui::EndTabItem();
}

}  // namespace frictionlab::ui
