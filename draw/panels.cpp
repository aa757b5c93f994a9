#include "draw/panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include "draw/overlays.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "lessons/runtime/class_words.h"
#include "lessons/runtime/model_card.h"

namespace frictionlab::draw {

bool begin_panel(const char* id, const char* title, ImVec2 corner, ImVec2 size, bool scroll) {
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  // No scroll bars: a picture cannot be scrolled, so what does not fit is cut at the edge.
  ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                           ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (!scroll) flags |= ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
  if (title == nullptr || *title == '\0') flags |= ImGuiWindowFlags_NoTitleBar;
  const std::string label = std::string(title ? title : "") + "###" + id;
  const bool open = ImGui::Begin(label.c_str(), nullptr, flags);
  if (title != nullptr) note_title(title);
  return open;
}

void end_panel() { ImGui::End(); }

bool begin_tab(const char* label, int flags) {
  const bool open = ImGui::BeginTabItem(label, nullptr, flags);
  // A tab too narrow for its name shows it cut with an ellipsis.
  const ImVec2 padding = ImGui::GetStyle().FramePadding;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  note_text_in(label, ImVec2(min.x + padding.x, min.y + padding.y), ImRect(min.x + padding.x, min.y, max.x - padding.x + 0.5f, max.y));
  return open;
}

void title_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size, const Fonts& fonts, bool one_line,
                 float one_line_padding) {
  if (one_line) ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetStyle().WindowPadding.x, one_line_padding));
  if (begin_panel("title", "", corner, size)) {
    char clock[32];
    std::snprintf(clock, sizeof clock, "t = %.2f s", lesson.scene().time());
    ImGui::PushFont(fonts.title);
    const float clock_width = ImGui::CalcTextSize(clock).x;
    const float clock_x = ImGui::GetWindowContentRegionMax().x - clock_width;
    const float room = clock_x - 12.0f * fonts.scale;
    // A long title stops short of the clock: wrapped onto the question's line on a screen; in
    // one line (projector mode), whose panel has no second line, cut with "…" where it would
    // wrap, so that what shows is whole and says it goes on.
    std::string title = lesson.title();
    if (one_line && ImGui::CalcTextSize(title.c_str()).x > room - ImGui::GetCursorPosX()) {
      const float ellipsis = ImGui::CalcTextSize("…").x;
      while (!title.empty() && ImGui::CalcTextSize(title.c_str()).x + ellipsis > room - ImGui::GetCursorPosX()) {
        // Drop the last character whole: its UTF-8 continuation bytes and its first byte.
        while (!title.empty() && (static_cast<unsigned char>(title.back()) & 0xC0u) == 0x80u) title.pop_back();
        if (!title.empty()) title.pop_back();
      }
      while (!title.empty() && title.back() == ' ') title.pop_back();
      title += "…";
    }
    ImGui::PushTextWrapPos(room);
    shown_text(title.c_str());
    ImGui::PopTextWrapPos();
    const ImVec2 title_end = ImGui::GetItemRectMax();
    const ImVec2 after_title = ImGui::GetCursorPos();
    ImGui::SetCursorPos(ImVec2(clock_x, ImGui::GetStyle().WindowPadding.y));
    shown_text(clock);
    ImGui::SetCursorPos(after_title);
    ImGui::PopFont();
    if (!one_line) {
      ImGui::PushTextWrapPos(0.0f);
      shown_text(lesson.question().c_str());
      ImGui::PopTextWrapPos();
    } else {
      // One line (projector mode): the question after the title, on its baseline, where it
      // fits before the clock; else the teacher asks it (the plots have the height).
      const float gap = 16.0f * fonts.scale;
      const float x = title_end.x - ImGui::GetWindowPos().x + gap;
      if (x + ImGui::CalcTextSize(lesson.question().c_str()).x <= room) {
        ImGui::SetCursorPos(ImVec2(x, ImGui::GetStyle().WindowPadding.y + fonts.title->Ascent - fonts.body->Ascent));
        shown_text(lesson.question().c_str());
      }
    }
  }
  end_panel();
  if (one_line) ImGui::PopStyleVar();
}

std::string pair_of(const lessons::Parameter& parameter) {
  return parameter.coefficient == nullptr ? "" : parameter.material_a + " on " + parameter.material_b;
}

std::vector<std::string> parameter_pairs(const lessons::Lesson& lesson) {
  std::vector<std::string> pairs;
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    const std::string pair = pair_of(parameter);
    if (!pair.empty() && std::find(pairs.begin(), pairs.end(), pair) == pairs.end()) pairs.push_back(pair);
  }
  return pairs;
}

