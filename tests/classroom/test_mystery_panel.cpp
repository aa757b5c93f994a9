// The mystery surface in the window: no hidden value in any text drawn, the CSV or the title
// before the reveal, and every one of them after; the class's answers and how far off each is
// (the draw itself is tests/classroom_state/test_mystery.cpp's).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "classroom_state/mystery.h"
#include "classroom_state/playback.h"
#include "draw/overlays.h"
#include "lessons/runtime/history_csv.h"
#include "lessons/runtime/lesson.h"
#include "physics/validation.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// Whether `text` shows `value` as a number in any of the ways a panel writes one ("0.47",
// "0.470"), not as part of a longer number ("10.47", "0.475").
bool mentions(const std::string& text, double value) {
  std::set<std::string> forms{validation::exact_text(value)};
  for (const char* format : {"%.2f", "%.3f", "%g", "%.3g"}) {
    char shown[32];
    std::snprintf(shown, sizeof shown, format, value);
    forms.insert(shown);
  }
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  for (const std::string& form : forms) {
    for (std::size_t at = text.find(form); at != std::string::npos; at = text.find(form, at + 1)) {
      const bool starts = at == 0 || (!digit(text[at - 1]) && text[at - 1] != '.');
      const std::size_t end = at + form.size();
      const bool ends = end >= text.size() || !(digit(text[end]) || (text[end] == '.' && end + 1 < text.size() && digit(text[end + 1])));
      if (starts && ends) return true;
    }
  }
  return false;
}

ClassroomOptions mystery_options(const std::string& lesson, const std::string& pair, std::uint64_t seed) {
  ClassroomOptions options;
  options.lesson = lesson;
  options.mystery = classroom_state::MysteryChoice{pair, seed};
  return options;
}

// The seed whose values the window tests hide: no other text of spring_pull at these moments
// happens to show the same numbers, so a mention is a leak.
constexpr std::uint64_t window_seed = 42;

// The window with the theory table showing (predictions not asked for), or asking the class to
// predict first, or with the class's predictions revealed beside the theory.
enum class Theory { table, predict_first, predictions_revealed };

class MysteryHidden : public ::testing::TestWithParam<Theory> {};

