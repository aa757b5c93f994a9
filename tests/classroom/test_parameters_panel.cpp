// The Parameters panel driven as a teacher drives it: sliders dragged and typed into, presets,
// a pair folded into its heading, the teacher's lock, and the column kept still as the run goes.
#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>

#include "classroom/classroom.h"
#include "draw/headless.h"
#include "draw/imgui_host.h"
#include "draw/overlays.h"
#include "lessons/runtime/catalog.h"
#include "tests/classroom_hands.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::classroom {
namespace {

using lessons::replaced;
using lessons::ScriptFile;

double first_slip_time(const Scene& scene) {
  for (std::size_t i = 0; i < scene.slipping().size(); ++i) {
    if (scene.slipping()[i]) return scene.times()[i];
  }
  return -1.0;
}

TEST(ParametersPanel, MovingTheStaticSliderChangesThePairTableAndWhenTheBlockBreaksAway) {
  ClassroomHands hands("spring_pull");
  hands.frame();
  ASSERT_FALSE(hands.playback().playing());  // it opens paused
  // Half-way along the slider's range [0, 2] is mu_s = 1.
  const ImRect slider = hands.control("mu_s slider");
  hands.click(ImVec2(slider.Min.x + 0.5f * slider.GetWidth(), slider.GetCenter().y));
  const double mu_s = hands.lesson().parameter("mu_s").value;
  EXPECT_NEAR(mu_s, 1.0, 0.03);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_s, mu_s);
  // The spring pulls k·v·t: the block breaks away at t = mu_s·m·g/(k·v) = 1.96 s for mu_s = 1
  // (0.88 s at the script's 0.45). Within two steps of 1/240 s and the slider's resolution.
  hands.playback().run_to(2.5);
  const double breakaway = mu_s * 1.0 * 9.81 / (50.0 * 0.1);
  EXPECT_NEAR(first_slip_time(hands.lesson().scene()), breakaway, 2.0 / 240.0 + 1e-9);
}

// A teacher's trial could not set push's mass to 1 kg by dragging (0.1 to 10 kg, a few hundredths
// a pixel, 0.98 then 1.02): a click anywhere along the slider sets a round value, one of two
// decimals at most, here at eleven places from end to end, and the lesson is built with it.
TEST(ParametersPanel, TheMassSliderSetsRoundValues) {
  ClassroomHands hands("push");
  hands.frame();
  for (int place = 0; place <= 10; ++place) {
    const ImRect slider = hands.control("mass slider");
    hands.click(ImVec2(slider.Min.x + 2.0f + (slider.GetWidth() - 4.0f) * static_cast<float>(place) / 10.0f + 0.37f,
                       slider.GetCenter().y));
    hands.frame();
    const double mass = hands.lesson().parameter("mass").value;
    EXPECT_EQ(std::round(mass * 100.0) / 100.0, mass) << "at place " << place << " of 10";
    const b2Body* block = hands.lesson().scene().body("block");
    ASSERT_NE(block, nullptr);
    EXPECT_NEAR(block->GetMass(), mass, 1e-5 * mass) << "at place " << place << " of 10";
  }
}

TEST(ParametersPanel, ATypedValueIsSetExactlyAndARefusedOneSaysWhy) {
  ClassroomHands hands("spring_pull");
  hands.frame();
  hands.click("mu_k value");
  hands.type("0.3125");
  hands.press(ImGuiKey_Enter);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.3125);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_k, 0.3125);

  hands.click("mu_k value");
  hands.type("0,5");
  hands.press(ImGuiKey_Enter);
  EXPECT_NE(hands.classroom().control_error("mu_k").find("write decimals with a point"), std::string::npos);
  hands.click("mu_k value");
  hands.type("3");
  hands.press(ImGuiKey_Enter);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.3125);
  EXPECT_NE(hands.classroom().control_error("mu_k").find("outside the allowed range [0, 2]"), std::string::npos)
      << hands.classroom().control_error("mu_k");
  // Named as its row names it (a teacher's trial read the script's "push_height" there).
  EXPECT_EQ(hands.classroom().control_error("mu_k").rfind("\u03bck kinetic = 3 ", 0), 0u) << hands.classroom().control_error("mu_k");

  // The reset button puts the script's value back, and the message goes with the mistake (it
  // stands over the rows under the box, and moves nothing: StableLayout in test_projector).
  hands.frame();
  hands.click("mu_k reset");
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.35);
  EXPECT_EQ(hands.classroom().control_error("mu_k"), "");
}