std::string pair_values(const lessons::Lesson& lesson, const std::string& pair, const HiddenValues& hidden) {
  std::string line;
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    // Drag coefficients at 0 are off: not worth a place on a folded line.
    const PairCoefficient* coefficient = parameter.coefficient;
    if (coefficient == nullptr || pair_of(parameter) != pair || (parameter.value == 0.0 && coefficient->drag)) continue;
    const std::string letter = lessons::class_words(coefficient->name);
    // Without units: the sliders, one arrow away, have them.
    char value[32];
    std::snprintf(value, sizeof value, "%g", parameter.value);
    if (hidden.hides(parameter.name)) std::snprintf(value, sizeof value, "?");
    line += (line.empty() ? "" : "  ") + letter + " " + value;
  }
  return line;
}

namespace {

// The rows of the values' table: a parameter, or a folded pair's one line.
struct ValueRow {
  std::string name, value;
};

std::vector<ValueRow> value_rows(const lessons::Lesson& lesson, std::size_t folded_pairs, const HiddenValues& hidden) {
  const std::vector<std::string> pairs = parameter_pairs(lesson);
  const std::size_t first_folded = pairs.size() - std::min(folded_pairs, pairs.size());
  std::vector<ValueRow> rows;
  std::vector<std::string> listed;
  for (const lessons::Parameter& parameter : lesson.parameters()) {
    const std::string pair = pair_of(parameter);
    const auto at = std::find(pairs.begin(), pairs.end(), pair);
    const bool folded = !pair.empty() && static_cast<std::size_t>(at - pairs.begin()) >= first_folded;
    if (!folded) {
      rows.push_back({lessons::parameter_title(parameter), hidden.hides(parameter.name) ? hidden_value_text : parameter.shown()});
    } else if (std::find(listed.begin(), listed.end(), pair) == listed.end()) {
      listed.push_back(pair);
      rows.push_back({pair, pair_values(lesson, pair, hidden)});
    }
  }
  return rows;
}

}  // namespace

float parameters_panel_height(const lessons::Lesson& lesson, float width, std::size_t folded_pairs,
                              const HiddenValues& hidden) {
  const ImGuiStyle& style = ImGui::GetStyle();
  // Two columns of equal weight; a value wraps in its half.
  const float half = 0.5f * (width - 2.0f * style.WindowPadding.x) - 2.0f * style.CellPadding.x;
  float height = ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y + 4.0f * style.ItemSpacing.y;
  for (const ValueRow& row : value_rows(lesson, folded_pairs, hidden)) {
    const float name = ImGui::CalcTextSize(row.name.c_str(), nullptr, false, half).y;
    const float value = ImGui::CalcTextSize(row.value.c_str(), nullptr, false, half).y;
    height += std::max(name, value) + 2.0f * style.CellPadding.y;
  }
  return height;
}

void parameters_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size, std::size_t folded_pairs,
                      const HiddenValues& hidden) {
  if (begin_panel("parameters", "Parameters", corner, size)) {
    if (ImGui::BeginTable("values", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      for (const ValueRow& row : value_rows(lesson, folded_pairs, hidden)) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::PushTextWrapPos(0.0f);
        shown_text(row.name.c_str());
        ImGui::TableNextColumn();
        shown_text(row.value.c_str());
        ImGui::PopTextWrapPos();
      }
      ImGui::EndTable();
    }
  }
  end_panel();
}

