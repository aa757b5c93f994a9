#include "classroom/prediction_panel.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "classroom/text_boxes.h"
#include "draw/overlays.h"
#include "draw/text_record.h"
#include "physics/validation.h"

namespace frictionlab::classroom {
namespace {

// Room for a number and its sign, typed: a box wider than that only pushes the unit away.
constexpr int answer_length = 16;

// Whether a row's word offers the class's choice: the word itself, or one of the words a row
// near the line between two of them gives ("smaller or the same": push's friction within the
// measurement's reach of its breakaway, where either may come).
bool offered_by(const std::string& truth, const std::string& choice) {
  if (truth == choice) return true;
  const std::string joint = " or ";
  std::size_t from = 0;
  for (;;) {
    const std::size_t at = truth.find(joint, from);
    const std::string part = truth.substr(from, at == std::string::npos ? std::string::npos : at - from);
    if (part == choice) return true;
    if (at == std::string::npos) return false;
    from = at + joint.size();
  }
}

// The row the prediction is about, failed or not; nullptr when the lesson has none of that name.
const lessons::ExpectationResult* named_row(const std::vector<lessons::ExpectationResult>& rows,
                                            const lessons::Prediction& prediction) {
  for (const lessons::ExpectationResult& row : rows) {
    if (row.name == prediction.expectation) return &row;
  }
  return nullptr;
}
// The same for reading: a row whose function failed is known no better than a missing one ("?").
const lessons::ExpectationResult* row_of(const std::vector<lessons::ExpectationResult>& rows,
                                         const lessons::Prediction& prediction) {
  const lessons::ExpectationResult* row = named_row(rows, prediction);
  return row != nullptr && row->failed ? nullptr : row;
}

std::string answer_of(const classroom_state::ClassPredictions& predictions, const lessons::Prediction& prediction) {
  const auto found = predictions.answers.find(prediction.expectation);
  return found == predictions.answers.end() ? "" : found->second;
}

// What the class said, as the table shows it: the number as typed with the row's unit.
std::string answer_shown(const lessons::Prediction& prediction, const std::string& answer) {
  if (answer.empty()) return "\u2014";
  return prediction.is_choice() || prediction.unit.empty() ? answer : answer + " " + prediction.unit;
}

std::string theory_shown(const lessons::ExpectationResult& row) {
  return row.numeric ? draw::format_quantity(row.predicted, row.unit.c_str()) : row.predicted_text;
}

std::string measured_shown(const lessons::ExpectationResult& row) {
  if (!row.measured_yet) return row.measured_text == "not measured" ? "not yet" : row.measured_text;
  const std::string shown = row.numeric ? draw::format_quantity(row.measured, row.unit.c_str()) : row.measured_text;
  // The mouse's hand pulled in this run: what it measured is not what the lesson asked about.
  return row.hand_pulled ? shown + " (hand-pulled)" : shown;
}

// Beside the reveal button, or under it when there is no room.
const char* intro(bool editable) {
  return editable ? "Ask the class before Play." : "Answers locked for this run (R: back to t = 0).";
}
bool intro_beside(float width) {
  const float button = ImGui::CalcTextSize("Reveal the theory (T)").x + 2.0f * ImGui::GetStyle().FramePadding.x;
  const float words = std::max(ImGui::CalcTextSize(intro(true)).x, ImGui::CalcTextSize(intro(false)).x);
  return button + ImGui::GetStyle().ItemSpacing.x + words <= width;
}
const char* reveal_label = "Reveal the theory (T)";

// A line of text wrapped at the panel's edge, noted for the layout test.
void wrapped(const char* text, std::optional<ImU32> colour = std::nullopt, bool faint = false) {
  ImGui::PushTextWrapPos(0.0f);
  if (colour) ImGui::PushStyleColor(ImGuiCol_Text, *colour);
  if (faint) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextUnformatted(text);
  draw::note_text(text);
  if (faint) ImGui::PopStyleColor();
  if (colour) ImGui::PopStyleColor();
  ImGui::PopTextWrapPos();
}

float wrapped_height(const std::string& text, float width) {
  return ImGui::CalcTextSize(text.c_str(), nullptr, false, width).y + ImGui::GetStyle().ItemSpacing.y;
}

// A choice's radio button: its circle, a gap and its word.
float choice_width(const std::string& word) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(word.c_str()).x;
}

float answer_box_width() { return 7.0f * ImGui::GetFontSize(); }

// The answer's controls from left to right: a number's box and unit, or each choice.
std::vector<float> answer_widths(const lessons::Prediction& prediction) {
  std::vector<float> widths;
  if (prediction.is_choice()) {
    for (const std::string& word : prediction.choices) widths.push_back(choice_width(word));
  } else {
    widths.push_back(answer_box_width());
    if (!prediction.unit.empty()) widths.push_back(ImGui::CalcTextSize(prediction.unit.c_str()).x);
  }
  return widths;
}

// Where items of these widths go, side by side while they fit in `width`: whether each starts
// a new line. The note after the answer is one more item.
std::vector<bool> line_breaks(const std::vector<float>& widths, float width) {
  std::vector<bool> breaks;
  float x = 0.0f;
  for (const float wanted : widths) {
    const bool fits = x == 0.0f || x + ImGui::GetStyle().ItemSpacing.x + wanted <= width;
    breaks.push_back(!fits || x == 0.0f);
    x = fits && x > 0.0f ? x + ImGui::GetStyle().ItemSpacing.x + wanted : wanted;
  }
  return breaks;
}

// Beside an empty answer once the run has measured the row (answers are typed at t = 0: R).
// No longer than a measurement ("measured: 3.92 N"), so it keeps the answer's line: a note of
// two lines made the column taller than planned and folded the Parameters panel.
const char* const held_back_note = "measured: hidden";
const char* const hand_pulled_note = "measured: hand-pulled";

// Beside the answer: what was typed is no number, or what the run has measured so far.
std::string answer_note(const lessons::Prediction& prediction, const std::string& answer,
                        const lessons::ExpectationResult* row, bool& fault) {
  // A row whose function failed: "?", as both tables show it, not "not yet".
  fault = false;
  if (!prediction.is_choice() && !answer.empty()) {
    std::string why;
    if (!classroom_state::read_answer(answer, why)) {
      fault = true;
      return why;
    }
  }
  if (row != nullptr && row->failed) return "measured: ?";
  // What the run measured is the answer the class is asked for: shown beside the class's own
  // answer only (a teacher's trial: "measured: 3.92 N" appeared mid-run beside an empty box
  // and gave the answer away). A row that is not measured yet, or says why not, gives nothing.
  if (answer.empty() && row != nullptr && row->measured_yet) return held_back_note;
  // The hand pulled in this run: what the row measured answers another question than the one
  // the class was asked (a teacher's trial: "measured: larger (hand-pulled)" beside "smaller",
  // on a block whose friction fell from a 5.70 N peak to 4.81 N, and the breakaway's
  // "measured: 2.68 N (hand-pulled)" wrapped onto a line of its own). The word alone, about as
  // long as a measurement; the theory table, once revealed, shows the figures beside it.
  if (row != nullptr && row->hand_pulled && row->measured_yet) return hand_pulled_note;
  return "measured: " + (row ? measured_shown(*row) : std::string("not yet"));
}

// A prediction's answer and note: their widths, and whether each starts a line.
struct AnswerLayout {
  std::vector<float> widths;
  std::vector<bool> breaks;
  int lines() const { return static_cast<int>(std::count(breaks.begin(), breaks.end(), true)); }
};
AnswerLayout answer_layout(const lessons::Prediction& prediction, const std::string& note, float width) {
  AnswerLayout layout;
  layout.widths = answer_widths(prediction);
  layout.widths.push_back(std::min(width, ImGui::CalcTextSize(note.c_str()).x));
  layout.breaks = line_breaks(layout.widths, width);
  return layout;
}

void before_the_reveal(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                       classroom_state::ClassPredictions& predictions, bool editable, const draw::Theme& theme,
                       const PredictionControls& controls) {
  // The button first: in a short column the questions scroll, and the reveal stays at hand.
  if (ImGui::Button(reveal_label) && controls.reveal) controls.reveal();
  if (controls.remember) controls.remember("reveal");
  const ImRect button(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  draw::note_text_centred(reveal_label, button);
  const float width = ImGui::GetContentRegionAvail().x;
  if (intro_beside(width)) {
    ImGui::SameLine();
    ImGui::AlignTextToFramePadding();
  }
  wrapped(intro(editable), std::nullopt, true);
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    ImGui::PushID(prediction.expectation.c_str());
    wrapped(prediction.question.c_str());
    const std::string before = answer_of(predictions, prediction);
    bool fault = false;
    const std::string note = answer_note(prediction, before, named_row(rows, prediction), fault);
    const AnswerLayout layout = answer_layout(prediction, note, width);
    std::size_t item = 0;
    const auto place = [&] {
      if (!layout.breaks[item]) ImGui::SameLine();
      ++item;
    };
    if (!editable) ImGui::BeginDisabled();
    if (prediction.is_choice()) {
      for (const std::string& word : prediction.choices) {
        place();
        if (ImGui::RadioButton(word.c_str(), before == word)) predictions.answers[prediction.expectation] = word;
        const ImRect circle(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
        draw::note_text_in(word.c_str(),
                     ImVec2(circle.Min.x + ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x,
                            circle.Min.y + ImGui::GetStyle().FramePadding.y),
                     circle);
        if (controls.remember) controls.remember("prediction " + prediction.expectation + ": " + word);
      }
    } else {
      place();
      char typed[answer_length + 1] = {};
      std::snprintf(typed, sizeof typed, "%s", before.c_str());
      ImGui::SetNextItemWidth(std::min(answer_box_width(), width));
      // A number: no blank joins it ("40 " read as "not a number"), and Space ends the typing and
      // plays (the window's rule for boxes that take a number, classroom/text_boxes.h).
      if (ImGui::InputText("##answer", typed, sizeof typed, ImGuiInputTextFlags_CharsNoBlank)) {
        predictions.answers[prediction.expectation] = typed;
      }
      takes_a_number();
      if (controls.remember) controls.remember("prediction " + prediction.expectation);
      const ImRect box(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
      draw::note_text_in(typed, ImVec2(box.Min.x + ImGui::GetStyle().FramePadding.x, box.Min.y + ImGui::GetStyle().FramePadding.y),
                   box);
      if (!prediction.unit.empty()) {
        place();
        ImGui::AlignTextToFramePadding();
        draw::shown_text(prediction.unit.c_str());
      }
    }
    if (!editable) ImGui::EndDisabled();
    place();
    // On the answer's line, level with its text; or wrapped on a line of its own.
    if (!layout.breaks.back()) ImGui::AlignTextToFramePadding();
    if (fault) {
      wrapped(note.c_str(), theme.bad);
    } else {
      wrapped(note.c_str(), std::nullopt, true);
    }
    ImGui::PopID();
  }
}

// How close the class came; while a mystery withholds the theory, against the run only.
Closeness judged(const lessons::Prediction& prediction, const std::string& answer, const lessons::ExpectationResult& row,
                 bool theory_withheld) {
  if (theory_withheld && !answer.empty() && !row.measured_yet) return {"class: judged once the run has measured it", false};
  // Against the theory is no judging while the mystery keeps it (closeness would give it away).
  if (theory_withheld && !answer.empty() && row.hand_pulled) {
    return {"class: judged once a run without the hand has measured it (R)", false};
  }
  return closeness(prediction, answer, row);
}

// The class's answer at its widest whatever the class answers: a number of three figures with
// a sign as typed ("-88.8 N"), or the longest word.
std::string widest_answer(const lessons::Prediction& prediction) {
  if (!prediction.is_choice()) return answer_shown(prediction, "-88.8");
  std::string widest;
  for (const std::string& word : prediction.choices) {
    if (word.size() > widest.size()) widest = word;
  }
  return widest;
}

// Once the theory is shown, nothing: the class's answers are a column of the theory table
// (class_answers). While a mystery keeps the theory, the class's answer, the theory (hidden) and the
// measurement side by side, each row's name above them and how close the class came below.
void after_the_reveal(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                      const classroom_state::ClassPredictions& predictions, const draw::Theme& theme, bool theory_withheld,
                      bool lines_in_table) {
  const float table_width = ImGui::GetContentRegionAvail().x;
  const float padding = 2.0f * ImGui::GetStyle().CellPadding.x;
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame |
                                ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_NoClip;
  // With the theory shown the class's answers are a column of the theory table (class_answers), or,
  // where the table cannot be whole in the column, each under its row's name above the table,
  // all in sight before the table's rows that scroll.
  if (!theory_withheld && lines_in_table) return;
  if (!theory_withheld) {
    if (!ImGui::BeginTable("class's answers", 1, flags)) return;
    for (const lessons::Prediction& prediction : lesson.predictions()) {
      const lessons::ExpectationResult* row = row_of(rows, prediction);
      const std::string answer = answer_of(predictions, prediction);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(ImGuiCol_TableHeaderBg));
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + table_width - padding);
      draw::shown_text(prediction.expectation.c_str());
      ImGui::PopTextWrapPos();
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const Closeness near = row ? judged(prediction, answer, *row, theory_withheld) : Closeness{"class: ?", false};
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + table_width - padding);
      if (near.close) ImGui::PushStyleColor(ImGuiCol_Text, theme.good);
      draw::shown_text(answer_and_closeness(prediction, answer, near).c_str());
      if (near.close) ImGui::PopStyleColor();
      ImGui::PopTextWrapPos();
    }
    ImGui::EndTable();
    return;
  }
  if (!ImGui::BeginTable("class against theory", 3, flags)) return;
  ImGui::TableSetupColumn("class");
  ImGui::TableSetupColumn("theory");
  ImGui::TableSetupColumn("measured");
  ImGui::TableHeadersRow();
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    const lessons::ExpectationResult* row = row_of(rows, prediction);
    const std::string answer = answer_of(predictions, prediction);
    // Spanning the row: drawn from the first cell, wrapped at the table's edge.
    const auto across = [&](const std::string& text, std::optional<ImU32> colour) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + table_width - padding);
      if (colour) ImGui::PushStyleColor(ImGuiCol_Text, *colour);
      draw::shown_text(text.c_str());
      if (colour) ImGui::PopStyleColor();
      ImGui::PopTextWrapPos();
    };
    across(prediction.expectation, std::nullopt);
    // Each row's name on the headers' shade, so the class's rows read as groups of three lines.
    ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(ImGuiCol_TableHeaderBg));
    // Each cell wraps at its column's edge: "0.602 N (hand-pulled)" is wider than a third of
    // the panel in projector mode, and the table has no room to scroll sideways.
    const auto cell = [](const std::string& text) {
      ImGui::TableNextColumn();
      ImGui::PushTextWrapPos(0.0f);
      draw::shown_text(text.c_str());
      ImGui::PopTextWrapPos();
    };
    ImGui::TableNextRow();
    cell(answer_shown(prediction, answer));
    cell(!row ? "?" : theory_withheld ? "hidden" : theory_shown(*row));
    cell(row ? measured_shown(*row) : "?");
    if (row != nullptr) {
      const Closeness near = judged(prediction, answer, *row, theory_withheld);
      across(near.words, near.close ? std::optional<ImU32>(theme.good) : std::nullopt);
    }
  }
  ImGui::EndTable();
}

}  // namespace

