#include "draw/frame.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "draw/close_up.h"
#include "draw/free_body.h"
#include "draw/legend.h"
#include "draw/overlays.h"
#include "draw/panels.h"
#include "draw/plots.h"
#include "draw/text_record.h"
#include "draw/words.h"
#include "draw/world_view.h"
#include "lessons/runtime/class_words.h"

namespace frictionlab::draw {

namespace {

// The frame's places; `plots`: the lesson has plots of its own, as FrameLayout::of asks it.
FrameLayout laid_out(ImVec2 display, float scale, ImVec2 origin, bool projector, bool plots) {
  FrameLayout layout;
  const float gap = 4.0f * scale;
  // The title's panel holds two lines (the title, the question under it) at a screen's text
  // size; on a projector one: 26 pt title text (load_fonts) and the panel's padding above and
  // below (title_padding, which title_panel keeps to).
  const float two_lines = 70.0f * scale;
  const float title_height = projector ? (26.0f + 2.0f * FrameLayout::title_padding) * scale : two_lines;
  // A slider row and a theory row need a width that grows with the text: at a screen's own
  // text size a third of the screen holds them, at projector size (the screen's text size
  // times 1.35) 39 % of it does; the world keeps the rest, room for its labels.
  const float column_width = std::max({0.36f * display.x, 300.0f * scale, std::min(0.5f * display.x, 370.0f * scale)});
  const float left_width = display.x - column_width - gap;
  layout.title_corner = ImVec2(0.0f, 0.0f);
  layout.title_size = ImVec2(display.x, title_height);
  layout.world_corner = ImVec2(0.0f, title_height + gap);
  // The legend's two rows of small text (14 pt and 6 pt between, draw_legend) and a margin:
  // at a screen's text size a strip of its own under the world, so nothing in the world hides it.
  const float legend_strip = 50.0f * scale;
  // The world's height is set by what its force labels, free-body inset and lanes need, which
  // the ForceLabels and lanes tests measure: 57 % of what is below a two-line title, less the
  // legend's strip (55 % on a projector, whose plots have more of the rest). These are the
  // least shares those tests pass at, found by trying them; the projector's world keeps that
  // height though its title is one line and its legend has left the strip, so that what they
  // gave goes to the plots.
  const float below_two_lines = display.y - two_lines - gap;
  layout.world_size = ImVec2(left_width, (projector ? 0.55f : 0.57f) * below_two_lines - legend_strip);
  // The free-body diagram takes at most a third of the world's width and 70 % of its height, so
  // that with large text (projector mode) it does not cover the world it explains.
  layout.inset_size = ImVec2(std::min(260.0f * scale, 0.32f * left_width), std::min(200.0f * scale, 0.7f * layout.world_size.y));
  layout.inset_corner = ImVec2(left_width - layout.inset_size.x - 6.0f * scale, layout.world_corner.y + 6.0f * scale);
  // Left out where it cannot be read (a projector's text in a world of a screen's height), and
  // on any projector: its small text is for a screen, not the back row, and at 1024 × 768 it
  // passed the size rule with a 50 px crate and its arrows over each other (a teacher's trial,
  // issue 31). The world's own arrows show the same forces, and the world keeps the width.
  if (projector || !free_body_readable(layout.inset_size, scale)) layout.inset_size = ImVec2(0.0f, 0.0f);
  if (projector && !plots) layout.world_size.y = display.y - layout.world_corner.y - legend_strip;
  const float under_world = layout.world_corner.y + layout.world_size.y;
  layout.legend_beside_plots = projector && plots;
  if (layout.legend_beside_plots) {
    // The plots' row right under the world, the legend a column at its right end: the row's
    // height is the key plot's (a third of the screen or more), and the legend, a line an
    // entry, needs no more than it has.
    // Their panels' edges close up to the world's (1 pt apart, not 4).
    const float close = 1.0f * scale;
    layout.legend_size = ImVec2(FrameLayout::legend_column_default_points * scale, display.y - under_world - close);
    layout.legend_corner = ImVec2(left_width - layout.legend_size.x, under_world + close);
    layout.plots_corner = ImVec2(0.0f, under_world + close);
    layout.plots_size = ImVec2(left_width - layout.legend_size.x - gap, display.y - layout.plots_corner.y);
  } else {
    layout.legend_corner = ImVec2(0.0f, under_world);
    layout.legend_size = ImVec2(left_width, legend_strip);
    layout.plots_corner = ImVec2(0.0f, layout.legend_corner.y + legend_strip + gap);
    // None high where the world took the row (a projector's lesson with no plots) or the window
    // is too short for one: draw_plots then draws none.
    layout.plots_size = ImVec2(left_width, std::max(0.0f, display.y - layout.plots_corner.y));
  }
  layout.column_corner = ImVec2(left_width + gap, title_height + gap);
  layout.column_size = ImVec2(column_width, display.y - title_height - gap);
  for (ImVec2* corner : {&layout.title_corner, &layout.world_corner, &layout.legend_corner, &layout.inset_corner,
                         &layout.plots_corner, &layout.column_corner}) {
    corner->x += origin.x;
    corner->y += origin.y;
  }
  return layout;
}

}  // namespace

FrameLayout FrameLayout::of(ImVec2 display, float scale, ImVec2 origin, bool projector, const lessons::Lesson& lesson) {
  return laid_out(display, scale, origin, projector, !lesson.plots().empty());
}

FrameLayout FrameLayout::of(ImVec2 display, float scale, ImVec2 origin) {
  return laid_out(display, scale, origin, false, true);
}

FrameLayout FrameLayout::with_legend_column(float width) const {
  FrameLayout layout = *this;
  const float right = legend_corner.x + legend_size.x;
  layout.legend_corner.x = right - width;
  layout.legend_size.x = width;
  layout.plots_size.x += legend_size.x - width;
  return layout;
}

FrameLayout FrameLayout::with_column_foot(float foot) const {
  FrameLayout layout = *this;
  layout.column_size.y = std::max(0.0f, column_size.y - foot);
  return layout;
}

namespace {

// The length the arrow of the run's largest force is drawn in a view (a lane) `height` px high.
// The run's largest force (run_force_for_scale) is 0.4 of the view's height (of a lane's, with
// lanes): as long as the view holds, a weight from the middle of a body down past the floor
// and a normal force up from it, so that as few forces as may be fall under the length a back
// row reads (legible_arrow_pixels), drawn broken. A quarter of the view, as before, left every
// arrow of push under it on a projector (issue 31).
float force_pixels_at(float height, float scale) { return std::clamp(0.4f * height, 30.0f * scale, 150.0f * scale); }

// A force's value's box as the placer keeps it clear, px high: a line of the body text and its padding.
float value_line_pixels(float scale) {
  const ImVec4 box = LabelPlacer::box_around(ImVec2(0.0f, 0.0f), ImVec2(0.0f, body_text_points * scale));
  return box.w - box.y;
}

// The arrows as drawn in a view (a lane) `height` px high (ArrowRoom): the run's largest force
// force_pixels_at long (without a run ahead, the heaviest weight), none shorter than legible.
ArrowRoom arrow_room_at(const lessons::Lesson& lesson, float height, float scale) {
  const float longest = force_pixels_at(height, scale);
  const std::optional<float> force = run_force_for_scale(lesson);
  const float per_newton = force ? longest / *force : pixels_per_newton(lesson.scene(), longest);
  return ArrowRoom{std::max(longest, legible_arrow_pixels(scale)), per_newton, legible_arrow_pixels(scale),
                   value_line_pixels(scale)};
}

// How the lesson's lanes stand in the world view (lane_grid): one column of strips where they
// hold their arrows, as in a window or the web page; side by side where a strip would be too
// thin for them (terrain's four lanes on a projector).
LaneGrid lanes_grid(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, const FrameLayout& layout, float scale) {
  return lane_grid(framing, lesson.scene(), layout.world_size, layout.world_size.x - layout.inset_size.x, scale,
                   [&](float height) { return arrow_room_at(lesson, height, scale); });
}

// The height of one lane (of the view, without lanes), px.
float lane_height(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, const FrameLayout& layout, float scale) {
  if (framing.view.kind != lessons::View::Kind::lanes) return layout.world_size.y;
  return layout.world_size.y / static_cast<float>(lanes_grid(lesson, framing, layout, scale).rows);
}

}  // namespace

float scale_force_pixels(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                         bool projector) {
  const FrameLayout layout = FrameLayout::of(display, scale, ImVec2(0.0f, 0.0f), projector, lesson);
  return force_pixels_at(lane_height(lesson, framing, layout, scale), scale);
}

float longest_arrow_pixels(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                           bool projector) {
  return std::max(scale_force_pixels(lesson, framing, display, scale, projector), legible_arrow_pixels(scale));
}

std::vector<Camera> world_cameras(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display,
                                  float scale, ImVec2 origin, const ViewAdjust& adjust, bool projector) {
  const FrameLayout layout = FrameLayout::of(display, scale, origin, projector, lesson);
  const LaneGrid grid = lanes_grid(lesson, framing, layout, scale);
  return framing_cameras(framing, lesson.scene(), layout.world_corner, layout.world_size,
                         layout.world_size.x - layout.inset_size.x, scale, adjust,
                         arrow_room_at(lesson, layout.world_size.y / static_cast<float>(grid.rows), scale), grid.columns,
                         layout.legend_beside_plots);
}

Camera world_camera(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                    ImVec2 origin) {
  return world_cameras(lesson, framing, display, scale, origin).front();
}

float arrow_scale(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, ImVec2 display, float scale,
                  bool projector) {
  // The run's largest force (run_force_for_scale, from the plots' run ahead) is drawn
  // scale_force_pixels long; without a run ahead, the heaviest weight.
  const float longest = scale_force_pixels(lesson, framing, display, scale, projector);
  if (const std::optional<float> force = run_force_for_scale(lesson)) return longest / *force;
  return pixels_per_newton(lesson.scene(), longest);
}

namespace {

// How the column's panels share its height. The parameters and the theory table come first:
// the ledger and the model card become tabs of one panel when the column is short, the theory
// table joins them as the first tab when it is shorter still, and only then do friction pairs
// give way, the last pair first: the window's sliders two a row, then folded into a line each
// (a picture's values folded at once). What still does not fit is cut (a picture) or scrolled
// (the window's tabs).
struct ColumnPlan {
  float parameters = 0.0f, theory = 0.0f, energy = 0.0f, model = 0.0f;
  std::size_t parameters_step = 0;  // how far the parameters gave way
  bool books_tabbed = false, theory_in_tabs = false, books_scroll = false;
  bool theory_whole = true;  // the theory panel (or its tab) holds what it was planned for
};

// `theory`: the theory panel's contents, the height it is planned for. `whole_theory`: when
// even the last step leaves them too little room, the parameters give way as far as they can
// (else they keep half the column).
ColumnPlan plan_column(const lessons::Lesson& lesson, const FrameStyle& style, ImVec2 display, float theory_contents,
                       bool whole_theory = false) {
  const float s = style.fonts->scale;
  const FrameLayout base = FrameLayout::of(display, s, style.origin, style.projector, lesson).with_column_foot(style.column_foot);
  const ImGuiStyle& imgui = ImGui::GetStyle();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float bar = ImGui::GetFrameHeight();  // a title bar, or a tab bar
  const float padding = 2.0f * imgui.WindowPadding.y;
  const float gap = 4.0f * s;
  const float inside = base.column_size.x - 2.0f * imgui.WindowPadding.x;
  const float theory = bar + padding + 4.0f * s + theory_contents;
  const bool window = static_cast<bool>(style.parameters_panel);
  // The parameters' height at each step of giving way: in a picture, the last k pairs folded;
  // the window's steps are its own (parameters_heights).
  const std::size_t steps = window ? style.parameters_heights.size() - 1 : parameter_pairs(lesson).size();
  const auto parameters = [&](std::size_t step) {
    return window ? style.parameters_heights[step] : parameters_panel_height(lesson, base.column_size.x, step, style.hidden);
  };
  const float ledger = energy_contents_height(lesson.scene(), inside);
  const float energy = bar + padding + 4.0f * s + ledger;
  const float model = bar + padding + 4.0f * s + model_contents_height(lesson, inside);
  // A tab bar in place of a title bar, and "since t = 0" under it when the tab's name is short.
  const float books = std::max(bar + padding + 4.0f * s + line + ledger, model) + imgui.ItemSpacing.y;
  const float room = base.column_size.y;

  ColumnPlan plan;
  plan.theory = theory;
  plan.energy = energy;
  plan.model = model;
  // Whatever the column has to spare goes to the parameters while every panel has its own
  // panel and all fit; once the books are tabs, the parameters take what they need and the
  // tabs (the last panel, to the column's foot) the rest, for the theory table, the class's
  // predictions or a longer tab the teacher picks: a projector's theory table scrolled beside
  // a half-empty Parameters panel.
  bool spare_to_parameters = true;
  const auto fits = [&](float others, std::size_t step) {
    const float wanted = parameters(step) + others;
    if (wanted > room) return false;
    plan.parameters_step = step;
    plan.parameters = spare_to_parameters ? room - others : parameters(step);
    return true;
  };
  // The window always keeps the books as tabs (it has more of them).
  if (!window && fits(theory + energy + model + 3.0f * gap, 0)) return plan;
  plan.books_tabbed = true;
  spare_to_parameters = false;
  if (fits(theory + books + 2.0f * gap, 0)) return plan;
  // The theory tab is the one shown first: the panel is made to hold it, and scrolls for a
  // longer tab the teacher picks.
  plan.theory_in_tabs = true;
  plan.books_scroll = window;
  const float tabs = theory;
  for (std::size_t step = 0; step <= steps; ++step) {
    if (fits(tabs + gap, step)) return plan;
  }
  // The tabs scroll; the parameters keep at least half the column, giving way only as far as
  // that needs.
  plan.theory_whole = false;
  plan.parameters_step = steps;
  if (whole_theory) {
    plan.parameters = parameters(steps);
    return plan;
  }
  const float budget = std::max(0.5f * room, room - tabs - gap);
  for (std::size_t step = 0; step <= steps; ++step) {
    if (parameters(step) <= budget) {
      plan.parameters_step = step;
      break;
    }
  }
  plan.parameters = std::min(parameters(plan.parameters_step), budget);
  return plan;
}

// A plot panel's inside, for its chart: less its title bar, or its title wrapped inside it
// when the title is longer than the bar (large text, three plots in a row), or the pager's
// row (buttons and title) that stands for the bar.
bool title_inside(const std::string& title, ImVec2 size) {
  return ImGui::CalcTextSize(title.c_str()).x + 2.0f * ImGui::GetStyle().FramePadding.x > size.x;
}
// The pager's line: its title and the page's number, after the two buttons.
std::string pager_line(const std::string& title, std::size_t page, std::size_t pages) {
  return title + "  (" + std::to_string(page + 1) + "/" + std::to_string(pages) + ")";
}
float pager_buttons_width() {
  const ImGuiStyle& imgui = ImGui::GetStyle();
  return 2.0f * (ImGui::CalcTextSize("\u2192").x + 2.0f * imgui.FramePadding.x + imgui.ItemSpacing.x);
}
ImVec2 chart_area(const std::string& title, ImVec2 size, bool pager) {
  const ImGuiStyle& imgui = ImGui::GetStyle();
  const float inside_width = size.x - 2.0f * imgui.WindowPadding.x;
  const auto wrapped = [&](const std::string& text, float wrap) {
    return ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap).y;
  };
  const float top =
      pager ? std::max(ImGui::GetFrameHeight(), wrapped(pager_line(title, 9, 9), inside_width - pager_buttons_width()) +
                                                    imgui.FramePadding.y) +
                  imgui.ItemSpacing.y
      : title_inside(title, size) ? wrapped(title, inside_width) + imgui.ItemSpacing.y
                                  : ImGui::GetFrameHeight();
  return ImVec2(inside_width, size.y - 2.0f * imgui.WindowPadding.y - top);
}

// The least width of a plot's data, as a share of its panel's, before the window shows fewer
// plots side by side (a page at a time): the rest is for its axis labels and a legend beside it.
constexpr float min_data_share = 0.5f;

// The plots under the world: up to three side by side, more on a second row. In the window,
// when that leaves a plot's legend no room off its data (large text: three plots across a
// projector put 3–5-key legends over the data), fewer go side by side, a page at a time; the
// first plot of a page has ← and → before its title to turn the pages, in place of its title
// bar. The choice counts every key a plot can have (its theory curves, shown or not yet), so
// the pages stay as the run goes on and at the reveal. A picture, which nobody clicks, keeps
// every plot in view.
// The plots a frame draws: the lesson's, then the window's extra plot (the force gauge).
struct FramePlots {
  const lessons::Lesson& lesson;
  const FrameStyle& style;
  std::size_t count() const { return lesson.plots().size() + (style.extra_plot ? 1 : 0); }
  // The title as shown: a plot's answer ("θc = 30.96°") joins it once the theory is shown.
  std::string title(std::size_t i) const { return titled(i, !style.theory_kept_back()); }
  // The title at its longest, with the answer: the room its panel keeps from the opening, so
  // that the reveal moves nothing.
  std::string title_room(std::size_t i) const { return titled(i, true); }
  std::string titled(std::size_t i, bool with_answer) const {
    if (i == lesson.plots().size()) return style.extra_plot_title;
    const lessons::Plot& plot = lesson.plots()[i];
    return with_answer && !plot.answer.empty() ? plot.title + ", " + plot.answer : plot.title;
  }
};

// How many plots go side by side: on a projector one, the key plot its row's full width; in the
// window up to three, fewer while a lesson plot's legend has no room off its data at that many
// (a page of one row when that is fewer than all of them), or leaves the data a sliver.
std::size_t plots_per_row(lessons::Lesson& lesson, const FrameStyle& style, const FrameLayout& layout, double time_span,
                          const Theme& colours) {
  const FramePlots plots{lesson, style};
  const Fonts& fonts = *style.fonts;
  const float s = fonts.scale;
  const float gap = 4.0f * s;
  const std::size_t most = std::min<std::size_t>(plots.count(), 3);
  const auto all_have_room = [&](std::size_t per_row) {
    const bool paged = per_row < most;
    const std::size_t rows = paged ? 1 : (plots.count() + per_row - 1) / per_row;
    const ImVec2 size(layout.plots_size.x / static_cast<float>(per_row) - (per_row > 1 ? gap : 0.0f),
                      layout.plots_size.y / static_cast<float>(rows) - (rows > 1 ? gap : 0.0f));
    for (std::size_t i = 0; i < lesson.plots().size(); ++i) {
      // A little less than the panel will hold, so that rounding does not tip the choice.
      const ImVec2 area =
          chart_area(plots.title_room(i), size, (paged && i % per_row == 0) || (style.projector && plots.count() == 1));
      const Chart chart = plot_chart(lesson, i, time_span, colours, true);
      const ImVec2 room(area.x - 4.0f * s, area.y - 4.0f * s);
      if (!legend_has_room(chart, room, fonts)) return false;
      // Nor a legend beside the data that leaves the data a sliver: the incline's two plots side
      // by side in projector mode drew their curves 240 px wide, their legends as wide again.
      const ChartLayout laid = layout_chart(chart, ImVec2(0.0f, 0.0f), room, fonts);
      if (laid.high_right.x - laid.low_left.x < min_data_share * room.x) return false;
    }
    return true;
  };
  std::size_t per_row = most;
  if (style.projector) {
    per_row = 1;
  } else if (style.parameters_panel) {
    while (per_row > 1 && !all_have_room(per_row)) --per_row;
  }
  return per_row;
}

// The pager's ← and → at the head of the first plot's panel, and the page it shows: kept per
// lesson (another lesson opens on its first page, not on the page the last was left at),
// turned by the keys or the buttons, the extra plot's page while the hand pulls.
std::size_t turn_plot_pages(const lessons::Lesson& lesson, const FrameStyle& style, std::size_t page_count) {
  ImGuiStorage* state = ImGui::GetStateStorage();
  const ImGuiID kept = ImGui::GetID(("page of " + lesson.path()).c_str());
  std::size_t page = std::min<std::size_t>(static_cast<std::size_t>(std::max(0, state->GetInt(kept, 0))), page_count - 1);
  if (style.turn_plot_pages != 0) {
    const long turned = static_cast<long>(page) + style.turn_plot_pages;
    page = static_cast<std::size_t>(std::clamp<long>(turned, 0, static_cast<long>(page_count) - 1));
  }
  if (style.show_extra_plot && style.extra_plot) page = page_count - 1;  // the extra plot is the last
  const auto turn = [&](const char* label, bool enabled, std::size_t to) {
    ImGui::BeginDisabled(!enabled);
    if (ImGui::Button(label)) page = to;
    note_text_centred(label, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
    ImGui::EndDisabled();
    ImGui::SameLine();
  };
  turn("\u2190", page > 0, page > 0 ? page - 1 : 0);
  turn("\u2192", page + 1 < page_count, page + 1);
  state->SetInt(kept, static_cast<int>(page));
  return page;
}

// Plot number `i` in its open panel, under its title (or the pager's line): the extra plot, or
// the lesson's, whose parts and levels' texts are noted for the tests.
void plot_in_panel(lessons::Lesson& lesson, const FrameStyle& style, std::size_t i, double time_span, const Theme& colours) {
  const ImVec2 area = ImGui::GetContentRegionAvail();
  if (i == lesson.plots().size()) {
    const ChartLayout drawn = style.extra_plot(ImGui::GetCursorScreenPos(), area);
    if (style.record != nullptr) style.record->plots.push_back({i, drawn});
    return;
  }
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  const ChartLayout drawn = draw_plot(ImGui::GetWindowDrawList(), lesson, i, time_span, corner, area,
                                      colours, *style.fonts, !style.theory_kept_back(), style.script_words, style.projector,
                                      style.hidden.theory());
  if (style.record != nullptr) {
    style.record->plots.push_back({i, drawn});
    // The levels' texts, drawn on the data or in the column beside it (not by ImGui's text
    // calls), with the rest: each shown within the data area, or the plot's, where it went.
    const ImVec4 data(drawn.low_left.x, drawn.high_right.y, drawn.high_right.x, drawn.low_left.y);
    const ImVec4 plot(corner.x, corner.y, corner.x + area.x, corner.y + area.y);
    for (const ChartLayout::Level& level : drawn.levels) {
      if (level.text.empty()) continue;  // its line alone
      style.record->texts.push_back({ImGui::GetCurrentWindow()->Name, level.text, level.at, level.beside ? plot : data});
    }
  }
}

void draw_plots(lessons::Lesson& lesson, const FrameStyle& style, const FrameLayout& layout, double time_span,
                const Theme& colours) {
  const FramePlots plots{lesson, style};
  const float s = style.fonts->scale;
  const std::size_t plot_count = plots.count();
  // No row for them: a projector's frame gives a lesson with no plots of its own the row.
  if (plot_count == 0 || layout.plots_size.y == 0.0f) return;
  const float gap = 4.0f * s;
  const std::size_t per_row = plots_per_row(lesson, style, layout, time_span, colours);
  const bool paged = per_row < std::min<std::size_t>(plot_count, 3);
  const std::size_t page_count = paged ? (plot_count + per_row - 1) / per_row : 1;
  const std::size_t rows_of_plots = paged ? 1 : (plot_count + per_row - 1) / per_row;
  const float width = layout.plots_size.x / static_cast<float>(per_row);
  const float height = layout.plots_size.y / static_cast<float>(rows_of_plots);
  std::size_t page = 0;
  for (std::size_t k = 0; k < (paged ? per_row : plot_count); ++k) {
    const std::size_t column = k % per_row, row = k / per_row;
    const ImVec2 at(layout.plots_corner.x + width * static_cast<float>(column),
                    layout.plots_corner.y + height * static_cast<float>(row));
    const ImVec2 size(width - (column + 1 < per_row ? gap : 0.0f), height - (row + 1 < rows_of_plots ? gap : 0.0f));
    const bool pager = paged && k == 0;
    // A projector's only plot is headed as the pager is, its title on a thin line of its own in
    // place of the title bar (a lesson of one plot had 17 px less data than one of two: 343 px,
    // under a third of the screen, with the stopwatch on).
    const bool headed = pager || (style.projector && plot_count == 1);
    // The pager's panel keeps its name from page to page: the page is kept in its state.
    const std::string id = pager ? std::string("plot pager") : "plot" + std::to_string(k);
    std::size_t i = page * per_row + k;
    if (!pager && i >= plot_count) break;
    bool open = false;
    if (headed) {
      // On a projector the page's line and its panel's edges are kept thin: each point of
      // height they leave goes to the key plot's data.
      if (style.projector) {
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetStyle().WindowPadding.x, 2.0f * s));
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 1.0f * s));
        ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 1.0f * s));
      }
      open = begin_panel(id.c_str(), "", at, size);
    }
    if (pager) {
      page = turn_plot_pages(lesson, style, page_count);
      i = page * per_row;
    }
    const std::string title = plots.title(i);
    const std::string room = plots.title_room(i);
    const bool inside = !headed && title_inside(room, size);
    if (!headed) open = begin_panel(id.c_str(), inside ? "" : title.c_str(), at, size);
    if (open) {
      if (headed || inside) {
        // The title on the buttons' line, as a title bar would have it, with the page's number;
        // or wrapped inside the panel, longer than its bar. As many lines as the title with its
        // answer takes, shown or not, so that the plot under it stays put at the reveal.
        if (pager) ImGui::AlignTextToFramePadding();
        const std::string line = pager ? pager_line(title, page, page_count) : title;
        const std::string longest = pager ? pager_line(room, page, page_count) : room;
        ImGui::PushTextWrapPos(0.0f);
        if (line == longest) {
          shown_text(line.c_str());
        } else {
          // The title with its answer laid out unseen, then the title as shown drawn in its
          // place: the panel keeps the answer's lines from the opening. (Moving the cursor down
          // by the lines' difference left the data 0.2–1.8 px off, as ImGui rounds positions.)
          const float wrap_width = ImGui::GetContentRegionAvail().x;
          ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.0f, 0.0f, 0.0f, 0.0f));
          ImGui::TextUnformatted(longest.c_str());
          ImGui::PopStyleColor();
          const ImVec2 from = ImGui::GetItemRectMin();
          ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(), from, ImGui::GetColorU32(ImGuiCol_Text),
                                              line.c_str(), nullptr, wrap_width);
          const ImVec2 extent = ImGui::CalcTextSize(line.c_str(), nullptr, false, wrap_width);
          note_text_at(line.c_str(), ImRect(from, ImVec2(from.x + extent.x, from.y + extent.y)));
        }
        ImGui::PopTextWrapPos();
      }
      plot_in_panel(lesson, style, i, time_span, colours);
    }
    end_panel();
    if (headed && style.projector) ImGui::PopStyleVar(3);
  }
}