namespace {

std::string with_unit(double value, const std::string& unit) {
  return format_quantity(value, unit.c_str());
}

// Each row's three cells as text, so the layout can be chosen from their widths.
struct TheoryCells {
  struct Cells {
    std::string theory, measured, error;
    std::string answer;  // the class's (its column: TheoryColumns::verdicts with the answers), "" for a row not predicted
    bool answer_close = false;
    std::string verdict;  // without the error column: the mark after the measured value ("\u2713")
    bool measured_yet, passes, hand_pulled;
    int error_lines = 1;  // 2: the error's unit under its number
  };
  std::vector<Cells> cells;
  std::string error_heading;  // "error", or "error (N)" when every numeric row is in newtons
  bool error_column = true;
  bool class_column = false;  // the class's answers between the theory and the measurement
  float widest[3];            // theory, measured, and the error or the class's answers
  bool planned = false;       // each number's column exactly widest[]: the plan's widths (planned_cells)
  float numbers() const {
    return widest[0] + widest[1] + widest[2] + (error_column || class_column ? 6.0f : 4.0f) * ImGui::GetStyle().CellPadding.x;
  }
  // Beside the numbers, a name needs room for a word or two; with large text in a narrow
  // column there is none, and each name goes on a line of its own above its numbers.
  bool names_above(float table_width) const { return table_width - numbers() < 9.0f * ImGui::CalcTextSize("m").x; }
};

// A row that states a claim's verdict of its own after " \u00b7 " (check_the_article's "first slip
// (article: 0.42 s) \u00b7 does not hold"): its mark says in words that it checks the simulation
// against the theory, since a bare \u2713 beside "does not hold" reads to a class as a contradiction.
bool claims_verdict(const lessons::ExpectationResult& row) { return row.name.find(" \u00b7 ") != std::string::npos; }

// What goes before the error: \u2713 or \u2717, or the words for a row with a verdict of its own.
std::string pass_mark(const lessons::ExpectationResult& row) {
  if (claims_verdict(row)) return row.passes ? "model agrees " : "model differs ";
  return row.passes ? "\u2713 " : "\u2717 ";
}

// The unit every numeric row shares, "" when they have none or differ.
std::string shared_unit(const std::vector<lessons::ExpectationResult>& rows) {
  std::string unit;
  bool first = true;
  for (const lessons::ExpectationResult& row : rows) {
    if (!row.numeric) continue;
    if (!first && row.unit != unit) return "";
    unit = row.unit;
    first = false;
  }
  return unit;
}

// ImGui's row of column headings (as TableHeadersRow draws it), each heading noted, so the
// layout test sees one its column cuts.
void noted_headers(int columns) {
  ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
  for (int column = 0; column < columns; ++column) {
    if (!ImGui::TableSetColumnIndex(column)) continue;
    const char* name = ImGui::TableGetColumnName(column);
    const ImVec2 start = ImGui::GetCursorScreenPos();
    ImGui::PushID(column);
    ImGui::TableHeader(name);
    ImGui::PopID();
    // The heading is drawn from the cursor up to its cell's right edge.
    if (*name != '\0') note_text_in(name, start, ImRect(start, ImGui::GetItemRectMax()));
  }
}

// The table's cells for a table `width` wide.
// Without the error column (TheoryColumns::verdicts) each measured value has its verdict after it,
// and the class's answers, where given, have a column of their own, as wide as the widest each may read.
TheoryCells theory_cells(const std::vector<lessons::ExpectationResult>& rows, bool predictions_hidden, float width,
                         TheoryColumns columns, const ClassAnswers& answers = {}) {
  // The error's unit: once in the heading when every row has it (the cells stay narrow and the
  // names keep their room), else in each cell, after the number, or under it in a cell that
  // would not fit across the table with it beside (projector text).
  const std::string unit_for_all = shared_unit(rows);
  const bool error_column = columns == TheoryColumns::errors;
  TheoryCells table{{}, unit_for_all.empty() ? "error" : "error (" + unit_for_all + ")", error_column,
                    !error_column && !answers.empty(), {}};
  float* widest = table.widest;
  widest[0] = ImGui::CalcTextSize("theory").x;
  widest[1] = ImGui::CalcTextSize("measured").x;
  widest[2] = error_column ? ImGui::CalcTextSize(table.error_heading.c_str()).x
              : table.class_column ? ImGui::CalcTextSize("class").x
                                   : 0.0f;
  for (const lessons::ExpectationResult& row : rows) {
    TheoryCells::Cells cell{row.numeric ? with_unit(row.predicted, row.unit) : row.predicted_text, "not yet", "",
                            "", false, "", row.measured_yet, row.passes, row.hand_pulled && !row.passes};
    if (const auto answer = answers.find(row.name); table.class_column && answer != answers.end()) {
      cell.answer = answer->second.answer;
      cell.answer_close = answer->second.close;
      for (const std::string* text : {&answer->second.answer, &answer->second.widest}) {
        widest[2] = std::max(widest[2], ImGui::CalcTextSize(text->c_str()).x);
      }
    }
    if (predictions_hidden) cell.theory = "hidden";
    // Its function failed (the message above the table says how): nothing of it is known.
    if (row.failed) {
      cell.theory.assign(1, '?');
      cell.measured.assign(1, '?');
    }
    if (row.measured_yet) {
      cell.measured = row.numeric ? with_unit(row.measured, row.unit) : row.measured_text;
      if (predictions_hidden) {
        cell.error = "";  // measured minus predicted would give the prediction away
      } else if (row.numeric) {
        std::string number = with_unit(row.error(), "");
        number.pop_back();
        cell.error = pass_mark(row) + std::string(row.error() > 0.0 ? "+" : "") + number;
        if (unit_for_all.empty() && !row.unit.empty()) cell.error += " " + row.unit;
      } else {
        cell.error = claims_verdict(row) ? pass_mark(row) : row.passes ? "\u2713 agrees" : "\u2717 differs";
      }
      // Not a failure: the hand's pull is in no prediction (the caveat above says when it pulled).
      if (row.hand_pulled && !row.passes) cell.error = "hand-pulled";
      if (!error_column && !cell.error.empty()) {
        // The verdict alone: the mark, or the words a claim's row or the hand's pull has.
        cell.verdict = cell.hand_pulled ? cell.error : pass_mark(row);
        if (cell.verdict.back() == ' ') cell.verdict.pop_back();
        cell.error.clear();
      }
    }
    widest[0] = std::max(widest[0], ImGui::CalcTextSize(cell.theory.c_str()).x);
    widest[1] = std::max(widest[1], ImGui::CalcTextSize(cell.measured.c_str()).x +
                                        (cell.verdict.empty() ? 0.0f
                                                              : ImGui::GetStyle().ItemSpacing.x +
                                                                    ImGui::CalcTextSize(cell.verdict.c_str()).x));
    table.cells.push_back(std::move(cell));
  }
  if (!error_column) return table;
  const float room = width - widest[0] - widest[1] - 6.0f * ImGui::GetStyle().CellPadding.x;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    TheoryCells::Cells& cell = table.cells[i];
    // A mark in words goes on a line of its own over the number where the two do not fit.
    const std::string mark = pass_mark(rows[i]);
    if (ImGui::CalcTextSize(cell.error.c_str()).x > room && claims_verdict(rows[i]) && rows[i].numeric && !cell.hand_pulled &&
        cell.error.compare(0, mark.size(), mark) == 0) {
      cell.error[mark.size() - 1] = '\n';
      cell.error_lines = 2;
    }
    if (ImGui::CalcTextSize(cell.error.c_str()).x > room && unit_for_all.empty() && !rows[i].unit.empty() &&
        cell.error.size() > rows[i].unit.size() + 1 && rows[i].numeric && !cell.hand_pulled) {
      cell.error[cell.error.size() - rows[i].unit.size() - 1] = '\n';
      ++cell.error_lines;
    }
    widest[2] = std::max(widest[2], ImGui::CalcTextSize(cell.error.c_str()).x);
  }
  return table;
}