draw::ClassAnswers class_answers(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                                 const classroom_state::ClassPredictions& predictions) {
  draw::ClassAnswers answers;
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    const lessons::ExpectationResult* row = row_of(rows, prediction);
    const std::string answer = answer_of(predictions, prediction);
    const bool close = row != nullptr && judged(prediction, answer, *row, false).close;
    answers[prediction.expectation] = {answer_shown(prediction, answer), close, widest_answer(prediction)};
  }
  return answers;
}

// The theory and the measurement are the theory table's, drawn right under the class's lines
// (they were a second time in them, and the two tables pushed the last rows out of a
// projector's column).
std::string answer_and_closeness(const lessons::Prediction& prediction, const std::string& answer, const Closeness& near) {
  if (answer.empty()) return near.words;
  const std::string prefix = "class: ";
  const std::string judged = near.words.rfind(prefix, 0) == 0 ? near.words.substr(prefix.size()) : near.words;
  return prefix + answer_shown(prediction, answer) + " \u00b7 " + judged;
}

Closeness closeness(const lessons::Prediction& prediction, const std::string& answer,
                    const lessons::ExpectationResult& row) {
  if (answer.empty()) return {"class: no prediction", false};
  // Against what happened once it has, and the theory before; a run the mouse's hand pulled
  // measured the hand too, which no prediction was about: against the theory then.
  const bool measured = row.measured_yet && !row.hand_pulled;
  const char* against = measured ? "the measurement" : row.hand_pulled ? "the theory (the hand pulled this run)" : "the theory";
  if (prediction.is_choice() || !row.numeric) {
    const std::string truth = measured ? row.measured_text : row.predicted_text;
    if (prediction.is_choice() && offered_by(truth, answer)) return {"class: \u2713 right", true};
    return {std::string(measured ? "class: \u2717 the run says " : "class: \u2717 the theory says ") + truth, false};
  }
  std::string why;
  const std::optional<double> value = classroom_state::read_answer(answer, why);
  if (!value) return {why, false};
  const double reference = measured ? row.measured : row.predicted;
  const double off = *value - reference;
  std::string words = draw::format_quantity(off, prediction.unit.c_str());
  if (words.rfind("-", 0) == 0) {
    words.replace(0, 1, "\u2212");
  } else if (off > 0.0) {
    words.insert(words.begin(), '+');
  }
  const bool close = std::abs(off) <= 0.1 * std::abs(reference) || std::abs(off) <= row.tolerance;
  if (reference != 0.0) {
    char share[64];
    std::snprintf(share, sizeof share, ", %.0f %% %s ", 100.0 * std::abs(off) / std::abs(reference),
                  off >= 0.0 ? "above" : "below");
    words += share;
  } else {
    words += " from ";
  }
  return {"class: " + words + against, close};
}

