#include "ui/panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include "lessons/runtime/model_card.h"
#include "ui/overlays.h"

namespace frictionlab::ui {

bool begin_panel(const char* id, const char* title, ImVec2 corner, ImVec2 size) {
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  // No scroll bars: a picture cannot be scrolled, so what does not fit is cut at the edge.
  ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                           ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollbar |
                           ImGuiWindowFlags_NoScrollWithMouse;
  if (title == nullptr || *title == '\0') flags |= ImGuiWindowFlags_NoTitleBar;
  const std::string label = std::string(title ? title : "") + "###" + id;
  return ImGui::Begin(label.c_str(), nullptr, flags);
}

void end_panel() { ImGui::End(); }

void title_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size, const Fonts& fonts) {
  if (begin_panel("title", "", corner, size)) {
    char clock[32];
    std::snprintf(clock, sizeof clock, "t = %.2f s", lesson.scene().time());
    ImGui::PushFont(fonts.title);
    const float clock_width = ImGui::CalcTextSize(clock).x;
    const float clock_x = ImGui::GetWindowContentRegionMax().x - clock_width;
    // A long title stops short of the clock.
    ImGui::PushTextWrapPos(clock_x - 12.0f * fonts.scale);
    ImGui::TextUnformatted(lesson.title().c_str());
    ImGui::PopTextWrapPos();
    const ImVec2 after_title = ImGui::GetCursorPos();
    ImGui::SetCursorPos(ImVec2(clock_x, ImGui::GetStyle().WindowPadding.y));
    ImGui::TextUnformatted(clock);
    ImGui::SetCursorPos(after_title);
    ImGui::PopFont();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(lesson.question().c_str());
    ImGui::PopTextWrapPos();
  }
  end_panel();
}

std::string parameter_title(const lessons::Parameter& parameter) {
  if (parameter.coefficient.empty()) return parameter.name;
  const std::string letter = parameter.coefficient == "mu_s"   ? "\u03bcs"
                             : parameter.coefficient == "mu_k" ? "\u03bck"
                                                               : parameter.coefficient;
  return letter + "  " + parameter.material_a + " / " + parameter.material_b;
}