// `rows` as a run ends them: each measured, passing or failing, with the values `measure` gives it,
// and written as its theory is.
template <typename Measure>
std::vector<lessons::ExpectationResult> ended_run(std::vector<lessons::ExpectationResult> rows, bool passes,
                                                  const Measure& measure) {
  for (lessons::ExpectationResult& row : rows) {
    if (row.failed) continue;
    row.measured_yet = true;
    row.hand_pulled = false;
    row.passes = passes;
    measure(row);
    row.measured_text = row.predicted_text;
  }
  return rows;
}

// The rows as a run may end them, whatever values it and the sliders give, so that none changes
// the plan: each number as wide as three figures with a sign ("−88.8 N"), each word as the theory
// says it, the error at the wider of its two forms ("−0.00888", "−8.8×10⁻¹⁰"), each row passing
// and failing (their marks differ in width).
std::vector<std::vector<lessons::ExpectationResult>> ended_runs(const std::vector<lessons::ExpectationResult>& rows) {
  std::vector<std::vector<lessons::ExpectationResult>> runs;
  for (const double off : {-0.00888, -8.8e-10}) {
    for (const bool passes : {true, false}) {
      runs.push_back(ended_run(rows, passes, [off](lessons::ExpectationResult& row) {
        row.predicted = -88.8;
        row.measured = row.predicted + off;
      }));
    }
  }
  return runs;
}

// The rows at the run's end with each measured just as its theory says, passing and failing: a
// measurement of what its theory predicts is of the same size, and as wide written.
std::vector<std::vector<lessons::ExpectationResult>> measured_as_the_theory(const std::vector<lessons::ExpectationResult>& rows) {
  std::vector<std::vector<lessons::ExpectationResult>> runs;
  for (const bool passes : {true, false}) {
    runs.push_back(ended_run(rows, passes, [](lessons::ExpectationResult& row) { row.measured = row.predicted; }));
  }
  return runs;
}