TEST(ParametersPanel, ChangingAValueMidRunSaysTheMeasurementsMixTwoRunsUntilReset) {
  ClassroomHands hands("spring_pull");
  hands.frame();
  hands.playback().run_to(1.2);
  EXPECT_EQ(hands.playback().readings().caveat, "");
  hands.playback().set_parameter("mu_s", "0.6");
  // In the books' letters, with the pair.
  EXPECT_EQ(hands.playback().readings().caveat.rfind("\u03bcs  aluminium / wood was changed at t = 1.20 s", 0), 0u)
      << hands.playback().readings().caveat;
  hands.key(Key::r);
  EXPECT_EQ(hands.playback().readings().caveat, "");
  // A change before anything was measured mixes nothing, and says nothing.
  hands.playback().set_parameter("mu_k", "0.3");
  EXPECT_EQ(hands.playback().readings().caveat, "");
}

TEST(ParametersPanel, TheTeachersLockShowsOnlyTheNamedControls) {
  ClassroomHands hands("spring_pull", {"mu_s", "mu_k"});
  hands.frame();
  EXPECT_TRUE(hands.classroom().control("mu_s slider").has_value());
  EXPECT_TRUE(hands.classroom().control("mu_k value").has_value());
  EXPECT_TRUE(hands.classroom().control("mu_s presets").has_value());
  EXPECT_FALSE(hands.classroom().control("mass slider").has_value());
  EXPECT_FALSE(hands.classroom().control("c slider").has_value());
  ClassroomOptions options;
  options.lesson = lessons::resolve_lesson("spring_pull");
  options.lock = {"mu_s", "mus"};
  EXPECT_NE(lessons::error_of([&] { Classroom classroom(options); }).find("--lock mus: "), std::string::npos);
}

TEST(ParametersPanel, APresetSetsBothCoefficientsOfThePair) {
  ClassroomHands hands("spring_pull");
  hands.frame();
  const ImRect box = hands.control("mu_s presets");
  hands.click(box.GetCenter());
  // The list opens under its box, one line per pair in the seed tables' order; the first is
  // metal on metal (mu_s 0.18, mu_k 0.14). Its middle is half a line below the box.
  hands.click(ImVec2(box.GetCenter().x, box.Max.y + 0.5f * ImGui::GetTextLineHeightWithSpacing() + 2.0f));
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, 0.18);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.14);
  EXPECT_EQ(hands.lesson().scene().pairs().pair("aluminium", "wood").mu_k, 0.14);
}

TEST(ParametersPanel, APairsArrowFoldsItsSlidersIntoItsHeadingAndOpensThemAgain) {
  ClassroomHands hands("spring_pull");
  hands.frame();
  ASSERT_TRUE(hands.classroom().control("mu_s slider").has_value());
  hands.click("aluminium on wood fold");
  hands.frame();
  EXPECT_FALSE(hands.classroom().control("mu_s slider").has_value());
  EXPECT_FALSE(hands.classroom().control("mu_k value").has_value());
  EXPECT_TRUE(hands.classroom().control("mass slider").has_value());
  hands.click("aluminium on wood fold");
  hands.frame();
  EXPECT_TRUE(hands.classroom().control("mu_s slider").has_value());
  EXPECT_TRUE(hands.classroom().control("mu_k value").has_value());
}