// The column's plan for this frame, and whether its theory panel scrolls. The class's
// predictions are planned for whole (as the first tab, if need be), at their tallest before the
// reveal or after it (predictions_height), and nothing else the class does moves them: not R,
// not the run's end, not the reveal. The friction pairs' sliders give way for them as far as
// that needs; the theory table, revealed under them, scrolls. (The column was planned anew as
// the run ended and at the reveal: after R on tipping_box the Parameters panel unfolded and
// pushed the reveal button under the teacher's pointer.) The answers' height is the same all
// through the run; the theory table's is not (its rows fill in as the run measures them), so the
// plan leaves it out: a plan with it folded the sliders when the run ended.
// A projector's theory table leaves out the error column: each measured value has its verdict
// beside it (TheoryColumns in panels.h).
TheoryColumns theory_columns(const FrameStyle& style) {
  return style.projector ? TheoryColumns::verdicts : TheoryColumns::errors;
}

struct ColumnChoice {
  ColumnPlan plan;
  bool theory_scrolls = false;
  bool class_answers_in_table = true;  // the class's answers a column of the revealed theory table
};

ColumnChoice choose_column(const lessons::Lesson& lesson, const FrameStyle& style, ImVec2 display,
                           const lessons::LessonReadings& readings) {
  const float s = style.fonts->scale;
  const float inside = FrameLayout::of(display, s, style.origin).column_size.x - 2.0f * ImGui::GetStyle().WindowPadding.x;
  const float table = theory_contents_height(readings.expectations, inside, readings.error, readings.caveat,
                                             style.hidden.theory(), theory_columns(style));
  ColumnChoice choice{plan_column(lesson, style, display, table)};
  if (style.predictions_height) {
    const FrameStyle::AnswersHeight answers = style.predictions_height(inside);
    // In projector mode, the theory table revealed with the class's answers in a column of
    // their own at the run's end, whole, where the friction pairs can give way for it (issue 31:
    // push's last row was a scroll away); it is planned at its tallest, which no value the run measures changes. Where
    // even that leaves too little room (or would fold the sliders away), the answers alone are
    // planned for and the revealed table scrolls. A screen's column keeps the plan it had (its
    // theory table has a panel of its own beside the tabs, a mystery's tab under it).
    if (style.projector) {
      const float revealed_table =
          theory_contents_tallest_height(readings.expectations, inside, "", "", false, theory_columns(style), style.class_answers);
      choice.plan = plan_column(lesson, style, display, std::max(answers.asked, revealed_table), true);
    }
    if (!style.projector || !choice.plan.theory_whole ||
        choice.plan.parameters_step > style.parameters_step_for_the_theory) {
      choice.class_answers_in_table = false;
      choice.plan = plan_column(lesson, style, display, std::max(answers.asked, answers.revealed_above), true);
    }
    // The answers alone, before the reveal, have the room planned for them: no scroll bar to
    // take width from them. A value changed since the plan (a slider; the hand's pull, which
    // writes "(hand-pulled)") may make them longer: they scroll then, rather than fold the
    // Parameters panel under the teacher's pointer (PredictionPanel keeps the planned height).
    choice.theory_scrolls = !style.theory_hidden || !choice.plan.theory_whole ||
                            (style.predictions_outgrew && style.predictions_outgrew());
  }
  return choice;
}