TEST_P(MysteryHidden, NoHiddenValueIsShownWrittenOrInTheTitleUntilTheReveal) {
  ClassroomOptions options = mystery_options("spring_pull", "aluminium/wood", window_seed);
  options.window.predictions = GetParam() != Theory::table;
  // Tall enough for spring_pull's four rows of theory to keep their own panel beside the tabs.
  ClassroomHands hands(options, ImVec2(1280.0f, 800.0f));
  const classroom_state::MysteryValues truth = classroom_state::mystery_values(window_seed);
  Classroom& window = hands.classroom();
  if (GetParam() == Theory::predictions_revealed) {
    window.key_pressed(Key::t, false);  // the teacher reveals the theory: the mystery's stays hidden
    hands.frame();
    // Where the class's predictions stand beside the theory: "Predict" before the reveal and after,
    // when they share the tabs (here they may have a panel of their own, planned for the answers).
    if (hands.texts().find("Predict###theory tab") != std::string::npos) hands.click_text("Predict###theory tab");
  }
  // The lesson runs with the drawn values...
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, truth.mu_s);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, truth.mu_k);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_s, truth.mu_s);
  // ...which no panel shows, at the start or after stick-slip has begun.
  for (const double t : {0.0, 3.0}) {
    window.playback().run_to(t);
    const std::string texts = hands.texts();
    EXPECT_FALSE(mentions(texts, truth.mu_s)) << "at t = " << t << ":\n" << texts;
    EXPECT_FALSE(mentions(texts, truth.mu_k)) << "at t = " << t << ":\n" << texts;
    // Nor any value the theory works out from them (a breakaway force is μs·m·g), as the table
    // writes it; a row whose measurement reads the same is left out, since the run may show that.
    window.playback().refresh_readings();
    for (const lessons::ExpectationResult& row : window.playback().readings().expectations) {
      if (!row.numeric) continue;
      const std::string predicted = draw::format_quantity(row.predicted, row.unit.c_str());
      if (row.measured_yet && draw::format_quantity(row.measured, row.unit.c_str()) == predicted) continue;
      EXPECT_EQ(texts.find(predicted), std::string::npos) << row.name << " " << predicted << " at t = " << t << ":\n" << texts;
    }
    if (GetParam() != Theory::predict_first) {
      EXPECT_NE(texts.find("hidden"), std::string::npos) << "the theory's values are hidden:\n" << texts;
    }
    // With predictions asked the Predict (or Theory) tab is in front, the Mystery tab a click away.
    if (GetParam() == Theory::table) {
      EXPECT_NE(texts.find("Measure \u03bcs and \u03bck of the mystery aluminium/wood surface"), std::string::npos) << texts;
    }
  }
  if (GetParam() != Theory::table) {
    hands.click_text("Mystery###mystery");
    const std::string tab = hands.texts();
    EXPECT_NE(tab.find("Measure \u03bcs and \u03bck of the mystery aluminium/wood surface"), std::string::npos) << tab;
    EXPECT_FALSE(mentions(tab, truth.mu_s) || mentions(tab, truth.mu_k)) << tab;
  }
  EXPECT_FALSE(window.control("mu_s slider").has_value()) << "no slider to read the value off";
  EXPECT_FALSE(window.control("mu_k value").has_value());
  EXPECT_FALSE(window.control("mu_s presets").has_value());
  // The export's settings file, beside it, says which values made the run: a mystery's are "?".
  const std::string settings = read_file(lessons::settings_path_for(window.export_history()));
  EXPECT_FALSE(mentions(settings, truth.mu_s)) << settings;
  EXPECT_NE(settings.find("\nmu_s = ? (a mystery)\n"), std::string::npos) << settings;
  EXPECT_FALSE(mentions(window.window_title(), truth.mu_s) || mentions(window.window_title(), truth.mu_k));
  EXPECT_NE(window.window_title().find("mystery"), std::string::npos) << window.window_title();

  hands.click("mystery reveal");
  ASSERT_TRUE(window.mystery()->revealed());
  const std::string revealed = hands.texts();
  EXPECT_TRUE(mentions(revealed, truth.mu_s)) << revealed;
  EXPECT_TRUE(mentions(revealed, truth.mu_k)) << revealed;
  EXPECT_TRUE(window.control("mu_s slider").has_value()) << "the sliders come back";
  const std::string after = read_file(lessons::settings_path_for(window.export_history()));
  EXPECT_NE(after.find("\nmu_s = " + validation::exact_text(truth.mu_s) + "\n"), std::string::npos) << after;
  EXPECT_NE(after.find("\nmu_k = " + validation::exact_text(truth.mu_k) + "\n"), std::string::npos) << after;
  EXPECT_NE(window.window_title().find("revealed"), std::string::npos) << window.window_title();
}

std::string theory_name(const ::testing::TestParamInfo<Theory>& theory) {
  return theory.param == Theory::table ? "TheoryTable" : theory.param == Theory::predict_first ? "PredictFirst" : "PredictionsRevealed";
}

INSTANTIATE_TEST_SUITE_P(Theory, MysteryHidden,
                         ::testing::Values(Theory::table, Theory::predict_first, Theory::predictions_revealed), theory_name);

// A lesson's run lasts until what it teaches has been seen: push's, until a while after the
// breakaway at μs·m·g. Its time axis drawn before Play gave a mystery's μs away (seed 427's axis
// ran to 10.1 s: μs = 0.88). Until the reveal every plot's time axis grows with the run instead,
// the same whatever the hidden values; after the reveal it spans the run again.
TEST(MysteryWindow, NoTimeAxisTellsTheRunsLengthBeforeTheReveal) {
  const auto time_axes = [](std::uint64_t seed, double t, bool reveal) {
    ClassroomOptions options = mystery_options("push", "wood/wood", seed);
    options.window.predictions = false;
    ClassroomHands hands(options);
    hands.classroom().playback().run_to(t);
    if (reveal) hands.classroom().reveal_mystery();
    draw::FrameRecord record;
    hands.frame(0.0, &record);
    std::vector<double> ends;
    for (const draw::FrameRecord::Plot& plot : record.plots) {
      if (plot.number == 1) ends.push_back(plot.layout.x_high);  // "Push and friction", over time
    }
    EXPECT_EQ(ends.size(), 1u);
    return ends;
  };
  // Seeds 1 and 2 draw μs that make runs of different lengths (the last line checks it).
  for (const double t : {0.0, 1.5}) {
    EXPECT_EQ(time_axes(1, t, false), time_axes(2, t, false)) << "at t = " << t;
  }
  EXPECT_NE(time_axes(1, 0.0, true), time_axes(2, 0.0, true)) << "revealed, each axis spans its own run";
}

