// The layout at the sizes a classroom uses, light and dark: no label lands on another label,
// on an arrow or under the free-body diagram, no moving body is under the diagram, and no text
// is cut by its panel (a panel's edge, a table's cell, a slider's frame, a tab, the screen),
// in the pictures and in the window with its sliders, tabs, menus and transport bar. The
// world's labels, the contrast and projector mode have files of their own beside this one.
#include "tests/layout_checks.h"

namespace frictionlab::classroom {
namespace {
using namespace layout_checks;

class Layout : public ::testing::TestWithParam<Screen> {};

TEST_P(Layout, EveryLessonsLabelsKeepClearOfEachOtherTheArrowsAndTheInset) {
  const Screen& screen = GetParam();
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    draw::HeadlessRenderer renderer(screen.width, screen.height, theme, screen.scale);
    for (const lessons::CatalogEntry& entry : lessons::catalog()) {
      for (const lessons::Moment& moment : entry.moments) {
        draw::LessonAt at(entry.name, moment.set, moment.at);
        draw::FrameRecord record;
        renderer.render(*at.lesson, at.framing, &record);
        std::string where = entry.name;
        where += " at ";
        where += moment.name;
        where += ", ";
        where += screen.name;
        if (theme == draw::ThemeName::dark) where += ", dark";
        check_layout(record, *at.lesson, where);
        if (screen.text) check_texts(record, where);
      }
    }
  }
}

// check_the_article's rows each give a claim's verdict ("· does not hold"): the mark beside the
// numbers, which says the simulation agrees with the exact solution, is in words ("model
// agrees"), never a bare ✓ a class reads as agreeing with "does not hold". Other lessons keep ✓.
TEST(TheoryTable, AMarkBesideAClaimsVerdictSaysItChecksTheModel) {
  for (const auto& [width, height] : {std::pair(1280, 720), std::pair(1920, 1080)}) {
    draw::HeadlessRenderer renderer(width, height);
    const auto texts_of = [&](const std::string& lesson, double t) {
      draw::LessonAt at(lesson, {}, t);
      draw::FrameRecord record;
      renderer.render(*at.lesson, at.framing, &record);
      std::vector<std::string> texts;
      for (const draw::ShownText& text : record.texts) texts.push_back(text.text);
      return texts;
    };
    const std::vector<std::string> article = texts_of("check_the_article", 5.0);
    int verdicts = 0, worded = 0;
    for (const std::string& text : article) {
      if (text.find(" \u00b7 does not hold") != std::string::npos || text.find(" \u00b7 holds") != std::string::npos) ++verdicts;
      if (text.rfind("model agrees", 0) == 0) ++worded;
      EXPECT_NE(text.rfind("\u2713", 0), 0u) << width << "x" << height << ": \"" << text << "\" is a bare mark";
    }
    EXPECT_GE(verdicts, 7) << width << "x" << height;
    EXPECT_EQ(worded, verdicts) << width << "x" << height;
    const std::vector<std::string> push = texts_of("push", 2.0);
    EXPECT_TRUE(std::any_of(push.begin(), push.end(), [](const std::string& text) { return text.rfind("\u2713 ", 0) == 0; }))
        << "push's table lost its \u2713";
  }
}

// A held block's measured acceleration is the step's float rounding (pulley held at μs 0.7
// measures −4.6×10⁻⁸ m/s², under ε·g, what a step resolves: lessons::motion_resolution): the
// picture's table shows it as 0, not as a power of ten.
TEST(TheoryTable, AHeldBlocksAccelerationUnderWhatTheStepResolvesIsShownAsZero) {
  draw::HeadlessRenderer renderer(1280, 720);
  draw::LessonAt at("pulley", {{"mu_s", "0.7"}}, 3.0);
  const std::vector<lessons::ExpectationResult> rows = at.lesson->expectations();
  const auto row = std::find_if(rows.begin(), rows.end(), [](const lessons::ExpectationResult& r) { return r.name == "acceleration"; });
  ASSERT_NE(row, rows.end());
  ASSERT_TRUE(row->measured_yet && row->measured != 0.0) << "the held block measured no rounding: the test tests nothing";
  draw::FrameRecord record;
  renderer.render(*at.lesson, at.framing, &record);
  int zeros = 0;
  for (const draw::ShownText& text : record.texts) {
    if (text.text.find("m/s") != std::string::npos) {
      EXPECT_EQ(text.text.find("\u00d710\u207b"), std::string::npos) << "\"" << text.text << "\" in " << text.panel;
    }
    if (text.text == "0 m/s\u00b2") ++zeros;
  }
  EXPECT_GE(zeros, 2) << "theory and measured, both 0 m/s²";
}

INSTANTIATE_TEST_SUITE_P(Screens, Layout, ::testing::ValuesIn(screens), screen_name);

class WindowLayout : public ::testing::TestWithParam<WindowScreen> {};

TEST_P(WindowLayout, EveryLessonsTextIsWholeAtTheStartMidRunAtTheEndAndRevealed) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const lessons::CatalogEntry& entry : lessons::catalog()) {
      ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
      options.window.theme = theme;
      Classroom window(options);
      const auto check_at = [&](double t, const char* moment) {
        window.playback().run_to(t);
        draw::FrameRecord record;
        // A few frames for tables and tab bars to settle their sizes, as the window's screenshots wait.
        for (int frame = 0; frame < 3; ++frame) {
          draw_window_frame(gl, host, window, display, 0.0, frame == 2 ? &record : nullptr);
        }
        std::string where = entry.name + " " + moment + ", window " + screen.name;
        if (theme == draw::ThemeName::dark) where += ", dark";
        check_texts(record, where);
      };
      const double duration = window.playback().lesson().duration();
      // As it opens (paused at t = 0), mid-run and when the run ends.
      check_at(0.0, "at the start");
      check_at(0.5 * duration, "mid-run");
      // The run's end says so in the transport bar.
      check_at(duration, "at the end");
      // The theory revealed beside the class's answers (each class's line under its row of the theory
      // table, or the class's lines above the table where it cannot be whole).
      for (const lessons::Prediction& prediction : window.playback().lesson().predictions()) {
        window.predictions().answers[prediction.expectation] = prediction.is_choice() ? prediction.choices.back() : "-12.5";
      }
      window.predictions().revealed = true;
      check_at(duration, "revealed");
    }
  }
}

