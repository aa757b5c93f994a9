// predict{}: what the class predicts before the run, read from the script and tied to the
// lesson's own expect rows, so that the class's answer meets that row's theory and measurement.
// The broken-script corpus (test_lesson_errors, broken_lessons/predict_*.lua) covers the
// messages one by one.
#include <gtest/gtest.h>

#include <algorithm>

#include "lessons/runtime/catalog.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

const char* const two_rows = R"(
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
parameter { "push", 1, min = 0, max = 10, unit = "N" }
force { "push", on = block, force = { param.push, 0 } }
expect { "friction", unit = "N", predicted = function() return param.push end,
  measured = function() return nil end, tolerance = 0.01 }
expect { "moves or stays", predicted = function() return param.push > 5 and "moves" or "stays" end,
  measured = function() return nil end }
)";

TEST(Predict, ANumberTakesItsRowsUnitAndAChoiceItsWordsInTheOrderDeclared) {
  ScriptFile script(with_heading(std::string(two_rows) + R"(
predict { "moves or stays", choices = { "moves", "stays" }, question = "Does the block move?" }
predict { "friction", unit = "N", question = "How hard does friction hold it?" }
)"));
  Lesson lesson(script.path());
  const std::vector<Prediction>& predictions = lesson.predictions();
  ASSERT_EQ(predictions.size(), 2u);
  EXPECT_EQ(predictions[0].expectation, "moves or stays");
  EXPECT_TRUE(predictions[0].is_choice());
  EXPECT_EQ(predictions[0].choices, (std::vector<std::string>{"moves", "stays"}));
  EXPECT_EQ(predictions[0].unit, "");
  EXPECT_EQ(predictions[0].question, "Does the block move?");
  EXPECT_EQ(predictions[0].declared_at, script.path() + ":12");
  EXPECT_EQ(predictions[1].expectation, "friction");
  EXPECT_FALSE(predictions[1].is_choice());
  EXPECT_EQ(predictions[1].unit, "N");
}

TEST(Predict, TheUnitMayBeLeftOutAndComesFromTheRow) {
  ScriptFile script(with_heading(std::string(two_rows) + R"(predict { "friction", question = "How hard?" })"));
  Lesson lesson(script.path());
  ASSERT_EQ(lesson.predictions().size(), 1u);
  EXPECT_EQ(lesson.predictions()[0].unit, "N");
}

// The answer is checked at the lesson's defaults only: with other values a row may rightly
// say something the class was not offered ("not reached"), and the lesson must still open.
TEST(Predict, OnlyTheDefaultsMustGiveAnAnswerTheClassCanPick) {
  const std::string body = std::string(two_rows) +
                           R"(predict { "moves or stays", choices = { "stays", "tips" }, question = "Does it move?" })";
  ScriptFile script(with_heading(body));
  EXPECT_NO_THROW(Lesson(script.path()));
  EXPECT_NO_THROW(Lesson(script.path(), {{"push", "8"}}));  // "moves" is no choice, but the defaults' answer is
  ScriptFile wrong(with_heading(std::string(two_rows) +
                                R"(predict { "moves or stays", choices = { "moves", "tips" }, question = "Does it move?" })"));
  try {
    Lesson lesson(wrong.path());
    ADD_FAILURE() << "the defaults' answer 'stays' is not among the choices, and the lesson built";
  } catch (const ScriptError& error) {
    EXPECT_NE(std::string(error.what()).find(") gives \"stays\", which is not one of the choices \"moves\", \"tips\""),
              std::string::npos)
        << error.what();
  }
}

// A reload that breaks a prediction leaves the last good lesson, and its predictions, running.
TEST(Predict, ABrokenPredictionOnReloadKeepsTheLastGoodOnes) {
  ScriptFile script(with_heading(std::string(two_rows) + R"(predict { "friction", question = "How hard?" })"));
  Lesson lesson(script.path());
  script.rewrite(with_heading(std::string(two_rows) + R"(predict { "friction", unit = "kg", question = "How hard?" })"));
  EXPECT_FALSE(lesson.reload());
  EXPECT_NE(lesson.last_error().find("unit \"kg\" is not its expect row's \"N\""), std::string::npos) << lesson.last_error();
  ASSERT_EQ(lesson.predictions().size(), 1u);
  EXPECT_EQ(lesson.predictions()[0].unit, "N");
}

// Every built-in lesson asks the class one or two questions, each about one of its own rows,
// worded as a question.
TEST(Predict, EveryBuiltInLessonAsksForOneOrTwoPredictions) {
  for (const CatalogEntry& entry : catalog()) {
    SCOPED_TRACE(entry.name);
    Lesson lesson(resolve_lesson(entry.name));
    const std::vector<Prediction>& predictions = lesson.predictions();
    EXPECT_GE(predictions.size(), 1u);
    EXPECT_LE(predictions.size(), 2u);
    const std::vector<ExpectationResult> rows = lesson.expectations();
    for (const Prediction& prediction : predictions) {
      const auto row = std::find_if(rows.begin(), rows.end(),
                                    [&](const ExpectationResult& r) { return r.name == prediction.expectation; });
      ASSERT_NE(row, rows.end()) << prediction.expectation;
      EXPECT_EQ(prediction.question.back(), '?') << prediction.question;
      if (prediction.is_choice()) {
        EXPECT_FALSE(row->numeric);
        EXPECT_NE(std::find(prediction.choices.begin(), prediction.choices.end(), row->predicted_text),
                  prediction.choices.end());
      } else {
        EXPECT_TRUE(row->numeric) << "theory says " << row->predicted_text;
        EXPECT_EQ(prediction.unit, row->unit);
      }
    }
  }
}

}  // namespace
}  // namespace frictionlab::lessons
