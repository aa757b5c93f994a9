// Predict first's panel (classroom/prediction_panel.h) in the window: the column planned for the
// class's answers is kept from a lesson's opening (a slider's value does not move it), and
// planned anew when the script is read again or a setup opens, whose questions may read
// otherwise: the answers then have the room they need, with no scroll bar.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "classroom/prediction_panel.h"
#include "tests/classroom_hands.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::classroom {
namespace {

const std::string breakaway_question = "The push grows steadily. How hard is it when the block starts to move?";

// push.lua as it is, or with its first question three sentences longer: lines more at any width.
std::string push_script(bool long_question) {
  std::ifstream file(lessons::resolve_lesson("push"));
  std::stringstream text;
  text << file.rdbuf();
  std::string script = text.str();
  const std::size_t at = script.find(breakaway_question);
  EXPECT_NE(at, std::string::npos) << "push.lua's question changed; this test lengthens it";
  if (long_question && at != std::string::npos) {
    script.insert(at + breakaway_question.size(),
                  " Watch the force gauge, not the block: the block may not seem to move at first. Say the number of"
                  " newtons you expect on the gauge at that moment. Then say whether it will slide faster and faster.");
  }
  return script;
}

// The class's answers as the window shows them: every text of the panel that asks the first
// question, and whether any of it is cut or a scroll away.
struct AnswersShown {
  bool asked = false;     // the question was drawn
  bool scrolls = false;   // its panel has a scroll bar
  bool whole = true;      // every text of it whole
};

AnswersShown answers_shown(ClassroomHands& hands, const std::string& question_start) {
  hands.frame();
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, &record);
  AnswersShown shown;
  std::string panel;
  for (const draw::ShownText& text : record.texts) {
    if (text.text.rfind(question_start, 0) == 0) panel = text.panel;
  }
  for (const draw::ShownText& text : record.texts) {
    if (panel.empty() || text.panel != panel) continue;
    shown.asked = true;
    shown.scrolls = shown.scrolls || text.scrolls;
    shown.whole = shown.whole && text.whole();
  }
  return shown;
}

// F5 after the student lengthened a question: planned for the question as it now reads. (Before,
// the column kept the height planned for the short question, and the answers scrolled.)
// Near the line between two words a row says both (push's "smaller or the same": the world's
// breakaway and friction within their tolerances of a difference that either word may take): a
// class that chose either is right; the third word is not, and a plain word takes itself alone.
TEST(PredictionPanel, AChoiceOneOfTheTwoWordsOfARowNearTheirLineIsRight) {
  lessons::Prediction sliding{"sliding vs breakaway", "Smaller, the same or larger?", "", {"smaller", "the same", "larger"},
                              "push.lua:1"};
  lessons::ExpectationResult row;
  row.name = "sliding vs breakaway";
  row.numeric = false;
  row.predicted_text = "smaller or the same";
  row.measured_text = "smaller or the same";
  row.measured_yet = true;
  EXPECT_TRUE(closeness(sliding, "smaller", row).close);
  EXPECT_TRUE(closeness(sliding, "the same", row).close);
  const Closeness larger = closeness(sliding, "larger", row);
  EXPECT_FALSE(larger.close);
  EXPECT_NE(larger.words.find("the run says smaller or the same"), std::string::npos) << larger.words;
  row.measured_text = "the same";
  EXPECT_TRUE(closeness(sliding, "the same", row).close);
  EXPECT_FALSE(closeness(sliding, "smaller", row).close);
}

TEST(PredictionPanel, TheAnswersArePlannedAnewWhenTheScriptIsReloaded) {
  const lessons::ScriptFile script(push_script(false));
  ClassroomOptions options;  // predictions asked, as by default
  options.lesson = script.path();
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  const AnswersShown before = answers_shown(hands, breakaway_question);
  ASSERT_TRUE(before.asked);
  EXPECT_FALSE(before.scrolls);
  script.rewrite(push_script(true));
  hands.key(Key::f5);
  ASSERT_EQ(hands.classroom().playback().script_error(), "");
  const AnswersShown after = answers_shown(hands, breakaway_question + " Watch the force gauge");
  ASSERT_TRUE(after.asked) << "the reloaded question is not shown";
  EXPECT_FALSE(after.scrolls) << "the answers scroll in a column planned for the script before F5";
  EXPECT_TRUE(after.whole);
}