// The tabs beside the theory table, each opened as a teacher clicks it: the energy ledger and
// the model card. Their lines ran past the column's right edge in projector mode.
TEST_P(WindowLayout, TheEnergyAndModelTabsTextIsWhole) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const lessons::CatalogEntry& entry : lessons::catalog()) {
      ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
      options.window.theme = theme;
      Classroom window(options);
      window.playback().run_to(0.5 * window.playback().lesson().duration());
      const auto frame = [&](draw::FrameRecord* record) {
        draw_window_frame(gl, host, window, display, 0.0, record);
      };
      for (const char* tab : {"###energy", "###model"}) {
        draw::FrameRecord before;
        frame(nullptr);
        frame(&before);
        const auto named = std::find_if(before.texts.begin(), before.texts.end(), [&](const draw::ShownText& text) {
          return text.text.find(tab) != std::string::npos;
        });
        ASSERT_NE(named, before.texts.end()) << entry.name << ": no tab " << tab;
        // A click on the tab's name, then a few frames for the tab to settle.
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(0.5f * (named->needed.x + named->needed.z), 0.5f * (named->needed.y + named->needed.w));
        frame(nullptr);
        io.MouseDown[0] = true;
        frame(nullptr);
        io.MouseDown[0] = false;
        frame(nullptr);
        io.MousePos = ImVec2(-1.0f, -1.0f);
        frame(nullptr);
        draw::FrameRecord record;
        frame(&record);
        std::string where = entry.name + " with the tab " + tab + " open, window " + screen.name;
        if (theme == draw::ThemeName::dark) where += ", dark";
        // What only that tab shows: the ledger's residual, the model card's friction terms.
        const char* shows = std::string(tab) == "###energy" ? "residual " : "friction: ";
        const bool open = std::any_of(record.texts.begin(), record.texts.end(), [&](const draw::ShownText& text) {
          return text.text.rfind(shows, 0) == 0;
        });
        EXPECT_TRUE(open) << where << ": the tab did not open";
        check_texts(record, where);
      }
    }
  }
}

// Whether a plot's legend lies on any of its data: a measured point or the line to the next,
// or a piece of a theory curve. Empty when none.
std::string legend_on_data(const draw::ChartLayout& plot) {
  // The data are drawn clipped to the data area (a pixel more at the right and bottom): only
  // the legend's part inside it can cover them.
  const ImVec4 legend(std::max(plot.legend_min.x, plot.low_left.x), std::max(plot.legend_min.y, plot.high_right.y),
                      std::min(plot.legend_max.x, plot.high_right.x + 1.0f), std::min(plot.legend_max.y, plot.low_left.y + 1.0f));
  if (!plot.drawable || !(legend.z > legend.x && legend.w > legend.y)) return "";
  const auto crosses = [&](const std::vector<ImVec2>& line) {
    for (std::size_t i = 0; i < line.size(); ++i) {
      const ImVec2 to = i + 1 < line.size() ? line[i + 1] : line[i];
      if (overlaps(legend, draw::DrawnSegment{line[i], to, 1.0f})) return text_of(ImVec4(line[i].x, line[i].y, to.x, to.y));
    }
    return std::string();
  };
  for (const std::vector<ImVec2>& series : plot.series_points) {
    if (const std::string at = crosses(series); !at.empty()) return "the data at " + at;
  }
  for (const auto& curve : plot.theory) {
    for (const std::vector<ImVec2>& piece : curve) {
      if (const std::string at = crosses(piece); !at.empty()) return "a theory curve at " + at;
    }
  }
  return "";
}

// Every plot of every lesson in the window on `screen` as the class sees it: through the run (at
// a quarter, half and its end, and a fifth of it past the end, where a window
// still records: tipping_box's box lies tipped, its "no contact" keyed) and after the theory is
// revealed (its curves add keys; at half and past the end), on every page of plots (turned by the
// pager's buttons, then its keys). `check` has each
// plot, the lesson's plot titles, where it was seen, and how many plots share its first page's
// row; every plot is on some page and every page's texts are whole.
void each_window_plot(const WindowScreen& screen,
                      const std::function<void(const draw::FrameRecord::Plot& plot, const std::string& title,
                                               const std::string& where, std::size_t side_by_side)>& check) {
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
    Classroom window(options);
    const double duration = window.playback().lesson().duration();
    const auto frame = [&](draw::FrameRecord* record) {
      draw_window_frame(gl, host, window, display, 0.0, record);
    };
    const std::size_t plot_count = window.playback().lesson().plots().size();
    // The pages are walked forward at one moment and back at the next, from the page the last
    // walk ended on: no frames go to turning back.
    bool forward = true;
    const auto check_at = [&](double t, const char* moment, bool by_button) {
      window.playback().run_to(t);
      const std::string where = entry.name + " " + moment + ", window " + screen.name;
      draw::FrameRecord record;
      frame(nullptr);
      frame(nullptr);
      frame(&record);
      // The plots in view, then those on each further page (turned by the pager, when there
      // are pages).
      std::vector<bool> seen(plot_count, false);
      std::vector<draw::FrameRecord::Plot> plots = record.plots;
      // Side by side: as many as a full page holds (a last page may hold fewer).
      std::size_t side_by_side = record.plots.size();
      const auto button = [](const draw::FrameRecord& shown, const char* label) -> const draw::ShownText* {
        for (const draw::ShownText& text : shown.texts) {
          if (text.text == label) return &text;
        }
        return nullptr;
      };
      const auto click = [&](const draw::ShownText& at) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(0.5f * (at.needed.x + at.needed.z), 0.5f * (at.needed.y + at.needed.w));
        frame(nullptr);
        io.MouseDown[0] = true;
        frame(nullptr);
        // A button acts when let go over it.
        io.MouseDown[0] = false;
        frame(nullptr);
        io.MousePos = ImVec2(-1.0f, -1.0f);
        frame(nullptr);
      };
      const char* arrow = forward ? "\u2192" : "\u2190";
      draw::FrameRecord page = record;
      int pages = 1;
      std::size_t page_start = plots.empty() ? 0 : plots.front().number;
      for (const draw::ShownText* next = button(page, arrow); next != nullptr && pages <= static_cast<int>(plot_count);
           next = button(page, arrow)) {
        // By the arrow's button at the run's first moment (so that the buttons turn every
        // lesson's pages), by its key after: one frame, where a click takes four.
        if (by_button) {
          const draw::ShownText at = *next;
          click(at);
        } else {
          window.key_pressed(forward ? Key::right : Key::left, false);
        }
        page = draw::FrameRecord();
        frame(&page);
        // The last page's arrow does nothing.
        if (page.plots.empty() || page.plots.front().number == page_start) break;
        page_start = page.plots.front().number;
        ++pages;
        check_texts(page, where + ", plot page " + std::to_string(pages));
        plots.insert(plots.end(), page.plots.begin(), page.plots.end());
        side_by_side = std::max(side_by_side, page.plots.size());
      }
      if (pages > 1) forward = !forward;
      for (const draw::FrameRecord::Plot& plot : plots) {
        ASSERT_LT(plot.number, plot_count) << where;
        seen[plot.number] = true;
        check(plot, window.playback().lesson().plots()[plot.number].title, where, side_by_side);
      }
      for (std::size_t i = 0; i < plot_count; ++i) {
        EXPECT_TRUE(seen[i]) << where << ": \"" << window.playback().lesson().plots()[i].title << "\" is on no page";
      }
    };
    for (const double share : {0.25, 0.5, 1.0, 1.2}) {
      char moment[32];
      std::snprintf(moment, sizeof moment, "at %.0f %% of the run", 100.0 * share);
      check_at(share * duration, moment, share == 0.25);
    }
    for (const lessons::Prediction& prediction : window.playback().lesson().predictions()) {
      window.predictions().answers[prediction.expectation] = prediction.is_choice() ? prediction.choices.back() : "1";
    }
    window.predictions().revealed = true;
    // Back to half the run, replayed from its record: run_to only steps forward, and this moment
    // was once drawn at 120 % under its "50 %" name. The end itself is left to the moments before
    // the reveal (the reveal's keys are the same at the end as a fifth past it).
    window.playback().scrub_to(0.5 * duration);
    ASSERT_NEAR(window.playback().lesson().scene().time(), 0.5 * duration, window.playback().lesson().scene().frame_step())
        << entry.name;
    for (const double share : {0.5, 1.2}) {
      char moment[48];
      std::snprintf(moment, sizeof moment, "revealed, at %.0f %% of the run", 100.0 * share);
      check_at(share * duration, moment, false);
    }
  }
}