// With lanes, each moving body's forces are drawn in one lane: the one whose own body is nearest
// its height (nearest_lane, as the lane's camera made room for its arrows).
std::vector<std::vector<const b2Body*>> bodies_by_lane(const Scene& scene, const lessons::WorldFraming& framing,
                                                       const std::vector<Camera>& cameras) {
  std::vector<std::vector<const b2Body*>> lane_bodies(cameras.size());
  const std::vector<const b2Body*> own = lessons::view_bodies(scene, framing.view);
  for (const auto& [name, body] : scene.bodies()) {
    if (body->GetType() != b2_dynamicBody) continue;
    // (A view without lanes has one camera, and every body is drawn in it.)
    const std::size_t lane = own.size() == cameras.size() ? nearest_lane(body, own) : 0;
    lane_bodies[lane].push_back(body);
  }
  return lane_bodies;
}

// The free-body inset sits over the world's top right, where the framing leaves no body; a
// body the mouse's hand drags there (the view holds still while it pulls) would go under it,
// gauge and all: the inset then takes the top left instead.
ImVec2 inset_corner_clear_of_the_hand(const Scene& scene, const b2Body* focus, const FrameLayout& layout, const Camera& camera,
                                      float s) {
  ImVec2 inset_corner = layout.inset_corner;
  if (focus != nullptr && scene.grabbed() == focus) {
    const b2AABB box = lessons::body_box(focus);
    const ImVec2 high_right = camera.to_screen(box.upperBound);  // screen y grows downwards: its top
    if (high_right.x > inset_corner.x && high_right.y < inset_corner.y + layout.inset_size.y) {
      inset_corner.x = layout.world_corner.x + 6.0f * s;
    }
  }
  return inset_corner;
}