TEST(ParametersPanel, InProjectorModeAPairsSlidersGoTwoARowAndCtrlClickTypesAValue) {
  ClassroomHands hands("spring_pull");
  hands.classroom().window_settings().projector = true;
  hands.set_display(ImVec2(1920.0f, 1080.0f));
  hands.playback().run_to(2.5);
  hands.frame();
  // With its table measured, spring_pull's column holds its four controls, the pair's heading
  // and the theory tab only with the pair's four coefficients two a row. Where the table's rows
  // leave no room for them the layout folds the pair; the teacher opens it, and it goes two a row.
  // (With the class's predictions asked, the whole panel is folded for their answers from the
  // lesson's opening: the teacher opens it first.)
  if (hands.classroom().control("parameters open")) {
    hands.click("parameters open");
    hands.frame();
  }
  if (!hands.classroom().control("mu_s slider")) {
    hands.click("aluminium on wood fold");
    hands.frame();
  }
  const ImRect mu_s = hands.control("mu_s slider"), mu_k = hands.control("mu_k slider");
  EXPECT_EQ(mu_s.Min.y, mu_k.Min.y);
  EXPECT_LT(mu_s.Max.x, mu_k.Min.x);
  EXPECT_FALSE(hands.classroom().control("mu_s value").has_value());
  EXPECT_TRUE(hands.classroom().control("mass value").has_value());
  ImGui::GetIO().KeyCtrl = true;
  hands.click(mu_s.GetCenter());
  ImGui::GetIO().KeyCtrl = false;
  // The slider's text box opens with its value selected: typing replaces it.
  hands.type("0.3");
  hands.press(ImGuiKey_Enter);
  hands.frame();
  EXPECT_EQ(hands.lesson().parameter("mu_s").value, 0.3);
}

TEST(ParametersPanel, AUnitWithAPercentSignIsShownAsText) {
  // A student's unit with a % in it ("%s" would make a format read a string that is not there).
  ScriptFile script(replaced(read_file(lessons::resolve_lesson("push")), "unit = \"kg\"", "unit = \"%s\""));
  ClassroomHands hands(script.path());
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, ImVec2(0.0f, 0.0f), &record);
  bool shown = false;
  for (const draw::ShownText& text : record.texts) shown = shown || text.text == "1 %s";
  EXPECT_TRUE(shown) << "the mass slider should read 1 %s";
}

// A teacher's trial: a first window in projector mode opened tipping_box with the help panel,
// whose strip took the room the sliders needed (the panel folded for the class's answers, so no
// push height, width or μs in sight while the class was asked whether the box tips), and the
// help's last line cut. The first window in projector mode is for the class: no help panel.
TEST(ParametersPanel, AFirstWindowInProjectorModeOpensWithoutTheHelpAndWithTippingBoxsSlidersInSight) {
  EXPECT_FALSE(opens_with_help(true, /*first_window=*/true, /*projector=*/true, /*picture=*/false));
  EXPECT_FALSE(opens_with_help(true, true, false, /*picture=*/true));
  EXPECT_TRUE(opens_with_help(true, true, false, false)) << "a newcomer at a window sees the shortcuts";
  EXPECT_TRUE(opens_with_help(true, false, true, false)) << "the teacher's own choice, kept, comes back";
  EXPECT_FALSE(opens_with_help(false, false, false, false));
  const auto opened_with_help = [](bool help) {
    ClassroomHands hands("tipping_box");
    hands.classroom().window_settings().projector = true;
    hands.classroom().window_settings().help = help;
    hands.set_display(ImVec2(1920.0f, 1080.0f));
    hands.frame();
    return hands.classroom().control("parameters open").has_value();
  };
  EXPECT_FALSE(opened_with_help(opens_with_help(true, true, true, false))) << "tipping_box's sliders folded";
  // (What the trial saw: with the help's strip, the answers need the sliders' room.)
  EXPECT_TRUE(opened_with_help(true)) << "the help's strip leaves room for both: the first test shows nothing";
}