// Every plot's legend off its data, in the window as the class sees it: through the run, before
// and after the theory is revealed (its curves add keys). With projector text three plots
// across the screen put 3–5-key legends over the data (wedge, check_the_article, tipping_box,
// push's friction against the pull after the reveal).
//
// And every level's text clear of its plot's legend and of the other levels' texts, in the window as
// the class sees it, through the run and after the reveal, every lesson's plots at each window
// size. Each text's box is measured here from what is drawn (its lines in the level font: the
// column's "label" over "= value" or one line, level_text_as_written, or the text by its line),
// not taken from the layout: tipping_box's tipping level, written on two lines ("tips:
// −m·g·width" over "/(2·push height) = …"), was placed as if one line high at 1280 × 720 and its
// second line ran over the legend's keys and the "slides" level's text. And clear of the axes'
// texts and of the levels' lines by a quarter of a line of its text at least (issue 31: after
// the reveal on a projector incline's "holding it: −m·g·sin θ = −5.63 N" stood 3 px over
// "time (s)", and at 1280 × 720 its "−μs·N = −4.82 N" 3 px off the middle of its own line, read
// as lying on it).
// (One walk for all: each walk of every lesson's plot pages is a minute of window frames
// under the sanitizers.)
TEST_P(WindowLayout, EveryPlotsLegendKeepsOffItsDataAndEveryLevelsTextOffTheLegendTheOtherLevelsTheLinesAndTheAxes) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  const float strip = [&] {
    Classroom window(class_window(lessons::resolve_lesson("push"), screen));
    return draw::FrameLayout::of(display, window.ui_scale(display)).plots_size.x;
  }();
  int texts = 0;
  each_window_plot(screen, [&](const draw::FrameRecord::Plot& plot, const std::string& title, const std::string& where,
                               std::size_t shown_together) {
    EXPECT_TRUE(plot.layout.drawable) << where << ": \"" << title << "\" has no data area";
    // Nor a sliver of data beside its legend: at least half its panel wide, less the panels'
    // padding (the incline's two plots side by side in projector mode drew their curves
    // 240 px wide of 575).
    // (A plot alone across the strip has nothing to give way to.)
    const std::size_t side_by_side = std::min<std::size_t>(shown_together, 3);
    const float panel = strip / static_cast<float>(side_by_side);
    if (side_by_side > 1) {
      EXPECT_GE(plot.layout.high_right.x - plot.layout.low_left.x, 0.45f * panel)
          << where << ": \"" << title << "\" draws its data " << plot.layout.high_right.x - plot.layout.low_left.x
          << " px wide in a panel " << panel << " px wide";
    }
    const std::string covered = legend_on_data(plot.layout);
    EXPECT_TRUE(covered.empty()) << where << ": the legend of \"" << title << "\" at "
                                 << text_of(ImVec4(plot.layout.legend_min.x, plot.layout.legend_min.y,
                                                   plot.layout.legend_max.x, plot.layout.legend_max.y))
                                 << (plot.layout.legend_outside ? " (outside)" : "")
                                 << (plot.layout.legend_on_data ? " (no room)" : "") << " lies on " << covered
                                 << "; data area " << text_of(ImVec4(plot.layout.low_left.x, plot.layout.high_right.y,
                                                                     plot.layout.high_right.x, plot.layout.low_left.y));
    const draw::ChartLayout& layout = plot.layout;
    const ImVec4 legend(layout.legend_min.x, layout.legend_min.y, layout.legend_max.x, layout.legend_max.y);
    std::vector<std::pair<std::string, ImVec4>> written;
    for (const draw::ChartLayout::Level& level : layout.levels) {
      if (level.text.empty()) continue;
      ASSERT_NE(layout.level_font, nullptr) << where;
      const std::string lines = draw::level_text_as_written(level, level.text);
      const ImVec2 size = layout.level_font->CalcTextSizeA(layout.level_font->FontSize, 1e6f, 0.0f, lines.c_str());
      const ImVec4 box(level.at.x, level.at.y, level.at.x + size.x, level.at.y + size.y);
      EXPECT_FALSE(layout.legend_at.size() > 0 && draw::overlaps(box, legend))
          << where << ": \"" << title << "\"'s level \"" << level.text << "\" at " << text_of(box)
          << " lies on the legend at " << text_of(legend);
      for (const auto& [other, other_box] : written) {
        EXPECT_FALSE(draw::overlaps(box, other_box)) << where << ": \"" << title << "\"'s level \"" << level.text << "\" at "
                                                     << text_of(box) << " lies on \"" << other << "\" at " << text_of(other_box);
      }
      // Clear of the axes' texts and of the levels' lines: its box as drawn (a pixel above and
      // below the text) a quarter of a line of its text or more from every tick label and axis
      // name, and, by its line in the data area, from every level's line's middle, its own too,
      // unless written on its own line, centred on it, which its box then breaks (where there is
      // no room beside it).
      const float quarter = 0.25f * layout.level_font->FontSize;
      const bool on_its_line = std::abs(0.5f * (box.y + box.w) - level.y) <= 1.0f;
      const ImVec4 as_drawn(box.x, box.y - 1.0f, box.z, box.w + 1.0f);
      for (const draw::ChartLayout::AxisText& axis : layout.axis_texts) {
        if (axis.text.empty()) continue;
        const float apart = std::max({axis.at.x - as_drawn.z, as_drawn.x - axis.at.z, axis.at.y - as_drawn.w, as_drawn.y - axis.at.w});
        EXPECT_GE(apart, quarter) << where << ": \"" << title << "\"'s level \"" << level.text << "\" at " << text_of(as_drawn)
                                  << " is " << apart << " px from the axis' \"" << axis.text << "\" at " << text_of(axis.at)
                                  << ", under a quarter of a line (" << quarter << " px)";
      }
      if (!level.beside) {
        for (const draw::ChartLayout::Level& line : layout.levels) {
          if (&line == &level && on_its_line) continue;
          const float apart = std::max(line.y - as_drawn.w, as_drawn.y - line.y);
          EXPECT_GE(apart, quarter) << where << ": \"" << title << "\"'s level \"" << level.text << "\" at " << text_of(as_drawn)
                                    << " is " << apart << " px from the middle of "
                                    << (&line == &level ? std::string("its own line") : "the line of \"" + line.text + "\"")
                                    << " at y = " << line.y << ", under a quarter of a line (" << quarter << " px)";
        }
      }
      written.emplace_back(level.text, box);
      ++texts;
    }
  });
  // Not a test of nothing: push's key plot at least labels its −μs·N and −μk·N levels at the
  // three moments after the reveal.
  EXPECT_GE(texts, 6);
}