// A projector's table (TheoryColumns::verdicts) is planned at its tallest from the lesson's
// opening (theory_contents_tallest_height), its columns as wide as any run's values make them
// (ended_runs): it is drawn at those widths, so that no column narrows or widens as the run fills
// its rows in or as R takes them back to "not yet", no name wraps anew, and no row moves under
// the teacher's pointer (issue 31: at the run's end stacked_blocks' last row came 106 px down,
// names above it wrapped anew beside measurements wider than "not yet"; R put it back). `with_the_values`:
// the columns drawn are wider where this lesson's values need it, its theory's as they are and
// each measured value as wide as its theory (wedge's "\u22120.0636 m \u2713", wider than "\u221288.8 m \u2713"); the
// plan is the placeholders' alone, which no slider changes, so that the column's plan holds while
// the teacher drags one. A measurement wider still (another order of magnitude than its theory's)
// widens its column as it comes.
TheoryCells planned_cells(const std::vector<lessons::ExpectationResult>& rows, bool predictions_hidden, float width,
                          TheoryColumns columns, const ClassAnswers& answers, bool with_the_values = true) {
  TheoryCells table = theory_cells(rows, predictions_hidden, width, columns, answers);
  if (columns != TheoryColumns::verdicts) return table;
  table.planned = true;
  std::vector<std::vector<lessons::ExpectationResult>> runs = ended_runs(rows);
  if (with_the_values) {
    for (std::vector<lessons::ExpectationResult>& run : measured_as_the_theory(rows)) runs.push_back(std::move(run));
  } else {
    std::fill(std::begin(table.widest), std::end(table.widest), 0.0f);
  }
  for (const std::vector<lessons::ExpectationResult>& ended : runs) {
    const TheoryCells run = theory_cells(ended, predictions_hidden, width, columns, answers);
    for (int column = 0; column < 3; ++column) table.widest[column] = std::max(table.widest[column], run.widest[column]);
  }
  return table;
}

// The height of `table`'s rows and headers (theory_contents draws them) at a width, in the current font.
float rows_height(const std::vector<lessons::ExpectationResult>& rows, const TheoryCells& table, float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  const float row_padding = 2.0f * style.CellPadding.y;  // above and below a row's text
  const bool above = table.names_above(width);
  const float padding = 2.0f * style.CellPadding.x;
  // The names wrap as theory_contents wraps them: across the row, or in what the numbers leave.
  const float name_width = above ? width - padding : std::max(1.0f, width - table.numbers() - padding);
  float height = font + row_padding;  // the headers
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const float name = ImGui::CalcTextSize(rows[i].name.c_str(), nullptr, false, name_width).y;
    const float numbers = static_cast<float>(table.cells[i].error_lines) * font;
    height += above ? name + numbers + 2.0f * row_padding : std::max(name, numbers) + row_padding;
  }
  return height;
}

}  // namespace

void theory_panel(const std::vector<lessons::ExpectationResult>& rows, ImVec2 corner, ImVec2 size, const Theme& theme,
                  const std::string& error, const std::string& caveat, bool predictions_hidden, TheoryColumns columns) {
  if (begin_panel("theory", "Theory against simulation", corner, size)) {
    theory_contents(rows, theme, error, caveat, predictions_hidden, {}, columns);
  }
  end_panel();
}

namespace {

// The theory table's columns: numbers only where each row's name stands above them
// (`names_above`), else a name column first; the class's answers and the error where shown.
void setup_theory_columns(const TheoryCells& table, bool names_above) {
  const float* widest = table.widest;
  if (names_above) {
    // Widths from the numbers alone: the names, drawn in the first cell, must not widen it.
    ImGui::TableSetupColumn("theory", ImGuiTableColumnFlags_WidthFixed, widest[0]);
    if (table.class_column) ImGui::TableSetupColumn("class", ImGuiTableColumnFlags_WidthFixed, widest[2]);
    if (table.error_column) {
      ImGui::TableSetupColumn("measured", ImGuiTableColumnFlags_WidthFixed, widest[1]);
      ImGui::TableSetupColumn(table.error_heading.c_str(), ImGuiTableColumnFlags_WidthStretch);
    } else {
      ImGui::TableSetupColumn("measured", ImGuiTableColumnFlags_WidthStretch);
    }
  } else {
    // The numbers' columns fit what they hold, or (planned) the widest the run may give them,
    // and the names take the rest.
    const ImGuiTableColumnFlags fixed = table.planned ? ImGuiTableColumnFlags_WidthFixed : ImGuiTableColumnFlags_None;
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("theory", fixed, table.planned ? widest[0] : 0.0f);
    if (table.class_column) ImGui::TableSetupColumn("class", ImGuiTableColumnFlags_WidthFixed, widest[2]);
    ImGui::TableSetupColumn("measured", fixed, table.planned ? widest[1] : 0.0f);
    if (table.error_column) ImGui::TableSetupColumn(table.error_heading.c_str());
  }
}

// A verdict or an error in its colour: grey for a hand's pull (no theory to judge it by), else
// good or bad.
void judged_text(const std::string& text, const TheoryCells::Cells& cell, const Theme& theme) {
  if (cell.hand_pulled) {
    ImGui::TextDisabled("%s", text.c_str());
  } else {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(cell.passes ? theme.good : theme.bad), "%s", text.c_str());
  }
  note_text(text.c_str());
}

