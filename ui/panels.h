// The ImGui panels beside the world: the lesson's title and question, its parameters, the
// theory-against-simulation table, the energy ledger and the model card. Each reads the lesson
// directly; nothing is copied.
#pragma once

#include <imgui.h>

#include <vector>

#include "lessons/runtime/lesson.h"
#include "ui/theme.h"

namespace frictionlab::ui {

// A fixed panel at a place in the frame, with a title bar unless `title` is empty.
bool begin_panel(const char* id, const char* title, ImVec2 corner, ImVec2 size);
void end_panel();

void title_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size, const Fonts& fonts);
// A parameter as a class reads it: a pair's coefficient in the books' letters with its pair
// ("μs  aluminium / wood"), any other by its name.
std::string parameter_title(const lessons::Parameter& parameter);

void parameters_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size);
// `error`: the script could not work the table out (shown instead of it); `caveat`: why the
// rows should not be trusted yet (shown above them).
void theory_panel(const std::vector<lessons::ExpectationResult>& rows, ImVec2 corner, ImVec2 size, const Theme& theme,
                  const std::string& error = "", const std::string& caveat = "");
void energy_panel(const Scene& scene, ImVec2 corner, ImVec2 size, const Theme& theme);
void model_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size);
// What those two panels hold, for a window that shows them as tabs of one panel.
void energy_contents(const Scene& scene, const Theme& theme);
void model_contents(const lessons::Lesson& lesson);

}  // namespace frictionlab::ui