// How much of a panel of the column is left empty under what it drew, and whether it scrolls.
struct ColumnPanel {
  bool drawn = false, scrolls = false;
  float empty = 0.0f;
};
ColumnPanel column_panel(const char* id) {
  const ImGuiWindow* panel = ImGui::FindWindowByName(id);
  ColumnPanel found;
  if (panel == nullptr || !panel->WasActive) return found;
  found.drawn = true;
  found.scrolls = panel->ScrollMax.y > 0.0f;
  found.empty = panel->Pos.y + panel->Size.y - panel->WindowPadding.y - panel->DC.CursorMaxPos.y;
  return found;
}

// The column's room goes where it is needed: while the theory table (or the class's
// predictions, or the tabs it shares) scrolls, the Parameters panel keeps no empty room under
// its controls. check_the_article's table showed 5 of its 7 rows in projector mode beside a
// Parameters panel half empty.
TEST_P(WindowLayout, TheParametersLeaveTheirSpareRoomToTheTheoryWhenItScrolls) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  int scrolled = 0;
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    for (const bool predictions : {false, true}) {
      ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
      options.window.predictions = predictions;
      Classroom window(options);
      const auto check_at = [&](double t, const char* moment) {
        window.playback().run_to(t);
        for (int frame = 0; frame < 4; ++frame) {
          draw_window_frame(gl, host, window, display, 0.0, nullptr);
        }
        const std::string where = entry.name + " " + moment + (predictions ? " with predictions" : "") + ", window " +
                                  screen.name;
        const ColumnPanel parameters = column_panel("###parameters");
        ASSERT_TRUE(parameters.drawn) << where;
        const ColumnPanel theory = column_panel("###theory"), books = column_panel("###books");
        if (!theory.scrolls && !books.scrolls) return;
        ++scrolled;
        EXPECT_LE(parameters.empty, ImGui::GetFrameHeightWithSpacing())
            << where << ": the theory scrolls while the Parameters panel keeps " << parameters.empty << " px empty";
      };
      check_at(0.0, "at the start");
      for (const lessons::Prediction& prediction : window.playback().lesson().predictions()) {
        window.predictions().answers[prediction.expectation] = prediction.is_choice() ? prediction.choices.back() : "1";
      }
      window.predictions().revealed = true;
      check_at(window.playback().lesson().duration(), "revealed at the end");
    }
  }
  if (screen.projector) {
    EXPECT_GT(scrolled, 0) << "no lesson's theory scrolls in projector mode: the test tests nothing";
  }
}

// While the class predicts, every question and its answer's box is in sight: the friction pairs'
// sliders give way for them. A teacher typing the class's answers on a projector found push's
// second question a scroll away, and scrolling took the reveal button out of sight.
TEST_P(WindowLayout, EveryPredictionIsInSightBeforeTheReveal) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
    options.window.predictions = true;
    Classroom window(options);
    for (int frame = 0; frame < 4; ++frame) {
      draw_window_frame(gl, host, window, display, 0.0, nullptr);
    }
    ASSERT_TRUE(window.theory_hidden()) << entry.name;
    const ColumnPanel theory = column_panel("###theory"), books = column_panel("###books");
    EXPECT_FALSE(theory.scrolls || books.scrolls) << entry.name << ", window " << screen.name
                                                  << ": the class's predictions are a scroll away";
  }
}

