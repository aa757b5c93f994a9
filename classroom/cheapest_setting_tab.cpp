// The Cheapest setting tab (classroom/cheapest_setting_tab.h). Every line wraps, and a control goes
// beside the last one only when it fits: in projector mode the column is a third of the screen
// and its text a third larger.
#include "classroom/cheapest_setting_tab.h"

#include <cmath>
#include <cstdio>

#include "classroom/text_boxes.h"
#include "draw/panels.h"
#include "draw/text_record.h"
#include "bench/lesson_problem.h"

namespace frictionlab::classroom {
namespace {

// A paragraph in `colour`, wrapped at the panel's edge (beside the last item when on its line).
void paragraph(const std::string& text, ImU32 colour) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::PushTextWrapPos(0.0f);
  draw::shown_text(text.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
}

// The next item beside the last one when `width` more fits before the panel's edge, else on a
// line of its own.
void beside_if_room(float width) {
  const float after = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x;
  if (after + width <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

float button_width(const char* label) { return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x; }

}  // namespace

std::optional<StepSettings> CheapestSettingTab::draw(const lessons::Lesson& lesson, float scale, const draw::Theme& colours,
                                                     ControlPlaces& controls) {
  const bool open = draw::begin_tab("Cheapest###cheapest setting");
  remember_item(controls, "Cheapest setting tab");
  if (!open) return std::nullopt;
  std::optional<StepSettings> use;
  const std::string& path = lesson.path();
  const std::string unit = "\u00d7 the lesson's tolerances";
  const ImU32 disabled = ImGui::GetColorU32(ImGuiCol_TextDisabled), bad = colours.bad;
  paragraph("Runs this lesson at each setting, judged by its table (?)", disabled);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Every friction treatment at 30 to 1920 Hz with 1, 2 or 4 sub-steps, each a fresh run of this\n"
                      "lesson's script with its sliders as they are now. Error: the largest |measured - theory| over\n"
                      "the table's rows, each in its tolerance at the default setting (stick-slip, 240 Hz, 1 sub-step);\n"
                      "a word row that differs is wrong. Within 1: the lesson's own table passes; 0.1: ten times tighter.");
  }
  ImGui::AlignTextToFramePadding();
  draw::shown_text("within");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f * scale);
  ImGui::InputDouble("##tolerance", &tolerance, 0.0, 0.0, "%g");
  takes_a_number();
  remember_item(controls, "tolerance");
  beside_if_room(ImGui::CalcTextSize(unit.c_str()).x);
  ImGui::AlignTextToFramePadding();
  draw::shown_text(unit.c_str());
  // "1e999" reads as infinity and "-1" as less than nothing: neither is a tolerance.
  const bool valid = tolerance > 0.0 && std::isfinite(tolerance);
  const char* measure = "Measure";
  beside_if_room(button_width(measure));
  const bool mine = search && lesson_path == path;
  ImGui::BeginDisabled((mine && !search->done()) || !valid);
  if (ImGui::Button(measure)) {
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
  draw::note_text_centred(measure, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
  if (!valid) paragraph("The tolerance must be a positive number (" + unit + ").", bad);
  if (!error.empty()) paragraph(error, bad);
  if (search && lesson_path == path) {
    char line[300];
    if (!search->done()) {
      ImGui::ProgressBar(static_cast<float>(search->progress()));
    } else if (const std::optional<Trial> best = search->cheapest()) {
      const char* use_it = "Use it";
      if (ImGui::Button(use_it)) use = best->settings;
      remember_item(controls, "use it");
      draw::note_text_centred(use_it, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
      ImGui::SameLine();
      std::snprintf(line, sizeof line, "Cheapest within %g %s: %s, error %.3g, %.3g ms CPU per simulated s.",
                    search->tolerance(), unit.c_str(), describe(best->settings).c_str(), best->error, best->cost * 1e3);
      paragraph(line, ImGui::GetColorU32(ImGuiCol_Text));
    } else {
      std::snprintf(line, sizeof line, "No setting tried answers within %g %s.", search->tolerance(), unit.c_str());
      paragraph(line, bad);
    }
    if (const std::string failed = search->failures(); search->done() && !failed.empty()) paragraph(failed, disabled);
  }
  ImGui::EndTabItem();
  return use;
}

}  // namespace frictionlab::classroom