// One expectation's row (two, its name above, where `names_above`): its name, theory, the
// class's answer, what was measured with its verdict, and the error.
void theory_row(const std::string& name, const TheoryCells::Cells& cell, const TheoryCells& table, const Theme& theme,
                bool names_above, float table_width) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  if (names_above) {
    // The name across the whole row: drawn from the first cell, wrapped at the table's edge.
    const float padding = 2.0f * ImGui::GetStyle().CellPadding.x;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + table_width - padding);
    shown_text(name.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
  } else {
    ImGui::TextWrapped("%s", name.c_str());
    note_text(name.c_str());
    ImGui::TableNextColumn();
  }
  shown_text(cell.theory.c_str());
  ImGui::TableNextColumn();
  if (table.class_column) {
    if (cell.answer_close) ImGui::PushStyleColor(ImGuiCol_Text, theme.good);
    if (!cell.answer.empty()) shown_text(cell.answer.c_str());
    if (cell.answer_close) ImGui::PopStyleColor();
    ImGui::TableNextColumn();
  }
  if (!cell.measured_yet) {
    // "not yet", or a failed row's "?" (as the class's table beside it shows it).
    ImGui::TextDisabled("%s", cell.measured.c_str());
    note_text(cell.measured.c_str());
    if (table.error_column) ImGui::TableNextColumn();
    return;
  }
  shown_text(cell.measured.c_str());
  if (!cell.verdict.empty()) {
    ImGui::SameLine();
    judged_text(cell.verdict, cell, theme);
  }
  if (!table.error_column) return;
  ImGui::TableNextColumn();
  if (!cell.error.empty()) judged_text(cell.error, cell, theme);
}

}  // namespace

void theory_contents(const std::vector<lessons::ExpectationResult>& rows, const Theme& theme, const std::string& error,
                     const std::string& caveat, bool predictions_hidden, const ClassAnswers& answers, TheoryColumns columns) {
  ImGui::PushTextWrapPos(0.0f);
  if (!error.empty()) {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme.bad), "%s", error.c_str());
    note_text(error.c_str());
  }
  if (!caveat.empty()) {
    ImGui::TextDisabled("%s", caveat.c_str());
    note_text(caveat.c_str());
  }
  ImGui::PopTextWrapPos();
  if (rows.empty() && !error.empty()) return;
  if (rows.empty()) {
    const char* none = "This lesson states no expectations (expect{} in its script).";
    ImGui::TextDisabled("%s", none);
    note_text(none);
    return;
  }
  const float table_width = ImGui::GetContentRegionAvail().x;
  const TheoryCells table = planned_cells(rows, predictions_hidden, table_width, columns, answers);
  const int numbers = table.error_column || table.class_column ? 3 : 2;
  const bool names_above = table.names_above(table_width);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerH;
  // A name above its numbers spans the row: the cells must not clip it.
  if (ImGui::BeginTable("rows", names_above ? numbers : numbers + 1, names_above ? flags | ImGuiTableFlags_NoClip : flags)) {
    // The numbers keep their width; a long name wraps.
    setup_theory_columns(table, names_above);
    noted_headers(names_above ? numbers : numbers + 1);
    for (std::size_t i = 0; i < rows.size(); ++i) theory_row(rows[i].name, table.cells[i], table, theme, names_above, table_width);
    ImGui::EndTable();
  }
}

float theory_contents_height(const std::vector<lessons::ExpectationResult>& rows, float width, const std::string& error,
                             const std::string& caveat, bool predictions_hidden, TheoryColumns columns) {
  const ImGuiStyle& style = ImGui::GetStyle();
  float height = 0.0f;
  for (const std::string* text : {&error, &caveat}) {
    if (!text->empty()) height += ImGui::CalcTextSize(text->c_str(), nullptr, false, width).y + style.ItemSpacing.y;
  }
  if (rows.empty()) return height + ImGui::GetFontSize() + style.ItemSpacing.y;
  const TheoryCells table = planned_cells(rows, predictions_hidden, width, columns, {});
  return height + rows_height(rows, table, width) + style.ItemSpacing.y;
}