// Each lane named (by its body, or the title the lesson gave it) in its corner; one view, no name.
std::string lane_name(const lessons::WorldFraming& framing, std::size_t lanes, std::size_t lane) {
  if (lanes < 2) return "";
  return lane < framing.view.titles.size() ? framing.view.titles[lane] : lessons::class_words(framing.view.bodies[lane]);
}

// The lane's name, and where one body's forces alone are drawn, in the lane that draws them,
// whose they are: a class seeing the top block's two forces must not take them for all there
// are (B, or View > Forces on, brings the others back).
std::string lane_caption(const Scene& scene, const lessons::WorldFraming& framing, const FrameStyle& style, std::size_t lanes,
                         std::size_t lane, const std::vector<const b2Body*>* bodies) {
  std::string caption = lane_name(framing, lanes, lane);
  if (style.forces_on == nullptr || bodies == nullptr || std::find(bodies->begin(), bodies->end(), style.forces_on) == bodies->end()) {
    return caption;
  }
  // Short in a lane, which may be a third of the world wide: friction_models' lanes are named
  // after their blocks, and "coulomb: forces on coulomb only" ran past its lane's edge.
  const std::string name = lessons::class_words(scene.name_of(style.forces_on));
  if (caption.empty()) return "forces on " + name + " only (B: next)";
  return caption + (caption == name ? "" : ": " + name) + " only (B: next)";
}