void predictions_contents(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                          classroom_state::ClassPredictions& predictions, bool editable, const draw::Theme& theme,
                          const PredictionControls& controls, bool theory_withheld, bool lines_in_table) {
  if (predictions.revealed) {
    after_the_reveal(lesson, rows, predictions, theme, theory_withheld, lines_in_table);
  } else {
    before_the_reveal(lesson, rows, predictions, editable, theme, controls);
  }
}

float predictions_contents_height(const lessons::Lesson& lesson, const std::vector<lessons::ExpectationResult>& rows,
                                  const classroom_state::ClassPredictions& predictions, float width, bool theory_withheld,
                                  bool lines_in_table) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  const float frame = ImGui::GetFrameHeight() + style.ItemSpacing.y;
  float height = 0.0f;
  if (predictions.revealed && !theory_withheld && !lines_in_table) {
    // As after_the_reveal lays it out above the table: each row's name and the class's line.
    const float row_padding = 2.0f * style.CellPadding.y;
    const float across = width - 2.0f * style.CellPadding.x;
    for (const lessons::Prediction& prediction : lesson.predictions()) {
      height += ImGui::CalcTextSize(prediction.expectation.c_str(), nullptr, false, across).y + row_padding;
      const lessons::ExpectationResult* row = row_of(rows, prediction);
      const std::string answer = answer_of(predictions, prediction);
      const Closeness near = row ? judged(prediction, answer, *row, theory_withheld) : Closeness{"class: ?", false};
      height += ImGui::CalcTextSize(answer_and_closeness(prediction, answer, near).c_str(), nullptr, false, across).y + row_padding;
    }
    return height + style.ItemSpacing.y;
  }
  // In the theory table (lines_in_table), nothing above it.
  if (predictions.revealed && !theory_withheld) return 0.0f;
  if (predictions.revealed) {
    // As after_the_reveal lays it out: the headers, then each row's name, numbers and closeness.
    const float row_padding = 2.0f * style.CellPadding.y;
    const float across = width - 2.0f * style.CellPadding.x;
    height += font + row_padding;
    for (const lessons::Prediction& prediction : lesson.predictions()) {
      height += ImGui::CalcTextSize(prediction.expectation.c_str(), nullptr, false, across).y + row_padding;
      // The numbers' line: as high as its tallest cell, each wrapped in its third of the table.
      const lessons::ExpectationResult* numbers = row_of(rows, prediction);
      const float column = across / 3.0f - 2.0f * style.CellPadding.x;
      float tallest = font;
      for (const std::string& cell : {answer_shown(prediction, answer_of(predictions, prediction)),
                                      !numbers ? std::string("?") : theory_withheld ? std::string("hidden") : theory_shown(*numbers),
                                      numbers ? measured_shown(*numbers) : std::string("?")}) {
        tallest = std::max(tallest, ImGui::CalcTextSize(cell.c_str(), nullptr, false, column).y);
      }
      height += tallest + row_padding;
      if (const lessons::ExpectationResult* row = numbers) {
        const Closeness near = judged(prediction, answer_of(predictions, prediction), *row, theory_withheld);
        height += ImGui::CalcTextSize(near.words.c_str(), nullptr, false, across).y + row_padding;
      }
    }
    return height + style.ItemSpacing.y;
  }
  height += frame;  // the reveal button
  if (!intro_beside(width)) height += std::max(wrapped_height(intro(true), width), wrapped_height(intro(false), width));
  for (const lessons::Prediction& prediction : lesson.predictions()) {
    height += wrapped_height(prediction.question, width);
    bool fault = false;
    const std::string note =
        answer_note(prediction, answer_of(predictions, prediction), named_row(rows, prediction), fault);
    // The taller of the note now and the one held back while the box is empty: the column is
    // planned at t = 0, before the run measures anything, and the held-back note comes later.
    float tallest = 0.0f;
    for (const std::string& shown : {note, std::string(held_back_note)}) {
      const AnswerLayout layout = answer_layout(prediction, shown, width);
      // Each line of controls is a frame high; a note on a line of its own wraps.
      float lines = frame * static_cast<float>(layout.lines() - (layout.breaks.back() ? 1 : 0));
      if (layout.breaks.back()) lines += wrapped_height(shown, width);
      tallest = std::max(tallest, lines);
    }
    height += tallest;
  }
  return height;
}