float theory_contents_tallest_height(const std::vector<lessons::ExpectationResult>& rows, float width,
                                     const std::string& error, const std::string& caveat, bool predictions_hidden,
                                     TheoryColumns columns, const ClassAnswers& answers) {
  if (rows.empty()) return theory_contents_height(rows, width, error, caveat, predictions_hidden, columns);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();
  const float row_padding = 2.0f * style.CellPadding.y;
  float height = 0.0f;
  for (const std::string* text : {&error, &caveat}) {
    if (!text->empty()) height += ImGui::CalcTextSize(text->c_str(), nullptr, false, width).y + style.ItemSpacing.y;
  }
  // Without the error column the table is drawn at the plan's widths (planned_cells): its height
  // is theirs, whatever the run has measured yet.
  if (columns == TheoryColumns::verdicts) {
    const TheoryCells table = planned_cells(rows, predictions_hidden, width, columns, answers, false);
    return height + rows_height(rows, table, width) + style.ItemSpacing.y;
  }
  // With it, whatever values the run gives (ended_runs), each error on as many lines as
  // theory_cells then breaks it into, and each name the taller of its two places: on lines of
  // its own across the row, or beside the numbers in the least room theory_contents leaves it
  // there (names_above: 9 m's).
  const float padding = 2.0f * style.CellPadding.x;
  const float least_beside = std::max(1.0f, 9.0f * ImGui::CalcTextSize("m").x - padding);
  std::vector<int> error_lines(rows.size(), 1);
  for (const std::vector<lessons::ExpectationResult>& ended : ended_runs(rows)) {
    const TheoryCells table = theory_cells(ended, predictions_hidden, width, columns, answers);
    for (std::size_t i = 0; i < rows.size(); ++i) error_lines[i] = std::max(error_lines[i], table.cells[i].error_lines);
  }
  height += font + row_padding;  // the headers
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const float numbers = static_cast<float>(error_lines[i]) * font;
    const float above = ImGui::CalcTextSize(rows[i].name.c_str(), nullptr, false, width - padding).y + numbers + 2.0f * row_padding;
    const float beside = std::max(ImGui::CalcTextSize(rows[i].name.c_str(), nullptr, false, least_beside).y, numbers) + row_padding;
    height += std::max(above, beside);
  }
  return height + style.ItemSpacing.y;
}

void energy_panel(const Scene& scene, ImVec2 corner, ImVec2 size, const Theme& theme) {
  if (begin_panel("energy", "Energy ledger (since t = 0)", corner, size)) energy_contents(scene, theme);
  end_panel();
}

namespace {

// The ledger's lines: what the bodies have, then what has been done to them since t = 0.
struct LedgerLine {
  const char* name;
  double value;
};
constexpr const char* stored_names[] = {"kinetic", "gravity", "spring"};
constexpr const char* work_names[] = {"work: applied", "driven bodies", "dry friction",
                                      "drag (c, b)",   "impacts",       "velocity set by the script"};

// The script's line only in lessons whose script has set a velocity: the others keep the
// panel they had.
std::size_t work_lines(const EnergyLedger& ledger) { return ledger.work_script != 0.0 ? 6 : 5; }

// One resolution for every line, 0.1 mJ, so the columns line up and add up by eye.
std::string joules(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f J", std::abs(value) < 5e-5 ? 0.0 : value);
  std::string shown = text;
  if (shown[0] == '-') shown.replace(0, 1, "\u2212");
  return shown;
}

// Whether the stored and the work lines fit side by side (four columns) in `width`, in the
// current font, with values as long as a ledger's usually are; else they go one under the
// other (two columns), as with large text in a narrow column (projector mode).
bool ledger_side_by_side(const EnergyLedger& ledger, float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const auto widest = [](const char* const* names, std::size_t count) {
    float w = 0.0f;
    for (std::size_t i = 0; i < count; ++i) w = std::max(w, ImGui::CalcTextSize(names[i]).x);
    return w;
  };
  const float value = ImGui::CalcTextSize("\u2212000.0000 J").x;
  const float cells = 4.0f * 2.0f * style.CellPadding.x + 3.0f * style.ItemSpacing.x;
  return widest(stored_names, 3) + widest(work_names, work_lines(ledger)) + 2.0f * value + cells <= width;
}

}  // namespace

float energy_contents_height(const Scene& scene, float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  // As energy_contents lays it out: the table's rows, then the residual, wrapped, at its
  // longest.
  const EnergyLedger& ledger = scene.ledger();
  const float rows = static_cast<float>(ledger_side_by_side(ledger, width) ? work_lines(ledger) : 3 + work_lines(ledger));
  const float table = rows * (ImGui::GetFontSize() + 2.0f * style.CellPadding.y) + style.ItemSpacing.y;
  const char* longest = "residual \u22124.7\u00d710\u207b\u2074 J, 100.00 % of the largest term";
  return table + ImGui::CalcTextSize(longest, nullptr, false, width).y + style.ItemSpacing.y;
}