// A setup of the same script, opened after the script was lengthened: planned for it too.
TEST(PredictionPanel, TheAnswersArePlannedAnewWhenASetupOpens) {
  const lessons::ScriptFile script(push_script(false));
  ClassroomOptions options;  // predictions asked, as by default
  options.lesson = script.path();
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  ASSERT_TRUE(answers_shown(hands, breakaway_question).asked);
  const std::string setup = hands.folder() + "/long.setup";
  std::ofstream(setup) << "# FrictionLab setup\nlesson " << script.path() << "\npredictions on\n";
  script.rewrite(push_script(true));
  ASSERT_EQ(hands.classroom().open_setup(setup), "");
  const AnswersShown after = answers_shown(hands, breakaway_question + " Watch the force gauge");
  ASSERT_TRUE(after.asked) << "the setup's lesson does not ask the lengthened question";
  EXPECT_FALSE(after.scrolls) << "the answers scroll in a column planned for the lesson before the setup";
  EXPECT_TRUE(after.whole);
}

// Issue 31, a teacher's trial: "measured: 3.92 N" showed beside the empty answer box mid-run,
// before the class had answered: it is the answer. Beside an empty box the measurement waits
// for the class's answer (typed at t = 0: R); beside an answer it shows as the run measures it.
TEST(PredictionPanel, TheMeasurementWaitsForTheClasssAnswer) {
  ClassroomOptions options;  // predictions asked, as by default
  options.lesson = "push";
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  hands.frame();
  hands.classroom().playback().run_to(3.0);  // theory's breakaway: 3.92 N at 1.96 s
  ASSERT_TRUE(hands.classroom().theory_hidden());
  const auto note = [&] {
    const std::string texts = hands.texts();
    const std::size_t at = texts.find("measured: ");
    return at == std::string::npos ? std::string("(none)") : texts.substr(at, texts.find('\n', at) - at);
  };
  EXPECT_EQ(note(), "measured: hidden") << "the breakaway push given away";
  hands.key(Key::r);
  hands.click("prediction breakaway push");
  hands.type("4");
  hands.press_enter();
  ASSERT_EQ(hands.classroom().predictions().answers["breakaway push"], "4");
  hands.classroom().playback().run_to(3.0);
  EXPECT_EQ(note().rfind("measured: 3.9", 0), 0u) << note();
}

// The class's predictions through a whole round: answered before Play, fixed once the run
// starts, set beside theory and measurement at the reveal, cleared when a value they depend on
// changes, asked again; and no panel giving the theory away before the reveal.
using lessons::ScriptFile;

// Asked of the class before the reveal, a failed row's note beside the answer box says "?" too,
// as both tables do (a student's second trial found "measured: not yet" there).
TEST(PredictionPanel, AFailedRowsNoteBesideTheClasssAnswerSaysItIsNotKnown) {
  const lessons::ScriptFile script(lessons::with_heading(R"(
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "broken", unit = "N", predicted = function() return 2 end,
  measured = function() if time() > 0.05 then return nothing_here.value end end, tolerance = 0.1 }
predict { "broken", unit = "N", question = "How hard?" }
)"));
  ClassroomHands hands(script.path());
  hands.classroom().window_settings().predictions = true;
  hands.playback().run_to(0.1);
  ASSERT_TRUE(hands.classroom().theory_hidden());
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, ImVec2(1280.0f, 720.0f), &record);
  bool unknown = false;
  for (const draw::ShownText& text : record.texts) {
    EXPECT_NE(text.text, "measured: not yet") << "the failed row is said to be not measured yet";
    unknown = unknown || text.text == "measured: ?";
  }
  EXPECT_TRUE(unknown) << "no \"measured: ?\" beside the class's answer";
}