// The help panel a newcomer's first window opens with (F1) stood in the middle of the window,
// over the spring, the block and half the sliders of the first lesson (a trial of the web page);
// then under the sliders, over the Predict tab, its question and its Reveal button (a teacher's
// projector trial); then over the plots' row, which hid the key plot once the run began (issue
// 31's trial at 1920x1080 in projector mode); then under the whole frame, which shrank the world
// (ForceLabels.EveryValueStandsBesideItsArrowAndTheScaleBarIsWholeWithTheHelpOpenOnAProjector).
// It is docked in a strip of its own at the foot of the column, over the transport bar: at the
// run's end, the key plot drawn, it overlaps no other panel, and every question of the class and
// its answer's box are in sight (the column does not scroll them away, shorter by the strip).
TEST_P(WindowLayout, TheHelpPanelIsDockedUnderTheColumnAndCoversNoPanelNorPushesAQuestionOutOfSight) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  int key_plots = 0;
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    draw::ImGuiHost host(nullptr);
    ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
    options.window.help = true;
    options.window.predictions = true;
    Classroom window(options);
    window.playback().run_to(window.playback().lesson().duration());
    draw::FrameRecord record;
    for (int frame = 0; frame < 4; ++frame) draw_window_frame(gl, host, window, display, 0.0, &record);
    const std::string where = entry.name + ", window " + screen.name;
    const ImGuiWindow* help = ImGui::FindWindowByName("Help (F1 shows and hides it)");
    ASSERT_TRUE(help != nullptr && help->WasActive) << where;
    // Nothing of the shorter frame is cut (the help's own rows scroll in its strip).
    draw::FrameRecord frame_texts = record;
    std::erase_if(frame_texts.texts, [](const draw::ShownText& text) { return text.panel.rfind("Help (F1", 0) == 0; });
    check_texts(frame_texts, where + " with the help open");
    const ImRect help_rect = help->Rect();
    EXPECT_GE(help_rect.Min.x, 0.0f) << where;
    EXPECT_LE(help_rect.Max.x, display.x + 0.5f) << where;
    EXPECT_LE(help_rect.Max.y, display.y + 0.5f) << where;
    // Three lines of keys in sight under its title, at least.
    EXPECT_GE(help_rect.GetHeight(), help->TitleBarHeight() + 3.0f * ImGui::GetTextLineHeight()) << where;
    for (const ImGuiWindow* other : ImGui::GetCurrentContext()->Windows) {
      if (other == help || !other->WasActive || (other->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Popup |
                                                                  ImGuiWindowFlags_Tooltip)) != 0) {
        continue;
      }
      if (std::string(other->Name).rfind("Debug##", 0) == 0) continue;  // ImGui's own, never drawn
      // Touching edges (the strip starts where the frame ends) is no overlap.
      ImRect inside = other->Rect();
      inside.Expand(-0.5f);
      EXPECT_FALSE(help_rect.Overlaps(inside)) << where << ": the help panel covers " << other->Name;
    }
    const ImGuiWindow* plot = ImGui::FindWindowByName("###plot pager");
    if (plot == nullptr || !plot->WasActive) plot = ImGui::FindWindowByName("###plot0");
    if (plot != nullptr && plot->WasActive) ++key_plots;
    const ColumnPanel theory = column_panel("###theory"), books = column_panel("###books");
    if (window.theory_hidden()) {
      EXPECT_FALSE(theory.scrolls || books.scrolls) << where << ": with the help open the class's predictions are a scroll away";
    }
  }
  EXPECT_GT(key_plots, 0) << screen.name << ": no key plot was drawn beside the help: the test tests nothing";
}

// A projector trial saw a band of glyphs under the help panel's title: one row of pixels where the
// rounded title bar's anti-aliased lower edge met the body's upper edge, each covering it only in
// part, let the tabs under the panel show through. Across the panel's width (its border and
// scroll bar left out), the rows round that seam are each one colour: title bar, body, or one
// blend of the two, never the words of what lies under them.
TEST_P(WindowLayout, NothingUnderTheHelpPanelShowsThroughBelowItsTitle) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  for (const char* lesson : {"push", "tipping_box"}) {
    draw::ImGuiHost host(nullptr);
    ClassroomOptions options = class_window(lessons::resolve_lesson(lesson), screen);
    options.window.help = true;
    options.window.predictions = true;
    Classroom window(options);
    for (int frame = 0; frame < 4; ++frame) draw_window_frame(gl, host, window, display, 0.0, nullptr);
    gl.make_current();
    gl.bind_framebuffer(screen.width, screen.height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    const draw::Image picture = gl.read_pixels();
    const ImGuiWindow* help = ImGui::FindWindowByName("Help (F1 shows and hides it)");
    ASSERT_TRUE(help != nullptr && help->WasActive) << lesson;
    const int seam = static_cast<int>(std::floor(help->Pos.y + help->TitleBarHeight()));
    const int left = static_cast<int>(std::ceil(help->Pos.x)) + 3;
    const int right = static_cast<int>(std::floor(help->Pos.x + help->Size.x - help->ScrollbarSizes.x)) - 3;
    ASSERT_GT(right - left, 100) << lesson;
    for (int y = seam - 1; y <= seam + 1; ++y) {
      int differing = 0;
      for (int x = left; x < right; ++x) {
        for (int channel = 0; channel < 3; ++channel) {
          if (std::abs(picture.pixel(x, y)[channel] - picture.pixel(left, y)[channel]) > 2) {
            ++differing;
            break;
          }
        }
      }
      EXPECT_EQ(differing, 0) << lesson << ", window " << screen.name << ": " << differing << " pixels of row " << y
                              << " (the help's title bar ends at " << help->Pos.y + help->TitleBarHeight()
                              << ") differ from its first: what lies under the panel shows through";
    }
  }
}

// At the run's end a teacher reads what the run measured beside each of the class's answers,
// reveals the theory, and sets class, theory and measurement side by side: every question (its
// short name once revealed), the class's answer and its comparison (the measurement before the
// reveal; after it the verdict under class, theory and measured) stays in sight, none a scroll
// away. In projector mode six lessons' answers were a scroll away before the reveal (stacked_blocks,
// friction_models, lubricated, terrain, tipping_box, wedge) and four lessons' after it.
TEST_P(WindowLayout, EveryAnswerIsInSightAtTheRunsEnd) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  int checked = 0, out_of_sight = 0;
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
    options.window.predictions = true;
    Classroom window(options);
    const std::vector<lessons::Prediction> predictions = window.playback().lesson().predictions();
    if (predictions.empty()) continue;
    // Typed before Play, as a class answers: numbers that are off, the last of each choice.
    for (const lessons::Prediction& prediction : predictions) {
      window.predictions().answers[prediction.expectation] = prediction.is_choice() ? prediction.choices.back() : "-12.5";
    }
    window.playback().run_to(window.playback().lesson().duration());
    for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
      for (const bool revealed : {false, true}) {
        window.window_settings().theme = theme;
        window.predictions().revealed = revealed;
        draw::FrameRecord record;
        for (int frame = 0; frame < 4; ++frame) draw_window_frame(gl, host, window, display, 0.0, frame == 3 ? &record : nullptr);
        std::string where = entry.name + (revealed ? " revealed" : " before the reveal") + " at the run's end, window " +
                            screen.name + (theme == draw::ThemeName::dark ? ", dark" : "");
        ASSERT_EQ(window.theory_hidden(), !revealed) << where;
        // The column's panels one under the other: none over the answers.
        const ImGuiWindow* parameters = ImGui::FindWindowByName("###parameters");
        ASSERT_TRUE(parameters != nullptr && parameters->WasActive) << where;
        for (const char* id : {"###theory", "###books"}) {
          const ImGuiWindow* below = ImGui::FindWindowByName(id);
          if (below == nullptr || !below->WasActive) continue;
          EXPECT_LE(parameters->Pos.y + parameters->Size.y, below->Pos.y + 0.5f)
              << where << ": the Parameters panel reaches down over " << id;
        }
        // Each prediction's texts in the order drawn, its first the first of that name: the
        // class's row above the theory table where the class's lines stand apart, else the theory
        // table's own row, the class's answer in its column (in the table's order of rows, which
        // need not be the questions').
        for (const lessons::Prediction& prediction : predictions) {
          std::size_t next = 0;
          for (const auto& [text, prefix] : answer_texts(window, prediction, revealed, where, record)) {
            const std::optional<std::size_t> found = lower_panel_text(record, next, text, prefix);
            ++checked;
            if (!found) {
              ADD_FAILURE() << where << ": \"" << text << "\" (" << prediction.expectation << ") is not drawn";
              ++out_of_sight;
              continue;
            }
            next = *found + 1;
            const draw::ShownText& shown = record.texts[*found];
            if (!shown.whole()) ++out_of_sight;
            EXPECT_TRUE(shown.whole()) << where << ": \"" << text << "\" needs " << text_of(shown.needed)
                                       << " but only " << text_of(shown.visible) << " shows: a scroll away";
          }
        }
      }
    }
  }
  std::printf("[ %s ] %d of %d answers' texts out of sight at the run's end\n", screen.name, out_of_sight, checked);
  EXPECT_GT(checked, 0);
}