std::string PredictionPanel::forget_outdated(const classroom_state::Playback& playback) {
  if (playback.lesson().scene().frame() != 0) return "";
  std::vector<std::string> outdated;
  for (const auto& [row_name, answer] : predictions.answers) {
    for (const lessons::ExpectationResult& row : playback.readings().expectations) {
      if (row.name != row_name || row.failed) continue;
      const std::string theory = row.numeric ? validation::exact_text(row.predicted) : row.predicted_text;
      const auto [seen, first] = predictions.theory_answered.emplace(row_name, theory);
      if (!first && seen->second != theory) outdated.push_back(row_name);
    }
  }
  for (const std::string& row_name : outdated) {
    predictions.answers.erase(row_name);
    predictions.theory_answered.erase(row_name);
  }
  // Rows no longer answered (a box emptied) are seen afresh when answered again.
  std::erase_if(predictions.theory_answered, [&](const auto& seen) { return predictions.answers.count(seen.first) == 0; });
  if (outdated.empty()) return "";
  return "A value changed after the class predicted \"" + outdated.front() + "\"" + (outdated.size() > 1 ? " (and more)" : "") +
         ": that prediction was for the old values, so it is cleared. " +
         (predictions.revealed ? "View > Predict again asks the class anew, the theory hidden." : "Ask the class again.");
}