void energy_contents(const Scene& scene, const Theme& theme) {
  {
    const EnergyLedger& ledger = scene.ledger();
    const LedgerLine stored[] = {{stored_names[0], ledger.kinetic}, {stored_names[1], ledger.potential},
                                 {stored_names[2], ledger.spring}};
    const LedgerLine work[] = {{work_names[0], ledger.work_applied}, {work_names[1], ledger.work_drivers},
                               {work_names[2], ledger.work_friction}, {work_names[3], ledger.work_damping},
                               {work_names[4], ledger.work_impacts},  {work_names[5], ledger.work_script}};
    const std::size_t lines = work_lines(ledger);
    const bool side_by_side = ledger_side_by_side(ledger, ImGui::GetContentRegionAvail().x);
    if (ImGui::BeginTable("ledger", side_by_side ? 4 : 2, ImGuiTableFlags_SizingFixedFit)) {
      const auto cell = [](const LedgerLine& line) {
        ImGui::TableNextColumn();
        shown_text(line.name);
        ImGui::TableNextColumn();
        shown_text(joules(line.value).c_str());
      };
      if (side_by_side) {
        for (std::size_t i = 0; i < lines; ++i) {
          ImGui::TableNextRow();
          if (i < 3) {
            cell(stored[i]);
          } else {
            ImGui::TableNextColumn();
            ImGui::TableNextColumn();
          }
          cell(work[i]);
        }
      } else {
        for (const LedgerLine& line : stored) {
          ImGui::TableNextRow();
          cell(line);
        }
        for (std::size_t i = 0; i < lines; ++i) {
          ImGui::TableNextRow();
          cell(work[i]);
        }
      }
      ImGui::EndTable();
    }
    // The residual is what the books cannot explain, judged against the largest amount in them:
    // a fall turns gravity into motion, a spring stores the hand's work, friction takes it.
    const double residual = ledger.residual();
    double largest = ledger.initial;
    for (double amount : {ledger.kinetic, ledger.potential, ledger.spring, ledger.work_applied, ledger.work_drivers,
                          ledger.work_friction, ledger.work_damping, ledger.work_impacts, ledger.work_script}) {
      largest = std::max(largest, std::abs(amount));
    }
    // A share of nothing says nothing: a block at rest has only float noise in its books.
    char share[64] = "";
    if (largest > 1e-3) std::snprintf(share, sizeof share, ", %.2f %% of the largest term", 100.0 * std::abs(residual) / largest);
    const bool small = std::abs(residual) <= 0.02 * std::max(largest, 1e-3);
    const std::string line = "residual " + format_quantity(residual, "J") + share;
    // Wrapped: with large text in a narrow column the share goes on a line of its own.
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(small ? theme.good : theme.bad), "%s", line.c_str());
    ImGui::PopTextWrapPos();
    note_text(line.c_str());
  }
}

void model_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size) {
  if (begin_panel("model", "Model card", corner, size)) model_contents(lesson);
  end_panel();
}

namespace {

// The model card's lines.
std::vector<std::string> model_lines(const lessons::Lesson& lesson) {
  const lessons::ModelCard card = lessons::model_card(lesson);
  std::vector<std::string> lines;
  const auto line = [&](const char* format, auto... values) {
    char text[256];
    std::snprintf(text, sizeof text, format, values...);
    lines.emplace_back(text);
  };
  const std::string held = card.constraints > 0 ? ", less " + std::to_string(card.constraints) + " held by joints" : "";
  line("%d degrees of freedom: %d moving bod%s%s", card.degrees_of_freedom, card.moving_bodies,
       card.moving_bodies == 1 ? "y" : "ies", held.c_str());
  std::string terms = card.dry ? "dry (\u03bcs, \u03bck)" : "no dry friction";
  terms += card.viscous ? ", viscous c" : ", no viscous c";
  terms += card.quadratic ? ", quadratic b" : ", no quadratic b";
  line("friction: %s", terms.c_str());
  line("%s treatment, %g steps per second", card.treatment.c_str(), card.hz);
  line("%d sub-step%s a step, %d velocity iterations", card.substeps, card.substeps == 1 ? "" : "s",
       card.velocity_iterations);
  // Pairs that name their own treatment say so; every other pair follows the run's.
  for (const lessons::ModelCard::PairLine& pair : card.pairs) {
    if (!pair.own) continue;
    char epsilon[48] = "";
    if (pair.epsilon > 0.0) std::snprintf(epsilon, sizeof epsilon, ", \u03b5 = %g m/s", pair.epsilon);
    line("  %s on %s: %s%s", pair.material_a.c_str(), pair.material_b.c_str(), pair.treatment.c_str(), epsilon);
  }
  return lines;
}

}  // namespace

void model_contents(const lessons::Lesson& lesson) {
  // Each line wrapped at the panel's edge (with projector text a line is longer than the
  // column) and noted as drawn, so the layout test sees a line the panel cuts.
  ImGui::PushTextWrapPos(0.0f);
  for (const std::string& line : model_lines(lesson)) shown_text(line.c_str());
  ImGui::PopTextWrapPos();
}

float model_contents_height(const lessons::Lesson& lesson, float width) {
  float height = 0.0f;
  for (const std::string& line : model_lines(lesson)) {
    height += ImGui::CalcTextSize(line.c_str(), nullptr, false, width).y + ImGui::GetStyle().ItemSpacing.y;
  }
  return height;
}

}  // namespace frictionlab::draw