// Predict first: the class's answer is typed before Play, fixed once the run starts, and set
// beside the theory and the measurement once the teacher reveals them.
TEST(PredictionPanel, TheClassPredictsBeforePlayAndTheRevealSetsItBesideTheoryAndMeasurement) {
  ClassroomHands hands("spring_pull");
  hands.set_display(ImVec2(1920.0f, 1080.0f));  // the questions whole, none a scroll away
  hands.frame();
  ASSERT_TRUE(hands.classroom().theory_hidden());
  hands.click("prediction breakaway force");
  hands.type("4");
  hands.press(ImGuiKey_Enter);
  EXPECT_EQ(hands.classroom().predictions().answers["breakaway force"], "4");
  // The run: the answer is the class's, and stays as it was.
  hands.key(Key::space);
  hands.playback().run_to(hands.lesson().duration());
  hands.key(Key::space);
  hands.click("prediction breakaway force");
  hands.type("9");
  hands.press(ImGuiKey_Enter);
  EXPECT_EQ(hands.classroom().predictions().answers["breakaway force"], "4");
  EXPECT_TRUE(hands.classroom().theory_hidden()) << "the run alone reveals nothing";

  hands.click("reveal");
  EXPECT_FALSE(hands.classroom().theory_hidden());
  draw::FrameRecord record;
  hands.frame(0.0, ImVec2(0.0f, 0.0f), &record);
  hands.frame(0.0, ImVec2(0.0f, 0.0f), &record);
  // Breakaway at mu_s·m·g = 0.45 × 1 kg × 9.81 m/s² = 4.41 N: the class's 4 N is 0.41 N below.
  lessons::ExpectationResult breakaway;
  for (const lessons::ExpectationResult& row : hands.playback().readings().expectations) {
    if (row.name == "breakaway force") breakaway = row;
  }
  ASSERT_TRUE(breakaway.measured_yet);
  EXPECT_NEAR(breakaway.predicted, 0.45 * 9.81, 1e-9);
  const auto drawn = [&](const std::string& text) {
    for (const draw::ShownText& shown : record.texts) {
      if (shown.text == text) return true;
    }
    return false;
  };
  EXPECT_TRUE(drawn(draw::format_quantity(breakaway.predicted, "N")));
  EXPECT_TRUE(drawn(draw::format_quantity(breakaway.measured, "N")));
  // The class's line: its answer with the unit, and how far off it was.
  const double off = 4.0 - breakaway.measured;
  char close[128];
  std::snprintf(close, sizeof close, "class: 4 N \u00b7 \u2212%s, %.0f %% below the measurement",
                draw::format_quantity(-off, "N").c_str(), 100.0 * -off / breakaway.measured);
  EXPECT_TRUE(drawn(close)) << close;
  // T again hides the theory, the class's answers kept (a reveal by mistake undone, issue 31);
  // T reveals it once more; a lesson opened afresh asks again.
  hands.key(Key::t);
  EXPECT_TRUE(hands.classroom().theory_hidden());
  EXPECT_EQ(hands.classroom().predictions().answers["breakaway force"], "4");
  hands.key(Key::t);
  EXPECT_FALSE(hands.classroom().theory_hidden());
  EXPECT_EQ(hands.classroom().open("tipping_box"), "");
  hands.frame();
  EXPECT_TRUE(hands.classroom().theory_hidden());
  EXPECT_TRUE(hands.classroom().predictions().answers.empty());
  hands.click("prediction tips or slides: slides");
  EXPECT_EQ(hands.classroom().predictions().answers["tips or slides"], "slides");
  hands.key(Key::t);
  EXPECT_FALSE(hands.classroom().theory_hidden());
}

// A prediction is for the values it was made at: a value changed before Play that changes the
// row's theory (the mass) clears that answer and says so; one that does not (how fast the push
// grows, for the breakaway push) keeps it.
TEST(PredictionPanel, APredictionIsClearedWhenAValueItDependsOnChanges) {
  ClassroomHands hands("push");
  hands.set_display(ImVec2(1920.0f, 1080.0f));
  hands.frame();
  hands.click("prediction breakaway push");
  hands.type("4");
  hands.press(ImGuiKey_Enter);
  hands.frame();
  const std::map<std::string, std::string>& answers = hands.classroom().predictions().answers;
  ASSERT_EQ(answers.count("breakaway push"), 1u);
  ASSERT_EQ(answers.at("breakaway push"), "4");
  // The breakaway push is mu_s·m·g, however fast the push grows.
  hands.playback().set_parameter("push_rate", "5");
  hands.frame();
  hands.frame();
  ASSERT_EQ(answers.count("breakaway push"), 1u) << "a value the theory does not use cleared it: " << hands.classroom().status();
  hands.playback().set_parameter("mass", "2");
  hands.frame();
  hands.frame();
  EXPECT_EQ(answers.count("breakaway push"), 0u) << "the prediction for 1 kg was kept at 2 kg";
  EXPECT_NE(hands.classroom().status().find("breakaway push"), std::string::npos) << hands.classroom().status();
  EXPECT_TRUE(hands.classroom().theory_hidden());

  // After the run and the reveal too (a teacher's trial: a 1 kg answer of 5 N was shown "87 %
  // below the theory" for 10 kg): the answer goes, and the status says how to ask anew.
  hands.click("prediction breakaway push");
  hands.type("19");
  hands.press(ImGuiKey_Enter);
  hands.frame();
  ASSERT_EQ(answers.count("breakaway push"), 1u);
  hands.playback().run_to(hands.lesson().duration());
  hands.key(Key::t);
  ASSERT_FALSE(hands.classroom().theory_hidden());
  hands.frame();
  ASSERT_EQ(answers.count("breakaway push"), 1u) << "the reveal cleared the answer: " << hands.classroom().status();
  hands.playback().set_parameter("mass", "10");
  hands.frame();
  hands.frame();
  EXPECT_EQ(answers.count("breakaway push"), 0u) << "the prediction for 2 kg was judged at 10 kg";
  EXPECT_NE(hands.classroom().status().find("Predict again"), std::string::npos) << hands.classroom().status();
  EXPECT_FALSE(hands.classroom().theory_hidden());
}