INSTANTIATE_TEST_SUITE_P(Screens, WindowLayout, ::testing::ValuesIn(window_screens), window_screen_name);

// The Mystery tab as the class sees it, answers typed, before and after the reveal: every
// lesson with a pair that can be a mystery, its first such pair.
class MysteryLayout : public ::testing::TestWithParam<WindowScreen> {};

TEST_P(MysteryLayout, TheMysteryTabsTextIsWholeBeforeAndAfterTheReveal) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  int lessons_with_a_mystery = 0;
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    ClassroomOptions options = class_window(lessons::resolve_lesson(entry.name), screen);
    const std::vector<std::string> pairs = classroom_state::mystery_pairs(lessons::Lesson(options.lesson));
    if (pairs.empty()) continue;
    ++lessons_with_a_mystery;
    options.mystery = classroom_state::MysteryChoice{pairs.front(), 1};
    // No predictions asked: they would keep the Predict tab in front of the Mystery tab (the
    // tab opened by a click, with predictions asked: WindowTabsLayout).
    options.window.predictions = false;
    Classroom window(options);
    window.answer_mystery(0.5, 0.25);
    for (const bool revealed : {false, true}) {
      if (revealed) window.reveal_mystery();
      draw::FrameRecord record;
      for (int frame = 0; frame < 3; ++frame) {
        draw_window_frame(gl, host, window, display, 0.0, frame == 2 ? &record : nullptr);
      }
      const std::string where = entry.name + " with " + pairs.front() + " a mystery" + (revealed ? ", revealed" : "") +
                                ", window " + screen.name;
      // Its answers' line: kept until the reveal, then how far off.
      const char* answered = revealed ? "% off" : "kept for the reveal";
      const bool tab_shown = std::any_of(record.texts.begin(), record.texts.end(), [&](const draw::ShownText& text) {
        return text.text.find(answered) != std::string::npos;
      });
      EXPECT_TRUE(tab_shown) << where << ": the Mystery tab is not showing";
      check_texts(record, where);
    }
  }
  EXPECT_GE(lessons_with_a_mystery, 5);
}

INSTANTIATE_TEST_SUITE_P(Screens, MysteryLayout, ::testing::ValuesIn(window_screens), window_screen_name);

// The window with the force gauge pulling and every measuring tool on: the gauge's reading, the
// stopwatch, the speed, the distance marks' numbers and the weight's components along a slope
// keep clear of each other, of the lesson's labels and arrows and of the inset, and the gauge's
// plot and the theory table's hand-pulled rows are whole, light and dark, in projector mode too.
TEST_P(WindowLayout, TheForceGaugeAndTheMeasuringToolsKeepClear) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const char* name : {"push", "incline", "spring_pull"}) {
      ClassroomOptions options = class_window(lessons::resolve_lesson(name), screen);
      if (std::string(name) == "incline") options.overrides = {{"angle", "25"}};
      options.window.theme = theme;
      options.window.tools = ToolSettings{true, true, true, true};
      Classroom window(options);
      const auto frame = [&](double wall, draw::FrameRecord* record) {
        draw_window_frame(gl, host, window, display, wall, record);
      };
      frame(0.0, nullptr);
      // The stopwatch running with a lap (shown before the run, Play starts it), and the hand
      // pulling the main body to the right for a second and a half, still held when the frame is
      // recorded.
      const b2Body* body = measured_body(window.playback().lesson());
      const ImVec2 held = window.world_camera().to_screen(body->GetWorldCenter());
      ImGuiIO& io = ImGui::GetIO();
      io.MousePos = held;
      frame(0.0, nullptr);
      io.MouseDown[0] = true;
      frame(0.0, nullptr);
      window.key_pressed(Key::space, false);
      for (int i = 1; i <= 90; ++i) {
        io.MousePos = ImVec2(held.x + static_cast<float>(i), held.y);
        frame(1.0 / 60.0, nullptr);
        if (i == 45) window.key_pressed(Key::l, false);
      }
      ASSERT_NE(window.playback().lesson().scene().grabbed(), nullptr) << name;
      draw::FrameRecord record;
      frame(0.0, &record);
      std::string where = std::string(name) + " with the gauge and tools, window " + screen.name;
      if (theme == draw::ThemeName::dark) where += ", dark";
      check_layout(record, window.playback().lesson(), where);
      check_texts(record, where);
      // The new rectangles are the layout's: the gauge's coil, from the point held to the hand's
      // end, is among what labels keep off; the stopwatch is over the title, whole (checked
      // above), not in the world.
      ASSERT_EQ(record.lanes.size(), 1u) << where;
      const draw::FrameRecord::Lane& lane = record.lanes.front();
      const Scene& scene = window.playback().lesson().scene();
      const ImVec2 hook = lane.camera.to_screen(scene.grabbed()->GetWorldPoint(scene.applied_forces().back().local_point));
      const ImVec2 hand = lane.camera.to_screen(scene.grab_hand());
      const bool coil = std::any_of(lane.arrows.begin(), lane.arrows.end(), [&](const draw::DrawnSegment& segment) {
        return std::abs(segment.from.x - hook.x) < 1.0f && std::abs(segment.from.y - hook.y) < 1.0f &&
               std::abs(segment.to.x - hand.x) < 1.0f && std::abs(segment.to.y - hand.y) < 1.0f;
      });
      EXPECT_TRUE(coil) << where << ": the gauge's coil is not in the layout";
      const bool stopwatch = std::any_of(record.texts.begin(), record.texts.end(), [](const draw::ShownText& text) {
        return text.text.rfind("stopwatch ", 0) == 0 && text.text.find("lap 1: ") != std::string::npos;
      });
      EXPECT_TRUE(stopwatch) << where << ": no stopwatch with its lap over the title";
      // The speed and the gauge's reading, off the body held (the gauge's sat on push's block).
      EXPECT_EQ(readings_off(lane, scene.grabbed(), where), 2) << where;
      io.MouseDown[0] = false;
      frame(0.0, nullptr);
    }
  }
}

