// The ImGui panels beside the world: the lesson's title and question, its parameters, the
// theory-against-simulation table, the energy ledger and the model card. Each reads the lesson
// directly; nothing is copied.
#pragma once

#include <imgui.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

// What the class must not see yet: the parameters of a mystery pair (classroom_state/mystery.h), by name.
// While any is hidden, so is the theory worked out from them (the theory table's predictions
// and errors, the plots' theory curves): a breakaway force predicted gives μs away.
struct HiddenValues {
  std::set<std::string> parameters;
  bool hides(const std::string& parameter) const { return parameters.count(parameter) > 0; }
  bool theory() const { return !parameters.empty(); }
};
// What a hidden value shows in its place.
inline constexpr const char* hidden_value_text = "? (a mystery)";

// A fixed panel at a place in the frame, with a title bar unless `title` is empty.
// `scroll`: what does not fit scrolls (a window's panel) instead of being cut at the edge.
bool begin_panel(const char* id, const char* title, ImVec2 corner, ImVec2 size, bool scroll = false);
void end_panel();

// `one_line` (projector mode): the question after the title where it fits, else left out, and
// `one_line_padding` pixels above and below.
void title_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size, const Fonts& fonts, bool one_line = false,
                 float one_line_padding = 0.0f);

// The friction pair a parameter is a coefficient of ("aluminium on wood"), "" for any other.
std::string pair_of(const lessons::Parameter& parameter);
// The pairs among a lesson's parameters, each once, in the order they come.
std::vector<std::string> parameter_pairs(const lessons::Lesson& lesson);
// A pair's coefficients on one line, without units, drag coefficients only when on: "μs 0.45  μk 0.35".
// A hidden coefficient shows "?".
std::string pair_values(const lessons::Lesson& lesson, const std::string& pair, const HiddenValues& hidden = {});

// The values as text. The last `folded_pairs` friction pairs are folded into a line each (their
// coefficients side by side) when the column is short.
void parameters_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size, std::size_t folded_pairs = 0,
                      const HiddenValues& hidden = {});
// The height that panel takes, in the current font, at a width.
float parameters_panel_height(const lessons::Lesson& lesson, float width, std::size_t folded_pairs,
                              const HiddenValues& hidden = {});
// `error`: the script could not work the table out (shown instead of it); `caveat`: why the
// rows should not be trusted yet (shown above them); `predictions_hidden`: the predicted and
// error columns say "hidden" (a mystery's values would be read off them).
// The theory table's columns: theory, measured and the error (a screen's); or theory and
// measured, each measured value followed by its verdict (\u2713, \u2717), which a projector's text
// needs: the error's column pushed each row's name onto a line of its own, and its unit under
// its number, so a row took four lines (stacked_blocks' five rows did not fit under its sliders).
enum class TheoryColumns { errors, verdicts };
// The class's answer to a predicted row, in a column of its own between the theory and the
// measurement (a projector's table, TheoryColumns::verdicts; classroom/prediction_panel.h):
// `answer` as the class gave it ("1.5 N", "tips", "\u2014" unanswered), in the good colour where
// `close` (within 10 % of the measurement, or the same word). `widest`: the widest it may read
// whatever the class answers later ("\u221288.8 N", the longest word), so that the table, planned
// from the lesson's opening, keeps its columns at the reveal. A line of words under each row
// ("class: 1.5 N \u00b7 \u22121.19 N, 44 % below the measurement") took two lines at projector text
// where the column takes none (stacked_blocks' two answers: four lines of its table).
struct ClassAnswer {
  std::string answer;
  bool close = false;
  std::string widest;
};
using ClassAnswers = std::map<std::string, ClassAnswer>;  // by the theory row's name
void theory_panel(const std::vector<lessons::ExpectationResult>& rows, ImVec2 corner, ImVec2 size, const Theme& theme,
                  const std::string& error = "", const std::string& caveat = "", bool predictions_hidden = false,
                  TheoryColumns columns = TheoryColumns::errors);
void energy_panel(const Scene& scene, ImVec2 corner, ImVec2 size, const Theme& theme);
void model_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size);
// What the theory, energy and model panels hold, for a window that shows them as tabs of one panel.
// `answers`: the class's, a column of their own where `columns` is TheoryColumns::verdicts.
void theory_contents(const std::vector<lessons::ExpectationResult>& rows, const Theme& theme,
                     const std::string& error = "", const std::string& caveat = "", bool predictions_hidden = false,
                     const ClassAnswers& answers = {}, TheoryColumns columns = TheoryColumns::errors);
// The height theory_contents takes at a width (the panel's inside), in the current font.
float theory_contents_height(const std::vector<lessons::ExpectationResult>& rows, float width,
                             const std::string& error = "", const std::string& caveat = "",
                             bool predictions_hidden = false, TheoryColumns columns = TheoryColumns::errors);
// The most theory_contents takes at a width once the run has measured every row, with numbers
// of up to three figures and a sign and words as the theory says them (its numbers' widths change
// as their rows fill in): planned for from a lesson's opening, the revealed table needs no more
// room at the run's end unless a measurement is longer than that (a failed row's other word).
// With `answers` (TheoryColumns::verdicts), their column at the widest each may read.
float theory_contents_tallest_height(const std::vector<lessons::ExpectationResult>& rows, float width,
                                     const std::string& error = "", const std::string& caveat = "",
                                     bool predictions_hidden = false, TheoryColumns columns = TheoryColumns::errors,
                                     const ClassAnswers& answers = {});
// A tab of a panel's tab bar (ImGui::BeginTabItem), its name noted for the layout test.
bool begin_tab(const char* label, int flags = 0);  // ImGuiTabItemFlags
void energy_contents(const Scene& scene, const Theme& theme);
// The height energy_contents takes at a width (the panel's inside), in the current font.
float energy_contents_height(const Scene& scene, float width);
void model_contents(const lessons::Lesson& lesson);
// The height model_contents takes at a width (the panel's inside), in the current font.
float model_contents_height(const lessons::Lesson& lesson, float width);

}  // namespace frictionlab::draw