TEST(MysteryWindow, TypedAnswersAreJudgedAndABadOneSaysWhy) {
  ClassroomHands hands(mystery_options("spring_pull", "aluminium/wood", window_seed));
  const classroom_state::MysteryValues truth = classroom_state::mystery_values(window_seed);
  hands.texts();
  // The class predicts first (the Predict tab is in front); then it measures, in the Mystery tab.
  hands.click_text("Mystery###mystery");
  hands.click("mystery answer mu_s");
  hands.type("0.5");
  hands.press_enter();
  const std::optional<classroom_state::Mystery>& mystery = hands.classroom().mystery();
  ASSERT_TRUE(mystery->answer_mu_s.has_value());
  EXPECT_EQ(*mystery->answer_mu_s, 0.5);
  char expected[32];
  std::snprintf(expected, sizeof expected, "%.1f %% off", 100.0 * std::abs(0.5 - truth.mu_s) / truth.mu_s);
  std::string texts = hands.texts();
  // How far off waits for the reveal: two guesses and their closeness would give the value away.
  EXPECT_EQ(texts.find("% off"), std::string::npos) << texts;
  EXPECT_NE(texts.find("kept for the reveal"), std::string::npos) << texts;
  EXPECT_NE(texts.find("not yet"), std::string::npos) << "μk is still to come:\n" << texts;

  hands.click("mystery answer mu_k");
  hands.type("3");
  hands.press_enter();
  EXPECT_FALSE(mystery->answer_mu_k.has_value());
  texts = hands.texts();
  EXPECT_NE(texts.find("type a number from 0 to 2"), std::string::npos) << texts;
  EXPECT_FALSE(mystery->revealed()) << "answering reveals nothing";
  hands.classroom().reveal_mystery();
  texts = hands.texts();
  EXPECT_NE(texts.find(expected), std::string::npos) << expected << " in\n" << texts;
}

TEST(MysteryWindow, TheMenuMakesAPairAMysteryAtTheStartOfAFreshRun) {
  ClassroomOptions options;
  options.lesson = "incline";
  ClassroomHands hands(options);
  Classroom& window = hands.classroom();
  window.playback().run_to(0.5);
  EXPECT_NE(window.make_mystery({"slope/fish", 7}), "");
  EXPECT_FALSE(window.mystery().has_value()) << "a refused pair changes nothing";
  EXPECT_EQ(window.make_mystery({"slope/block", 7}), "");
  const classroom_state::MysteryValues truth = classroom_state::mystery_values(7);
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, truth.mu_s);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, truth.mu_k);
  EXPECT_EQ(hands.lesson().scene().frame(), 0) << "a new surface starts a new run";
  const std::string texts = hands.texts();
  EXPECT_FALSE(mentions(texts, truth.mu_s)) << texts;
  EXPECT_FALSE(mentions(texts, truth.mu_k)) << texts;
  // Opening another lesson ends it: the mystery was a pair of the lesson that closed.
  EXPECT_EQ(window.open("spring_pull"), "");
  EXPECT_FALSE(window.mystery().has_value());
}

// Under the teacher's lock the class cannot draw a new mystery in place of the one prepared:
// the menu's pairs are greyed and say why; the teacher's reveal is still there. (The trial's
// locked setup let the menu replace its mystery.)
TEST(MysteryWindow, UnderALockTheMenuDrawsNoNewMysteryButStillReveals) {
  ClassroomOptions options;
  options.lesson = "incline";
  options.lock = {"angle", "mass"};
  options.mystery = classroom_state::MysteryChoice{"slope/block", 42};
  ClassroomHands hands(options);
  Classroom& window = hands.classroom();
  const classroom_state::MysteryValues truth = classroom_state::mystery_values(42);
  hands.frame();
  hands.click("Mystery menu");
  hands.click("mystery block/slope");
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, truth.mu_s) << "the prepared mystery stays";
  EXPECT_EQ(window.mystery()->choice().seed, 42u);
  hands.click("Mystery menu");
  EXPECT_NE(hands.texts().find("Locked by --lock"), std::string::npos) << "the menu says why";
  hands.click("mystery reveal menu");
  EXPECT_TRUE(window.mystery()->revealed()) << "the teacher still reveals it";
}