// The lessons with lanes or several bodies, in the window with every measuring tool on, as the
// trial's teacher ran them (terrain at the run's end showed "stopwatch 99.00 s (paused)" written
// across "asphalt box"), at the start, mid-run and run on past the end: the stopwatch is over the
// title, whole and on no lane; the speed says whose it is (in a lane named by the body, the
// lane's name does), once, off the body it reads; the distance marks carry at least one number
// in the measured body's lane (the launched boxes' lanes had no marks at all, and "0 m" was
// never shown, hidden by its own tick); and every layout rule of check_layout and check_texts holds.
TEST_P(WindowLayout, TheMeasuringToolsAreReadableInTheLessonsWithLanes) {
  const WindowScreen& screen = GetParam();
  const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  const std::pair<const char*, double> runs[] = {{"terrain", 99.0},         {"contact_area", 1.0},
                                                 {"friction_models", 1.0}, {"thrown_box", 1.5},
                                                 {"where_methods_fail", 3.0}, {"stacked_blocks", 2.0}};
  for (const auto& [name, end] : runs) {
    for (const double at : {0.0, 0.5 * end, end}) {
      ClassroomOptions options = class_window(lessons::resolve_lesson(name), screen);
      options.window.tools = ToolSettings{true, true, true, true};
      Classroom window(options);
      draw::FrameRecord record;
      for (int frame = 0; frame < 3; ++frame) {
        if (frame == 1) window.run_to(at);
        draw_window_frame(gl, host, window, display, 0.0, frame == 2 ? &record : nullptr);
      }
      char when[32];
      std::snprintf(when, sizeof when, " at %.2f s", at);
      const std::string where = std::string(name) + when + ", window " + screen.name;
      check_layout(record, window.playback().lesson(), where);
      check_texts(record, where);
      const auto stopwatch = std::find_if(record.texts.begin(), record.texts.end(), [](const draw::ShownText& text) {
        return text.text.rfind("stopwatch ", 0) == 0;
      });
      ASSERT_NE(stopwatch, record.texts.end()) << where << ": no stopwatch in the window's panels";
      // Over the title: above the world's first lane.
      EXPECT_LE(stopwatch->needed.w, record.lanes.front().camera.origin.y) << where << ": the stopwatch is not over the world";
      const lessons::Lesson& lesson = window.playback().lesson();
      const b2Body* body = measured_body(lesson);
      ASSERT_NE(body, nullptr) << where;
      const std::string named = lessons::class_words(std::find_if(lesson.scene().bodies().begin(), lesson.scene().bodies().end(),
                                                         [&](const auto& entry) { return entry.second == body; })->first) + ": v = ";
      int readouts = 0, numbers = 0;
      for (const draw::FrameRecord::Lane& lane : record.lanes) {
        for (const std::string& text : lane.texts) {
          EXPECT_NE(text.rfind("stopwatch", 0), 0u) << where << ": the stopwatch is in a lane";
          if (text.find("v = ") != std::string::npos) {
            ++readouts;
            // In a lane named by the body itself, its name is beside it already.
            const lessons::View& view = lesson.view();
            const bool lane_names_it = view.kind == lessons::View::Kind::lanes && view.titles.empty();
            if (!lane_names_it || text.rfind("v = ", 0) != 0) {
              EXPECT_EQ(text.rfind(named, 0), 0u) << where << ": \"" << text << "\" does not say whose speed it is";
            }
          }
          if (text.size() > 2 && text.compare(text.size() - 2, 2, " m") == 0) ++numbers;
          // The ticks' spacing beside a lone number reads the scale as well as two numbers.
          if (text.rfind("ticks ", 0) == 0) ++numbers;
        }
        readings_off(lane, body, where);
      }
      EXPECT_EQ(readouts, 1) << where;
      // (A body launched at t = 0 stands on no surface until its first step.)
      if (lesson.scene().frame() > 0 || body->GetLinearVelocity().Length() == 0.0f) {
        // Two numbers, or one and the ticks' spacing, give the scale; a projector's thinnest lanes
        // (terrain's, friction_models', where_methods_fail's) have room for one number only.
        EXPECT_GE(numbers, 1) << where << ": no distance mark's number";
      }
    }
  }
}

// An open menu hides what is under it: its background (every popup's) and the menu bar's are
// opaque in both themes, at a screen's text size and in projector mode. ImGui's own popups are
// 94 % (dark) and 98 % (light) opaque, and on a projector the title and panels showed through.
TEST(Menus, AreOpaqueInBothThemes) {
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const float scale : {1.0f, 1.35f * 1.5f}) {
      host.prepare(scale, theme);
      const ImGuiStyle& style = ImGui::GetStyle();
      const char* where = theme == draw::ThemeName::dark ? "dark" : "light";
      EXPECT_EQ(style.Colors[ImGuiCol_PopupBg].w, 1.0f) << where << " at text scale " << scale;
      EXPECT_EQ(style.Colors[ImGuiCol_MenuBarBg].w, 1.0f) << where << " at text scale " << scale;
    }
  }
}