// One lane of the world: its bodies, forces and the tools over them, its labels kept off the
// inset and each other, its name, and what it placed noted for the layout test.
void draw_lane(ImDrawList* draw, const lessons::Lesson& lesson, const lessons::WorldFraming& framing, const FrameStyle& style,
               const std::vector<Camera>& cameras, std::size_t lane, const std::vector<const b2Body*>* bodies, ImVec4 inset,
               float newtons_to_pixels) {
  const Fonts& fonts = *style.fonts;
  const Theme& colours = theme(style.theme);
  const float s = fonts.scale;
  const Camera& camera = cameras[lane];
  const ImVec2 lane_end(camera.origin.x + camera.size.x, camera.origin.y + camera.size.y);
  draw->PushClipRect(camera.origin, lane_end, true);
  // Labels stay in what of the lane shows: the world's panel clips half its padding off
  // each edge (10 px with projector text), and a label placed only inside the lane lost its
  // first letter there (the speed readout of a body at the view's left edge).
  const ImVec2 shown_min = draw->GetClipRectMin(), shown_max = draw->GetClipRectMax();
  LabelPlacer labels(shown_min, sub(shown_max, shown_min));
  if (inset.z > inset.x) labels.avoid(inset);
  const std::string name = lane_caption(lesson.scene(), framing, style, cameras.size(), lane, bodies);
  const ImVec2 name_size = fonts.small->CalcTextSizeA(fonts.small->FontSize, 1e6f, 0.0f, name.c_str());
  const ImVec2 name_at(camera.origin.x + 8.0f * s + 0.5f * name_size.x, camera.origin.y + 6.0f * s + 0.5f * name_size.y);
  if (!name.empty()) {
    labels.avoid(ImVec4(name_at.x - 0.5f * name_size.x - 3.0f, name_at.y - 0.5f * name_size.y - 1.0f,
                        name_at.x + 0.5f * name_size.x + 3.0f, name_at.y + 0.5f * name_size.y + 1.0f));
  }
  const auto tools = [&](WorldToolsPass pass) {
    if (style.world_tools) style.world_tools(pass, draw, camera, lane, newtons_to_pixels, labels);
  };
  tools(WorldToolsPass::avoid);
  draw_world(draw, lesson, camera, colours, fonts, newtons_to_pixels, labels, bodies, [&] { tools(WorldToolsPass::fixed_labels); });
  tools(WorldToolsPass::draw);
  if (style.record != nullptr) {
    style.record->lanes.push_back({camera, labels.labels(), labels.segments(), labels.marks(),
                                   ImVec4(shown_min.x, shown_min.y, shown_max.x, shown_max.y), labels.texts(), labels.bodies(),
                                   labels.force_labels(), name});
    style.record->inset = inset;
  }
  if (!name.empty()) {
    draw_label(draw, fonts.small, name_at, colours.text, colours.panel, name.c_str());
    // Parted from the lane above by a line, and from the lane to its left where lanes stand
    // side by side (lane_grid).
    const Camera& first = cameras.front();
    if (camera.origin.y > first.origin.y + 0.5f) draw->AddLine(camera.origin, ImVec2(lane_end.x, camera.origin.y), colours.outline, 2.0f * s);
    if (camera.origin.x > first.origin.x + 0.5f) draw->AddLine(camera.origin, ImVec2(camera.origin.x, lane_end.y), colours.outline, 2.0f * s);
  }
  draw->PopClipRect();
}