TEST(MysteryWindow, APairTheLessonDoesNotHaveIsRefusedWithItsPairs) {
  try {
    ClassroomHands hands(mystery_options("spring_pull", "rubber/ice", 1));
    ADD_FAILURE() << "rubber/ice was taken";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("--mystery rubber/ice: "), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("its pairs: aluminium/wood"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace frictionlab::classroom

namespace frictionlab::classroom {
namespace {

// A value that rebuilds the lesson keeps the mystery's values; one that would take its pair away
// (the block's material in spring_pull) is refused while the mystery lasts, and says why.
TEST(MysteryWindow, ARebuildKeepsTheValuesAndThePairCannotBeChangedAway) {
  ClassroomOptions options = mystery_options("spring_pull", "aluminium/wood", window_seed);
  ClassroomHands hands(options);
  const classroom_state::MysteryValues truth = classroom_state::mystery_values(window_seed);
  hands.texts();
  hands.click("block slider");
  hands.frame();
  hands.click("block choice plastic");
  hands.frame();
  EXPECT_EQ(hands.lesson().parameter("block").shown(), "aluminium") << "the pair stays aluminium on wood";
  EXPECT_NE(hands.classroom().control_error("block").find("The mystery is aluminium/wood"), std::string::npos)
      << hands.classroom().control_error("block");
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, truth.mu_s);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_s, truth.mu_s);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_k, truth.mu_k);
  // A value that rebuilds the scene (the mass, read while it is built) keeps the drawn values.
  hands.classroom().playback().run_to(1.0);
  // The refusal's message lies over the rows under the block's, the mass's among them: a click
  // on it only takes it away (it set what it covered), and the next click sets the mass.
  const ImRect mass = hands.control("mass slider");
  for (int click = 0; click < 2; ++click) {
    ImGui::GetIO().MousePos = ImVec2(mass.Min.x + 0.7f * mass.GetWidth(), mass.GetCenter().y);
    hands.frame();
    ImGui::GetIO().MouseDown[0] = true;
    hands.frame();
    ImGui::GetIO().MouseDown[0] = false;
    hands.frame();
  }
  EXPECT_EQ(hands.classroom().control_error("block"), "") << "the refusal outlived a click";
  EXPECT_NE(hands.lesson().parameter("mass").value, 1.0) << "the click set the mass";
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, truth.mu_s);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, truth.mu_k);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_s, truth.mu_s);
}

}  // namespace
}  // namespace frictionlab::classroom