// The menu bar names the running script's file, so a student knows which to edit. A path
// longer than the bar has room for (a projector's large text, a student's folder deep in
// their home) shows its start and its whole file name with "…" between, never cut at the
// window's edge; a path that fits shows whole.
TEST(Menus, TheMenuBarShowsAsMuchOfTheScriptsPathAsFitsAndCutsNone) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / "frictionlab_menu_path" /
                          "a_folder_name_long_enough_to_fill_a_projectors_menu_bar_twice_over" /
                          "and_another_one_inside_it_for_the_classroom_of_tuesday_morning";
  fs::create_directories(folder);
  const fs::path script = folder / "check_the_article.lua";
  fs::copy_file(lessons::resolve_lesson("check_the_article"), script, fs::copy_options::overwrite_existing);
  draw::HeadlessContext gl;
  draw::ImGuiHost host(nullptr);
  for (const WindowScreen& screen : window_screens) {
    for (const std::string& path : {script.string(), lessons::resolve_lesson("wedge")}) {
      ClassroomOptions options = class_window(path, screen);
      Classroom window(options);
      const ImVec2 display(static_cast<float>(screen.width), static_cast<float>(screen.height));
      draw::FrameRecord record;
      for (int frame = 0; frame < 3; ++frame) draw_window_frame(gl, host, window, display, 0.0, frame == 2 ? &record : nullptr);
      const std::string name = fs::path(path).filename().string();
      int shown = 0;
      for (const draw::ShownText& text : record.texts) {
        if (text.text.size() < name.size() || text.text.compare(text.text.size() - name.size(), name.size(), name) != 0) continue;
        ++shown;
        const std::string where = std::string(screen.name) + ": \"" + text.text + "\"";
        EXPECT_TRUE(text.whole()) << where << " is cut: it needs x " << text.needed.x << " to " << text.needed.z << ", the bar shows "
                                  << text.visible.x << " to " << text.visible.z;
        if (path == script.string()) {
          EXPECT_NE(text.text.find("\u2026/"), std::string::npos) << where << ": too long to show whole";
          EXPECT_EQ(text.text.rfind("/", 0), 0u) << where << ": its start";
        }
      }
      EXPECT_EQ(shown, 1) << screen.name << ": " << name << " in the menu bar";
    }
  }
  fs::remove_all(fs::temp_directory_path() / "frictionlab_menu_path");
}

// The window's own tabs as a teacher opens them, each by a click on its name: the Cheapest
// setting tab (as it opens, with a tolerance refused, and with the cheapest setting found), the
// Stability map tab, and the Mystery tab of a lesson with a mystery pair. Every lesson, at each
// size, light and dark: every text of the tab whole.
class WindowTabs {
 public:
  WindowTabs(const WindowScreen& screen, ClassroomOptions options)
      : display_(static_cast<float>(screen.width), static_cast<float>(screen.height)) {
    options.lesson = lessons::resolve_lesson(options.lesson);
    options.window.help = false;
    options.window.projector = screen.projector;
    window_ = std::make_unique<Classroom>(options);
    // A tab bar lays its tabs out in its first frame: a hand finds them from the second.
    frame();
    frame();
  }
  Classroom& window() { return *window_; }
  void frame(draw::FrameRecord* record = nullptr) { draw_window_frame(gl_, host_, *window_, display_, 0.0, record); }
  void click(const std::string& control) {
    frame();
    const std::optional<ImRect> rect = window_->control(control);
    ASSERT_TRUE(rect.has_value()) << "no " << control << " was drawn";
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = rect->GetCenter();
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
    io.MousePos = ImVec2(-1.0f, -1.0f);  // no tooltip over what is checked
  }
  void type(const std::string& text) {
    for (const char c : text) ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(c));
    frame();
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown[io.KeyMap[ImGuiKey_Enter]] = true;
    frame();
    io.KeysDown[io.KeyMap[ImGuiKey_Enter]] = false;
    frame();
  }
  // The frame after a few have let the tab bar settle, light and dark, each checked whole and
  // for `shows` (a text only that tab draws).
  void check(const std::string& where, const std::string& shows) {
    for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
      window_->window_settings().theme = theme;
      frame();
      frame();
      draw::FrameRecord record;
      frame(&record);
      const std::string said = where + (theme == draw::ThemeName::dark ? ", dark" : "");
      const bool shown = std::any_of(record.texts.begin(), record.texts.end(), [&](const draw::ShownText& text) {
        return text.text.find(shows) != std::string::npos;
      });
      EXPECT_TRUE(shown) << said << ": no \"" << shows << "\": the tab is not showing";
      check_texts(record, said);
    }
  }

 private:
  draw::HeadlessContext gl_;
  draw::ImGuiHost host_{nullptr};
  ImVec2 display_;
  std::unique_ptr<Classroom> window_;
};

class WindowTabsLayout : public ::testing::TestWithParam<WindowScreen> {};

TEST_P(WindowTabsLayout, TheCheapestStabilityAndMysteryTabsTextIsWholeWhenEachIsSelected) {
  const WindowScreen& screen = GetParam();
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    const std::string where = entry.name + ", window " + screen.name;
    {
      ClassroomOptions options;
      options.lesson = entry.name;
      WindowTabs tabs(screen, options);
      tabs.click("Cheapest setting tab");
      tabs.check(where + ", Cheapest setting tab", "Runs this lesson at each setting");
      tabs.click("Stability map tab");
      const bool has_map = !tabs.window().stability_map_tab().chart.cells.empty();
      tabs.check(where + ", Stability map tab", has_map ? "the regularized law here" : "This lesson has no \u03bcs");
    }
    const std::vector<std::string> pairs = classroom_state::mystery_pairs(lessons::Lesson(lessons::resolve_lesson(entry.name)));
    if (pairs.empty()) continue;
    ClassroomOptions options;
    options.lesson = entry.name;
    options.mystery = classroom_state::MysteryChoice{pairs.front(), 1};
    WindowTabs tabs(screen, options);
    tabs.window().answer_mystery(0.5, 0.25);
    tabs.click("Mystery tab");
    tabs.check(where + " with " + pairs.front() + " a mystery, Mystery tab", "kept for the reveal");
  }
  // A tolerance refused, then the cheapest setting found and named.
  ClassroomOptions options;
  options.lesson = "incline";
  WindowTabs tabs(screen, options);
  tabs.click("Cheapest setting tab");
  tabs.click("tolerance");
  tabs.type("-1");
  tabs.check(std::string("incline, window ") + screen.name + ", a tolerance refused", "must be a positive number");
  tabs.click("tolerance");
  tabs.type("0.01");
  tabs.click("measure");
  for (int i = 0; i < 100 && tabs.window().control("use it") == std::nullopt; ++i) tabs.frame();
  ASSERT_TRUE(tabs.window().control("use it").has_value()) << "the search did not end";
  tabs.check(std::string("incline, window ") + screen.name + ", the cheapest setting found", "Cheapest within");
}

INSTANTIATE_TEST_SUITE_P(Screens, WindowTabsLayout, ::testing::ValuesIn(window_screens), window_screen_name);

}  // namespace
}  // namespace frictionlab::classroom