// What the world's panel leaves a legend drawn apart from it: the camera and arrow scale the
// legend's samples are drawn at.
struct LegendScale {
  Camera camera;
  float newtons_to_pixels = 1.0f;
};

// The world, drawn into a window of its own so the panels' windows stay on top of it: its lanes,
// the legend in a strip under it (unless `legend_apart`) and the free-body inset over it.
std::optional<LegendScale> world_panel(const lessons::Lesson& lesson, const lessons::WorldFraming& framing, const FrameStyle& style,
                                       ImVec2 display, const FrameLayout& layout, bool legend_apart) {
  const Fonts& fonts = *style.fonts;
  const float s = fonts.scale;
  std::optional<LegendScale> legend;
  const ImVec2 panel(layout.world_size.x, layout.world_size.y + (legend_apart ? 0.0f : layout.legend_size.y));
  if (begin_panel("world", "", layout.world_corner, panel)) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const std::vector<Camera> cameras =
        world_cameras(lesson, framing, display, s, style.origin, style.view_adjust, style.projector);
    const float newtons_to_pixels = arrow_scale(lesson, framing, display, s, style.projector);
    std::vector<std::vector<const b2Body*>> lane_bodies = bodies_by_lane(lesson.scene(), framing, cameras);
    for (std::vector<const b2Body*>& bodies : lane_bodies) {
      if (style.forces_on != nullptr) std::erase_if(bodies, [&](const b2Body* body) { return body != style.forces_on; });
    }
    const bool lanes_filtered = cameras.size() > 1 || style.forces_on != nullptr;
    const b2Body* focus = main_body(lesson.scene());
    const ImVec2 inset_corner = inset_corner_clear_of_the_hand(lesson.scene(), focus, layout, cameras.front(), s);
    const bool inset_shown = layout.inset_size.x > 0.0f;
    // Where the free-body inset cannot be read (a projector), a close-up of a body the lesson's
    // fixed window draws too small, over the same world: the lanes' labels keep off either.
    const std::optional<CloseUp> close_up =
        inset_shown || cameras.size() != 1
            ? std::nullopt
            : close_up_place(lesson, focus, cameras.front(), layout.world_corner, layout.world_size, s,
                             fonts.small->FontSize);
    const ImVec4 inset = inset_shown ? ImVec4(inset_corner.x, inset_corner.y, inset_corner.x + layout.inset_size.x,
                                              inset_corner.y + layout.inset_size.y)
                                     : close_up ? close_up->place : ImVec4(0.0f, 0.0f, 0.0f, 0.0f);
    for (std::size_t lane = 0; lane < cameras.size(); ++lane) {
      draw_lane(draw, lesson, framing, style, cameras, lane, lanes_filtered ? &lane_bodies[lane] : nullptr, inset,
                newtons_to_pixels);
    }
    if (close_up) {
      LabelPlacer labels(ImVec2(close_up->place.x, close_up->place.y),
                         ImVec2(close_up->place.z - close_up->place.x, close_up->place.w - close_up->place.y));
      draw_close_up(draw, lesson, focus, *close_up, cameras.front(), theme(style.theme), fonts, labels);
      if (style.record != nullptr) {
        style.record->close_ups.push_back({close_up_camera(*close_up, focus, cameras.front()), labels.labels(),
                                           labels.segments(), labels.marks(), close_up->place, labels.texts(),
                                           labels.bodies(), labels.force_labels(), ""});
      }
    }
    legend = LegendScale{cameras.front(), newtons_to_pixels};
    if (!legend_apart) {
      draw_legend(draw, lesson.scene(), legend->camera, layout.legend_corner, layout.legend_size, theme(style.theme), fonts,
                  newtons_to_pixels);
    }
    std::string focus_name;
    for (const auto& [name, body] : lesson.scene().bodies()) {
      if (body == focus) focus_name = name;
    }
    if (inset_shown) {
      draw_free_body(draw, lesson.scene(), focus, focus_name, inset_corner, layout.inset_size, theme(style.theme), fonts,
                     style.record != nullptr ? &style.record->free_body : nullptr);
    }
  }
  end_panel();
  return legend;
}