namespace frictionlab::classroom {
namespace {

// In projector mode the column shows only the first lines of a tab before it scrolls: both
// answers and the reveal are there, where a hand clicks them.
TEST(MysteryWindow, TheAnswersAndTheRevealAreInSightInProjectorMode) {
  ClassroomOptions options = mystery_options("spring_pull", "aluminium/wood", window_seed);
  options.window.projector = true;
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  hands.classroom().playback().run_to(3.0);
  hands.texts();
  hands.click_text("Mystery###mystery");  // the Predict tab was in front
  hands.click("mystery answer mu_s");
  hands.type("0.55");
  hands.press_enter();
  hands.click("mystery answer mu_k");
  hands.type("0.5");
  hands.press_enter();
  EXPECT_EQ(hands.classroom().mystery()->answer_mu_s, 0.55);
  EXPECT_EQ(hands.classroom().mystery()->answer_mu_k, 0.5);
  hands.click("mystery reveal");
  EXPECT_TRUE(hands.classroom().mystery()->revealed()) << "the click found the button";
  EXPECT_NEAR(hands.lesson().scene().time(), 3.0, 1e-9) << "and nothing under it (the time bar) instead";
}

// The reveal keeps its place while the class's answers are typed, a wrong one refused, and
// corrected: it stood after the μk line's word, and moved right as "not yet" became "kept for
// the reveal", so a teacher's click aimed at it landed on the text (the projector trial).
TEST(MysteryWindow, TheRevealKeepsItsPlaceWhileAnswersAreTyped) {
  for (const bool projector : {false, true}) {
    ClassroomOptions options = mystery_options("push", classroom_state::mystery_pairs(lessons::Lesson(lessons::resolve_lesson("push"))).at(0), window_seed);
    options.window.projector = projector;
    ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
    hands.texts();
    hands.click_text("Mystery###mystery");
    const std::optional<ImRect> first = hands.classroom().control("mystery reveal");
    ASSERT_TRUE(first.has_value()) << "projector " << projector;
    const auto same_place = [&](const char* after) {
      hands.texts();
      const std::optional<ImRect> now = hands.classroom().control("mystery reveal");
      ASSERT_TRUE(now.has_value()) << after;
      EXPECT_EQ(now->Min.x, first->Min.x) << after << ", projector " << projector;
      EXPECT_EQ(now->Min.y, first->Min.y) << after << ", projector " << projector;
    };
    hands.click("mystery answer mu_k");
    hands.type("7");
    hands.press_enter();
    same_place("a μk of 7 refused");
    hands.click("mystery answer mu_k");
    hands.press(ImGuiKey_Backspace);  // the 7
    hands.type("0.3");
    hands.press_enter();
    ASSERT_EQ(hands.classroom().mystery()->answer_mu_k, 0.3);
    same_place("μk answered");
    hands.click("mystery answer mu_s");
    hands.type("0.5");
    hands.press_enter();
    same_place("both answered");
  }
}

// The Stability map tab gives way to the Mystery tab while the mystery's μs is hidden (the map's
// boundary would give it away) and comes back at the reveal, with the map for the μs the class
// has just been told (issue 31: it stayed away), beside the others, which do not move. In
// projector mode six tabs do not fit the column side by side: there the Mystery tab keeps its
// place and the map stays away, rather than every tab shrinking and moving at the reveal. With
// predictions asked first or not: every tab's name whole.
TEST(MysteryWindow, TheStabilityMapTabComesBackAtTheRevealWhereItFits) {
  const std::string pair = classroom_state::mystery_pairs(lessons::Lesson(lessons::resolve_lesson("incline"))).at(0);
  struct Screen {
    const char* name;
    ImVec2 size;
    bool projector;
  };
  for (const Screen& screen : {Screen{"window 1920x1080", ImVec2(1920.0f, 1080.0f), false},
                               Screen{"window 1280x720", ImVec2(1280.0f, 720.0f), false},
                               Screen{"projector 1920x1080", ImVec2(1920.0f, 1080.0f), true}}) {
    for (const bool predictions : {false, true}) {
      const std::string where = std::string(screen.name) + (predictions ? ", predictions asked" : "");
      ClassroomOptions options = mystery_options("incline", pair, window_seed);
      options.window.projector = screen.projector;
      options.window.predictions = predictions;
      ClassroomHands hands(options, screen.size);
      hands.texts();
      EXPECT_FALSE(hands.classroom().control("Stability map tab").has_value()) << where << ": the map would tell μs";
      const ImRect mystery_tab = hands.control("Mystery tab");
      hands.classroom().reveal_mystery();
      hands.texts();
      const ImRect revealed_tab = hands.control("Mystery tab");
      EXPECT_EQ(revealed_tab.Min.x, mystery_tab.Min.x) << where << ": the Mystery tab moved at the reveal";
      EXPECT_EQ(revealed_tab.Max.x, mystery_tab.Max.x) << where << ": the Mystery tab moved at the reveal";
      EXPECT_EQ(hands.classroom().control("Stability map tab").has_value(), !screen.projector) << where;
      if (!screen.projector) {
        hands.click("Stability map tab");
        EXPECT_FALSE(hands.classroom().stability_map_tab().chart.cells.empty()) << where << ": no map for the revealed μs";
      }
      draw::FrameRecord record;
      hands.frame(0.0, &record);
      for (const draw::ShownText& text : record.texts) {
        if (text.text.find("###") == std::string::npos) continue;  // a tab's name, with its id
        EXPECT_TRUE(text.whole_across()) << where << ": the tab " << text.text << " is cut";
      }
    }
  }
}

}  // namespace
}  // namespace frictionlab::classroom