// A second round: after the reveal the teacher changes a value and asks the class again. The
// View menu's "Predict again" hides the theory, clears the answers and takes the run back to
// t = 0, where the new answers are typed; before, the theory stayed up until another lesson
// was opened, and the old answers were judged against the new run.
TEST(PredictionPanel, PredictAgainHidesTheTheoryForANewRoundOfAnswers) {
  ClassroomHands hands("tipping_box");
  hands.set_display(ImVec2(1920.0f, 1080.0f));
  hands.frame();
  hands.click("prediction tips or slides: slides");
  hands.key(Key::space);
  hands.playback().run_to(hands.lesson().duration());
  hands.key(Key::t);
  ASSERT_FALSE(hands.classroom().theory_hidden());
  hands.playback().set_parameter("push_height", "0.3");
  hands.click("View menu");
  hands.click("Predict again");
  hands.frame();
  EXPECT_TRUE(hands.classroom().theory_hidden()) << "the theory is hidden for the new round";
  EXPECT_TRUE(hands.classroom().predictions().answers.empty()) << "the old answers are gone";
  EXPECT_EQ(hands.lesson().scene().frame(), 0) << "back at the start, where answers are typed";
  EXPECT_EQ(hands.lesson().parameter("push_height").value, 0.3) << "the teacher's new value stays";
  hands.click("prediction tips or slides: tips");
  EXPECT_EQ(hands.classroom().predictions().answers["tips or slides"], "tips");
}

// Space is how the window plays. Typed into a prediction's number (a teacher who typed the
// class's answer and pressed Space to start, as the trial did), it ends the typing and plays,
// and never becomes part of the number ("40 " read as "not a number" after the reveal).
TEST(PredictionPanel, SpaceTypedIntoAPredictionPlaysAndJoinsNoNumber) {
  ClassroomHands hands("spring_pull");
  hands.set_display(ImVec2(1920.0f, 1080.0f));
  hands.frame();
  hands.click("prediction breakaway force");
  hands.type("4");
  ASSERT_TRUE(ImGui::GetIO().WantTextInput) << "the box is being typed in";
  hands.classroom().key_pressed(Key::space, false);  // the key, as the window passes it on...
  hands.type(" ");                                    // ...and the character it types
  EXPECT_EQ(hands.classroom().predictions().answers["breakaway force"], "4");
  EXPECT_TRUE(hands.playback().playing()) << "Space played the run";
  hands.frame();
  hands.frame();  // ImGui tells what the frame before asked for
  EXPECT_FALSE(ImGui::GetIO().WantTextInput) << "the typing ended";
  std::string why;
  EXPECT_EQ(classroom_state::read_answer(" 40 ", why), std::optional<double>(40.0)) << why;
}

// A teacher who takes no predictions has the theory from the start.
TEST(PredictionPanel, WithPredictionsOffTheTheoryShowsFromTheStart) {
  ClassroomHands hands("incline");
  hands.frame();
  EXPECT_TRUE(hands.classroom().theory_hidden());
  hands.click("View menu");
  hands.click("Ask for predictions first");
  EXPECT_FALSE(hands.classroom().window_settings().predictions);
  EXPECT_FALSE(hands.classroom().theory_hidden());
}

// The vertices a plot's window drew in the theory's colours: its curves and their legend keys.
int theory_vertices(const draw::Theme& colours, std::size_t plots) {
  int count = 0;
  for (std::size_t i = 0; i < plots; ++i) {
    const ImGuiWindow* window = ImGui::FindWindowByName(("###plot" + std::to_string(i)).c_str());
    if (window == nullptr) continue;
    for (const ImDrawVert& vertex : window->DrawList->VtxBuffer) {
      for (const ImU32 theory : colours.theory) {
        if ((vertex.col & 0x00ffffffu) == (theory & 0x00ffffffu) && (vertex.col >> 24) > 0) ++count;
      }
    }
  }
  return count;
}