// The theory's part of the column: the class's predictions first; before the reveal they stand
// in for the theory.
void predictions_and_theory(const FrameStyle& style, const lessons::LessonReadings& readings, bool class_answers_in_table) {
  if (style.predictions) style.predictions(class_answers_in_table);
  if (!style.theory_hidden) {
    theory_contents(readings.expectations, theme(style.theme), readings.error, readings.caveat, style.hidden.theory(),
                    class_answers_in_table ? style.class_answers : ClassAnswers{},
                    theory_columns(style));
  }
}

// The ledger and the model card as tabs of one panel from `at` to the column's foot (with the
// theory as the first tab when the plan put it there).
void books_tabs(lessons::Lesson& lesson, const FrameStyle& style, const lessons::LessonReadings& readings, const ColumnChoice& column,
                ImVec2 at, ImVec2 size) {
  const ColumnPlan& plan = column.plan;
  // Short names when the full ones would not fit side by side.
  const char* const full[] = {"Theory against simulation###theory tab", "Energy ledger (since t = 0)###energy",
                              "Model card###model"};
  // While the class predicts the tab is "Predict" before the reveal and after it (the answers
  // come first in it either way): a name that changed at the reveal moved the tabs after it.
  const char* const brief[] = {style.predictions ? "Predict###theory tab" : "Theory###theory tab", "Energy###energy",
                               "Model###model"};
  float full_width = 0.0f;
  for (const char* name : full) full_width += ImGui::CalcTextSize(name, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
  const bool short_names = plan.theory_in_tabs || style.more_tabs || full_width > 0.9f * size.x;
  const char* const* names = short_names ? brief : full;
  // With the theory table the tabs are another bar, which opens on its first tab: the theory
  // shows as it joins them (a column that just became short), and whatever tab was chosen
  // comes back with the room. A picture, which nobody clicks, shows each bar's first tab.
  if (begin_panel("books", "", at, size, plan.books_scroll) &&
      ImGui::BeginTabBar(plan.theory_in_tabs ? "books with theory" : "books")) {
    if (plan.theory_in_tabs && begin_tab(names[0])) {
      predictions_and_theory(style, readings, column.class_answers_in_table);
      ImGui::EndTabItem();
    }
    if (begin_tab(names[1])) {
      if (short_names) {
        ImGui::TextDisabled("since t = 0");
        note_text("since t = 0");
      }
      energy_contents(lesson.scene(), theme(style.theme));
      ImGui::EndTabItem();
    }
    if (begin_tab(names[2])) {
      model_contents(lesson);
      ImGui::EndTabItem();
    }
    if (style.more_tabs) style.more_tabs();
    ImGui::EndTabBar();
  }
  end_panel();
}

// The column: parameters, theory against simulation, energy, model, as the plan shares it.
void column_panels(lessons::Lesson& lesson, const FrameStyle& style, const lessons::LessonReadings& readings,
                   const FrameLayout& layout, const ColumnChoice& column) {
  const ColumnPlan& plan = column.plan;
  const Theme& colours = theme(style.theme);
  const float gap = 4.0f * style.fonts->scale;
  ImVec2 at = layout.column_corner;
  const float width = layout.column_size.x;
  if (style.parameters_panel) {
    style.parameters_panel(at, ImVec2(width, plan.parameters), plan.parameters_step);
  } else {
    parameters_panel(lesson, at, ImVec2(width, plan.parameters), plan.parameters_step, style.hidden);
  }
  at.y += plan.parameters + gap;
  if (!plan.theory_in_tabs && !style.predictions) {
    theory_panel(readings.expectations, at, ImVec2(width, plan.theory), colours, readings.error, readings.caveat,
                 style.hidden.theory(), theory_columns(style));
    at.y += plan.theory + gap;
  } else if (!plan.theory_in_tabs) {
    if (begin_panel("theory", style.theory_hidden ? "Predict, then watch" : "Theory against simulation", at,
                    ImVec2(width, plan.theory), column.theory_scrolls)) {
      predictions_and_theory(style, readings, column.class_answers_in_table);
    }
    end_panel();
    at.y += plan.theory + gap;
  }
  if (plan.books_tabbed) {
    books_tabs(lesson, style, readings, column, at, ImVec2(width, layout.column_corner.y + layout.column_size.y - at.y));
  } else {
    energy_panel(lesson.scene(), at, ImVec2(width, plan.energy), colours);
    at.y += plan.energy + gap;
    model_panel(lesson, at, ImVec2(width, plan.model));
  }
}

}  // namespace

