#include "ui/cheapest_setting_tab.h"

#include <cmath>

#include "lessons/runtime/lesson_benchmark.h"
#include "ui/panels.h"

namespace frictionlab::ui {

std::optional<StepSettings> CheapestSettingTab::draw(const lessons::Lesson& lesson, float scale, const Theme& colours,
                                                     ControlPlaces& controls) {
  const bool open = begin_tab("Cheapest###cheapest setting");
  remember_item(controls, "Cheapest setting tab");
  if (!open) return std::nullopt;
  std::optional<StepSettings> use;
  const std::string& path = lesson.path();
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
  ImGui::SetNextItemWidth(90.0f * scale);
  ImGui::InputDouble("##tolerance", &tolerance, 0.0, 0.0, "%g");
  remember_item(controls, "tolerance");
  ImGui::SameLine();
  ImGui::TextUnformatted(unit);
  // "1e999" reads as infinity and "-1" as less than nothing: neither is a tolerance.
  const bool valid = tolerance > 0.0 && std::isfinite(tolerance);
  ImGui::SameLine();
  const bool mine = search && lesson_path == path;
  ImGui::BeginDisabled((mine && !search->done()) || !valid);
  if (ImGui::Button("Measure")) {
    // Its own Lesson instances, built from the script with the sliders' values: the running
    // lesson is not touched.
    try {
      search = std::make_unique<Recommender>(lessons::lesson_problem(path, lessons::parameter_values(lesson)), tolerance, 1);
      lesson_path = path;
      error.clear();
    } catch (const std::exception& failure) {
      search.reset();
      error = failure.what();
    }
  }
  ImGui::EndDisabled();
  remember_item(controls, "measure");
  const ImVec4 bad = ImGui::ColorConvertU32ToFloat4(colours.bad);
  if (!valid) ImGui::TextColored(bad, "The tolerance must be a positive number (%s).", unit);
  if (!error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(bad, "%s", error.c_str());
    ImGui::PopTextWrapPos();
  }
  if (search && lesson_path == path) {
    if (!search->done()) {
      ImGui::ProgressBar(static_cast<float>(search->progress()));
    } else if (const std::optional<Trial> best = search->cheapest()) {
      if (ImGui::Button("Use it")) use = best->settings;
      remember_item(controls, "use it");
      ImGui::SameLine();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::Text("Cheapest within %g %s: %s, error %.3g, %.3g ms CPU per simulated s.", search->tolerance(), unit,
                  describe(best->settings).c_str(), best->error, best->cost * 1e3);
      ImGui::PopTextWrapPos();
    } else {
      ImGui::TextColored(bad, "No setting tried answers within %g %s.", search->tolerance(), unit);
    }
    if (const std::string failed = search->failures(); search->done() && !failed.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", failed.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  ImGui::EndTabItem();
  return use;
}

}  // namespace frictionlab::ui