// Before the reveal no panel states a theory value of the lesson, and no plot draws a theory
// curve: every text the frame drew is searched for each row's theory as the table writes it
// (a word only as one of the choices offered, as often as the choices name it). After the
// reveal each predicted row's theory is drawn beside the class's answer.
TEST(PredictionPanel, BeforeTheRevealNoPanelGivesTheTheoryAway) {
  const auto all = [](const draw::FrameRecord& record, const std::string& text, bool whole) {
    int count = 0;
    for (const draw::ShownText& shown : record.texts) count += whole ? shown.text == text : shown.text.find(text) != std::string::npos;
    return count;
  };
  for (const lessons::CatalogEntry& entry : lessons::catalog()) {
    SCOPED_TRACE(entry.name);
    ClassroomHands hands(entry.name);
    hands.set_display(ImVec2(1920.0f, 1080.0f));
    draw::FrameRecord record;
    hands.frame();
    hands.frame(0.0, ImVec2(0.0f, 0.0f), &record);
    const std::vector<lessons::ExpectationResult> rows = hands.lesson().expectations();
    const auto& predictions = hands.lesson().predictions();
    ASSERT_FALSE(predictions.empty());
    for (const lessons::ExpectationResult& row : rows) {
      if (row.numeric) {
        // A theory of exactly 0 (check_the_article's block ends at rest) reads "0 J", which the
        // energy ledger's "0.0000 J" contains without giving anything away: it is looked for as
        // a whole text, as a table cell would show it.
        EXPECT_EQ(all(record, draw::format_quantity(row.predicted, row.unit.c_str()), row.predicted == 0.0), 0)
            << row.name << ": " << draw::format_quantity(row.predicted, row.unit.c_str());
        continue;
      }
      int offered = 0;
      for (const lessons::Prediction& prediction : predictions) {
        offered += static_cast<int>(std::count(prediction.choices.begin(), prediction.choices.end(), row.predicted_text));
      }
      EXPECT_EQ(all(record, row.predicted_text, true), offered) << row.name << ": " << row.predicted_text;
    }
    const draw::Theme& colours = theme(draw::ThemeName::light);
    const std::size_t plots = hands.lesson().plots().size();
    bool any_theory_curve = false;
    for (const lessons::Plot& plot : hands.lesson().plots()) any_theory_curve = any_theory_curve || !plot.theory.empty();
    EXPECT_EQ(theory_vertices(colours, plots), 0);

    // Revealed, with an answer for each question: the theory beside the class's answer.
    for (const lessons::Prediction& prediction : predictions) {
      hands.classroom().predictions().answers[prediction.expectation] = prediction.is_choice() ? prediction.choices[0] : "1";
    }
    hands.classroom().predictions().revealed = true;
    hands.frame();
    hands.frame(0.0, ImVec2(0.0f, 0.0f), &record);
    for (const lessons::Prediction& prediction : predictions) {
      const auto row = std::find_if(rows.begin(), rows.end(),
                                    [&](const lessons::ExpectationResult& r) { return r.name == prediction.expectation; });
      ASSERT_NE(row, rows.end());
      const std::string theory = row->numeric ? draw::format_quantity(row->predicted, row->unit.c_str()) : row->predicted_text;
      // In the theory table only (the class's lines give the answer and how close it came, not
      // the theory a second time): once for each row whose theory reads the same (contact_area's
      // four blocks all break away at one pull).
      const auto shown_theory = [](const lessons::ExpectationResult& r) {
        return r.numeric ? draw::format_quantity(r.predicted, r.unit.c_str()) : r.predicted_text;
      };
      const auto same = std::count_if(rows.begin(), rows.end(), [&](const lessons::ExpectationResult& r) { return shown_theory(r) == theory; });
      EXPECT_EQ(all(record, theory, true), static_cast<int>(same)) << prediction.expectation << ": in the theory table, and only there";
      const std::string answer = prediction.is_choice() ? prediction.choices[0] : "1 " + prediction.unit;
      EXPECT_GE(all(record, "class: " + answer + " \u00b7 ", false), 1) << prediction.expectation << ": the class's line";
    }
    if (any_theory_curve) {
      EXPECT_GT(theory_vertices(colours, plots), 0);
    }
  }
}

}  // namespace
}  // namespace frictionlab::classroom