void build_frame(lessons::Lesson& lesson, const lessons::WorldFraming& framing, const FrameStyle& style, ImVec2 display) {
  const Fonts& fonts = *style.fonts;
  const float s = fonts.scale;
  // Every text the panels draw is noted for the layout test.
  std::optional<TextRecording> noting;
  if (style.record != nullptr) noting.emplace(&style.record->texts);
  ImGui::PushFont(fonts.body);
  lessons::LessonReadings own;
  if (style.readings == nullptr) {
    own.duration = lesson.duration();
    own.expectations = lesson.expectations();
    lessons::zero_unresolved_motion(own.expectations, lesson);
  }
  const lessons::LessonReadings& readings = style.readings ? *style.readings : own;
  const ColumnChoice column = choose_column(lesson, style, display, readings);
  // On a projector the legend is a column beside the plots' row, as wide as its names need; a
  // lesson with no plots has no such row, and keeps the legend in its strip under the world.
  FrameLayout layout = FrameLayout::of(display, s, style.origin, style.projector, lesson).with_column_foot(style.column_foot);
  const bool legend_apart = layout.legend_beside_plots;
  if (legend_apart) layout = layout.with_legend_column(legend_column_width(lesson.scene(), fonts));

  title_panel(lesson, layout.title_corner, layout.title_size, fonts, style.projector, FrameLayout::title_padding * s);
  // The legend in a strip under the world, in the world's panel, or apart.
  const std::optional<LegendScale> legend = world_panel(lesson, framing, style, display, layout, legend_apart);
  if (legend_apart && legend) {
    if (begin_panel("legend", "", layout.legend_corner, layout.legend_size)) {
      draw_legend(ImGui::GetWindowDrawList(), lesson.scene(), legend->camera, layout.legend_corner, layout.legend_size,
                  theme(style.theme), fonts, legend->newtons_to_pixels);
    }
    end_panel();
  }
  const double now = lesson.scene().time();
  draw_plots(lesson, style, layout, time_axis_span(readings.duration, now, style.hidden.theory()), theme(style.theme));
  column_panels(lesson, style, readings, layout, column);
  ImGui::PopFont();
}

}  // namespace frictionlab::draw