void PredictionPanel::style(draw::FrameStyle& style, const classroom_state::Playback& playback, bool asking, const draw::Theme& colours,
                            ControlPlaces& controls, std::function<bool()> theory_withheld) {
  const lessons::Lesson& lesson = playback.lesson();
  // A teacher who takes no predictions, or a lesson that asks for none, has the theory table as it was.
  if (!asking || lesson.predictions().empty()) return;
  style.theory_hidden = classroom_state::theory_hidden(lesson, predictions, asking);
  // Before the reveal too: the column is planned for the table they will be in (it is drawn only once revealed).
  if (!theory_withheld()) style.class_answers = class_answers(lesson, playback.readings().expectations, predictions);
  style.predictions = [this, &playback, &colours, &controls, theory_withheld](bool lines_in_table) {
    // Answers are given before the run: once it has started they are what the class said.
    const bool editable = !predictions.revealed && playback.lesson().scene().frame() == 0;
    PredictionControls noted;
    noted.remember = [&controls](const std::string& name) { remember_item(controls, name); };
    noted.reveal = [this] { predictions.revealed = true; };
    predictions_contents(playback.lesson(), playback.readings().expectations, predictions, editable, colours, noted,
                         theory_withheld(), lines_in_table);
  };
  style.predictions_height = [this, &playback, theory_withheld](float width) {
    // The panel before the reveal and after it: the column is planned once for both, so that
    // nothing in it moves at the reveal (or when T hides the theory again).
    classroom_state::ClassPredictions asked = predictions, revealed = predictions;
    asked.revealed = false;
    revealed.revealed = true;
    const bool withheld = theory_withheld();
    const lessons::Lesson& on_show = playback.lesson();
    const float font_size = ImGui::GetFontSize();
    const auto& rows = playback.readings().expectations;
    const draw::FrameStyle::AnswersHeight height{predictions_contents_height(on_show, rows, asked, width, withheld),
                                                 predictions_contents_height(on_show, rows, revealed, width, withheld, false)};
    if (planned && planned->lesson_path == on_show.path() && planned->script_loads == playback.script_loads() &&
        planned->questions == on_show.predictions().size() && planned->width == width && planned->font_size == font_size) {
      planned->outgrown = height.asked > planned->height.asked || height.revealed_above > planned->height.revealed_above;
      return planned->height;
    }
    planned = PlannedHeight{on_show.path(), playback.script_loads(), on_show.predictions().size(), width, font_size, height, false};
    return height;
  };
  style.predictions_outgrew = [this] { return planned && planned->outgrown; };
}