// Issue 31: the Parameters panel folded into its heading as the run ended (to leave the class's
// answers their room) and unfolded at R, moving the tabs under the teacher's pointer. Whether it
// folds is decided as the lesson opens, for the answers at their tallest, and kept through the
// run, its end and R; a click on its arrow opens it for the rest of the lesson. Every built-in
// lesson has room for both at 1920×1080 in projector mode, so the lesson here is tipping_box
// with its two questions in a teacher's longer words: no room for both, folded from the opening.
TEST(ParametersPanel, TheParametersFoldForTheAnswersFromTheOpeningNeverAsTheRunEndsAndOpenOnAClick) {
  const std::filesystem::path folder = std::filesystem::path(testing::TempDir()) / "fold_for_the_answers";
  std::filesystem::create_directories(folder);
  const std::filesystem::path script = folder / "tipping_box_longer_questions.lua";
  {
    std::ifstream original(lessons::resolve_lesson("tipping_box"));
    std::string text((std::istreambuf_iterator<char>(original)), std::istreambuf_iterator<char>());
    const std::string longer =
        " Think of a tall bookcase pushed along a carpet: talk it over with the person beside you, write"
        " your answer down, and be ready to say why before the run starts.";
    std::size_t asked = 0;
    for (const std::string question : {"does the box tip over or slide along the floor?",
                                       "when the box starts to tip or slide?"}) {
      const std::size_t at = text.find(question);
      if (at == std::string::npos) continue;
      text.insert(at + question.size(), longer);
      ++asked;
    }
    ASSERT_EQ(asked, 2u) << "tipping_box's questions were reworded: find its two questions anew";
    std::ofstream(script) << text;
  }
  {
  ClassroomHands hands(script.string());
  hands.classroom().window_settings().projector = true;
  hands.set_display(ImVec2(1920.0f, 1080.0f));
  hands.frame();
  ASSERT_TRUE(hands.classroom().theory_hidden());
  const auto folded = [&] { return hands.classroom().control("parameters open").has_value(); };
  const auto slider = [&] { return hands.classroom().control("push_height slider").has_value(); };
  EXPECT_TRUE(folded()) << "the answers need the room from the lesson's opening";
  EXPECT_FALSE(slider());
  hands.playback().run_to(hands.lesson().duration());
  hands.frame();
  hands.frame();
  EXPECT_TRUE(folded()) << "the same at the run's end";
  hands.click("parameters open");
  hands.frame();
  EXPECT_FALSE(folded()) << "opened by the teacher";
  EXPECT_TRUE(slider());
  EXPECT_TRUE(hands.classroom().theory_hidden()) << "opening the sliders reveals nothing";
  // Back to t = 0 and played again: as the teacher left it.
  hands.key(Key::r);
  EXPECT_FALSE(folded());
  hands.playback().run_to(hands.lesson().duration());
  hands.frame();
  hands.frame();
  EXPECT_FALSE(folded()) << "the run's end folded the panel the teacher opened";
  EXPECT_TRUE(slider());
  }
  // A lesson with room for both keeps its sliders, at the opening and at the run's end alike.
  ClassroomHands incline("incline");
  incline.classroom().window_settings().projector = true;
  incline.set_display(ImVec2(1920.0f, 1080.0f));
  incline.frame();
  EXPECT_FALSE(incline.classroom().control("parameters open").has_value());
  incline.playback().run_to(incline.lesson().duration());
  incline.frame();
  incline.frame();
  EXPECT_FALSE(incline.classroom().control("parameters open").has_value()) << "incline's sliders folded as the run ended";
  std::filesystem::remove_all(folder);
}

// A slider let go keeps the column as the lesson opened with: at stacked_blocks' slowest pull its
// answers say "measured: runs off the floor first", a line longer, and a plan worked out anew
// folded the Parameters panel, the slider and its tabs under the teacher's pointer.
TEST(ParametersPanel, ASliderLetGoKeepsTheColumnAsTheLessonOpened) {
  ClassroomHands hands("stacked_blocks");
  hands.classroom().window_settings().projector = true;
  hands.set_display(ImVec2(1920.0f, 1080.0f));
  hands.frame();
  hands.frame();
  ASSERT_TRUE(hands.classroom().control("pull_rate slider").has_value()) << "stacked_blocks opens with its sliders";
  const ImRect slider = *hands.classroom().control("pull_rate slider");
  for (const double pull_rate : {0.5, 20.0, 5.0}) {
    hands.playback().set_parameter("pull_rate", pull_rate);
    hands.frame();
    hands.frame();
    EXPECT_FALSE(hands.classroom().control("parameters open").has_value()) << "pull_rate " << pull_rate << ": folded";
    const std::optional<ImRect> now = hands.classroom().control("pull_rate slider");
    ASSERT_TRUE(now.has_value()) << "pull_rate " << pull_rate << ": the slider went";
    EXPECT_TRUE(now->Min.x == slider.Min.x && now->Min.y == slider.Min.y && now->Max.x == slider.Max.x &&
                now->Max.y == slider.Max.y)
        << "pull_rate " << pull_rate << ": the slider moved";
  }
}

}  // namespace
}  // namespace frictionlab::classroom