void parameters_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size) {
  if (begin_panel("parameters", "Parameters", corner, size)) {
    if (ImGui::BeginTable("values", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      for (const lessons::Parameter& parameter : lesson.parameters()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(parameter_title(parameter).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(parameter.shown().c_str());
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

}  // namespace

void theory_panel(const std::vector<lessons::ExpectationResult>& rows, ImVec2 corner, ImVec2 size, const Theme& theme,
                  const std::string& error, const std::string& caveat) {
  if (begin_panel("theory", "Theory against simulation", corner, size)) {
    ImGui::PushTextWrapPos(0.0f);
    if (!error.empty()) ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(theme.bad), "%s", error.c_str());
    if (!caveat.empty()) ImGui::TextDisabled("%s", caveat.c_str());
    ImGui::PopTextWrapPos();
    if (rows.empty() && !error.empty()) {
      end_panel();
      return;
    }
    if (rows.empty()) {
      ImGui::TextDisabled("This lesson states no expectations (expect{} in its script).");
      end_panel();
      return;
    }
    // Each row's three cells as text, so the layout can be chosen from their widths.
    struct Cells {
      std::string predicted, measured, error;
      bool measured_yet, passes;
    };
    std::vector<Cells> cells;
    float widest[3] = {ImGui::CalcTextSize("predicted").x, ImGui::CalcTextSize("measured").x,
                       ImGui::CalcTextSize("error").x};
    for (const lessons::ExpectationResult& row : rows) {
      Cells cell{row.numeric ? with_unit(row.predicted, row.unit) : row.predicted_text, "not yet", "", row.measured_yet,
                 row.passes};
      if (row.measured_yet) {
        cell.measured = row.numeric ? with_unit(row.measured, row.unit) : row.measured_text;
        if (row.numeric) {
          // The unit is in the columns beside it; here it would push the names into wrapping.
          std::string number = with_unit(row.error(), "");
          number.pop_back();
          cell.error = (row.passes ? "\u2713 " : "\u2717 ") + std::string(row.error() > 0.0 ? "+" : "") + number;
        } else {
          cell.error = row.passes ? "\u2713 agrees" : "\u2717 differs";
        }
      }
      widest[0] = std::max(widest[0], ImGui::CalcTextSize(cell.predicted.c_str()).x);
      widest[1] = std::max(widest[1], ImGui::CalcTextSize(cell.measured.c_str()).x);
      widest[2] = std::max(widest[2], ImGui::CalcTextSize(cell.error.c_str()).x);
      cells.push_back(std::move(cell));
    }
    const float padding = 2.0f * ImGui::GetStyle().CellPadding.x;
    const float numbers = widest[0] + widest[1] + widest[2] + 3.0f * padding;
    // Beside the numbers, a name needs room for a word or two; with large text in a narrow
    // column there is none, and each name goes on a line of its own above its numbers.
    const float table_width = ImGui::GetContentRegionAvail().x;
    const bool names_above = table_width - numbers < 9.0f * ImGui::CalcTextSize("m").x;
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerH;
    // A name above its numbers spans the row: the cells must not clip it.
    if (ImGui::BeginTable("rows", names_above ? 3 : 4, names_above ? flags | ImGuiTableFlags_NoClip : flags)) {
      // The numbers keep their width; a long name wraps.
      if (names_above) {
        // Widths from the numbers alone: the names, drawn in the first cell, must not widen it.
        ImGui::TableSetupColumn("predicted", ImGuiTableColumnFlags_WidthFixed, widest[0]);
        ImGui::TableSetupColumn("measured", ImGuiTableColumnFlags_WidthFixed, widest[1]);
        ImGui::TableSetupColumn("error", ImGuiTableColumnFlags_WidthStretch);
      } else {
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("predicted");
        ImGui::TableSetupColumn("measured");
        ImGui::TableSetupColumn("error");
      }
      ImGui::TableHeadersRow();
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const Cells& cell = cells[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (names_above) {
          // The name across the whole row: drawn from the first cell, wrapped at the table's edge.
          ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + table_width - padding);
          ImGui::TextUnformatted(rows[i].name.c_str());
          ImGui::PopTextWrapPos();
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
        } else {
          ImGui::TextWrapped("%s", rows[i].name.c_str());
          ImGui::TableNextColumn();
        }
        ImGui::TextUnformatted(cell.predicted.c_str());
        ImGui::TableNextColumn();
        if (!cell.measured_yet) {
          ImGui::TextDisabled("not yet");
          ImGui::TableNextColumn();
          continue;
        }
        ImGui::TextUnformatted(cell.measured.c_str());
        ImGui::TableNextColumn();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(cell.passes ? theme.good : theme.bad), "%s", cell.error.c_str());
      }
      ImGui::EndTable();
    }
  }
  end_panel();
}

void energy_panel(const Scene& scene, ImVec2 corner, ImVec2 size, const Theme& theme) {
  if (begin_panel("energy", "Energy ledger (since t = 0)", corner, size)) energy_contents(scene, theme);
  end_panel();
}

void energy_contents(const Scene& scene, const Theme& theme) {
  {
    const EnergyLedger& ledger = scene.ledger();
    struct Line {
      const char* name;
      double value;
    };
    // What the bodies have, then what has been done to them since t = 0.
    const Line stored[] = {{"kinetic", ledger.kinetic}, {"gravity", ledger.potential}, {"spring", ledger.spring}};
    const Line work[] = {{"work: applied", ledger.work_applied}, {"driven bodies", ledger.work_drivers},
                         {"dry friction", ledger.work_friction}, {"drag (c, b)", ledger.work_damping},
                         {"impacts", ledger.work_impacts}, {"velocity set by the script", ledger.work_script}};
    // One resolution for every line, 0.1 mJ, so the columns line up and add up by eye.
    const auto joules = [](double value) {
      char text[32];
      std::snprintf(text, sizeof text, "%.4f J", std::abs(value) < 5e-5 ? 0.0 : value);
      std::string shown = text;
      if (shown[0] == '-') shown.replace(0, 1, "\u2212");
      return shown;
    };
    if (ImGui::BeginTable("ledger", 4, ImGuiTableFlags_SizingFixedFit)) {
      // The script's line only in lessons whose script has set a velocity: the others keep the
      // panel they had.
      const std::size_t lines = ledger.work_script != 0.0 ? std::size(work) : std::size(work) - 1;
      for (std::size_t i = 0; i < lines; ++i) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (i < 3) ImGui::TextUnformatted(stored[i].name);
        ImGui::TableNextColumn();
        if (i < 3) ImGui::TextUnformatted(joules(stored[i].value).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(work[i].name);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(joules(work[i].value).c_str());
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
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(small ? theme.good : theme.bad), "residual %s%s",
                       format_quantity(residual, "J").c_str(), share);
  }
}

void model_panel(const lessons::Lesson& lesson, ImVec2 corner, ImVec2 size) {
  if (begin_panel("model", "Model card", corner, size)) model_contents(lesson);
  end_panel();
}

void model_contents(const lessons::Lesson& lesson) {
  {
    const lessons::ModelCard card = lessons::model_card(lesson);
    const std::string held = card.constraints > 0 ? ", less " + std::to_string(card.constraints) + " held by joints" : "";
    ImGui::Text("%d degrees of freedom: %d moving bod%s%s", card.degrees_of_freedom, card.moving_bodies,
                card.moving_bodies == 1 ? "y" : "ies", held.c_str());
    std::string terms = card.dry ? "dry (\u03bcs, \u03bck)" : "no dry friction";
    terms += card.viscous ? ", viscous c" : ", no viscous c";
    terms += card.quadratic ? ", quadratic b" : ", no quadratic b";
    ImGui::Text("friction: %s", terms.c_str());
    ImGui::Text("%s treatment, %g steps per second", card.treatment.c_str(), card.hz);
    ImGui::Text("%d sub-step%s a step, %d velocity iterations", card.substeps, card.substeps == 1 ? "" : "s",
                card.velocity_iterations);
    // Pairs that name their own treatment say so; every other pair follows the run's.
    for (const lessons::ModelCard::PairLine& pair : card.pairs) {
      if (!pair.own) continue;
      char epsilon[48] = "";
      if (pair.epsilon > 0.0) std::snprintf(epsilon, sizeof epsilon, ", \u03b5 = %g m/s", pair.epsilon);
      ImGui::Text("  %s on %s: %s%s", pair.material_a.c_str(), pair.material_b.c_str(), pair.treatment.c_str(), epsilon);
    }
  }
}

}  // namespace frictionlab::ui