bool PredictionPanel::theory_hidden(const lessons::Lesson& lesson, bool asking) const {
  return classroom_state::theory_hidden(lesson, predictions, asking);
}

void PredictionPanel::reveal_key(const lessons::Lesson& lesson, bool asking) {
  if (theory_hidden(lesson, asking)) {
    predictions.revealed = true;
  } else if (predictions.revealed && asking && !lesson.predictions().empty()) {
    predictions.revealed = false;
  }
}

std::string PredictionPanel::predict_again(classroom_state::Playback& playback) {
  predictions = {};
  playback.reset();
  return "New predictions: the class's answers are cleared, the theory is hidden, and the run is back at t = 0.";
}

std::optional<std::string> PredictionPanel::menu_items(bool& asking, classroom_state::Playback& playback, ControlPlaces& controls) {
  // Off: the theory shows from the start, as for a teacher who takes no predictions.
  ImGui::MenuItem("Ask for predictions first", nullptr, &asking);
  remember_item(controls, "Ask for predictions first");
  if (ImGui::MenuItem("Reveal the theory", "T", false, theory_hidden(playback.lesson(), asking))) predictions.revealed = true;
  // A second round: the teacher changed a value after the reveal, and the class predicts anew
  // (before, the theory stayed up and the old answers were judged against the new run).
  const bool answered = predictions.revealed || !predictions.answers.empty();
  const bool asks = asking && !playback.lesson().predictions().empty();
  std::optional<std::string> said;
  if (ImGui::MenuItem("Predict again (new answers, theory hidden)", nullptr, false, asks && answered)) said = predict_again(playback);
  remember_item(controls, "Predict again");
  return said;
}

}  // namespace frictionlab::classroom
