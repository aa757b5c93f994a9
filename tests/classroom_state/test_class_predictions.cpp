// The class's predictions as the window keeps them (classroom_state/class_predictions.h): a
// typed answer read as a number or refused in words a class can act on, and the theory kept
// back only while there is something to predict and it has not been revealed.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "classroom_state/class_predictions.h"
#include "lessons/runtime/lesson.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::classroom_state {
namespace {

std::optional<double> read(const std::string& typed, std::string& why) {
  why = "left from before";  // what a refusal says is written afresh each time
  return read_answer(typed, why);
}

TEST(ClassPredictions, ATypedAnswerIsReadAsTheNumberTypedWithTheSpacesAroundItLeftOut) {
  std::string why;
  EXPECT_EQ(read("2.5", why), 2.5);
  EXPECT_EQ(read("-0.3", why), -0.3);
  EXPECT_EQ(read("40 ", why), 40.0);  // a box typed into before Play
  EXPECT_EQ(read(" \t7\t ", why), 7.0);
  EXPECT_EQ(read("1e3", why), 1000.0);
}

TEST(ClassPredictions, AnAnswerThatIsNoNumberOrOutOfRangeIsRefusedSayingWhy) {
  std::string why;
  EXPECT_EQ(read("0,5", why), std::nullopt);
  EXPECT_EQ(why, "not a number: write decimals with a point, as in 0.5");
  EXPECT_EQ(read("about 3", why), std::nullopt);
  EXPECT_EQ(why, "not a number: type it as 2.5 or -0.3");
  EXPECT_EQ(read("   ", why), std::nullopt);
  EXPECT_EQ(why, "not a number: type it as 2.5 or -0.3");
  // ±largest_answer itself is taken; a thousandth past it is not.
  EXPECT_EQ(read("1000000", why), largest_answer);
  EXPECT_EQ(read("-1000000", why), -largest_answer);
  EXPECT_EQ(read("1000000.001", why), std::nullopt);
  EXPECT_EQ(why, "outside the range a prediction takes, from -1000000 to 1000000");
  EXPECT_EQ(read("-2e6", why), std::nullopt);
  EXPECT_EQ(why, "outside the range a prediction takes, from -1000000 to 1000000");
  // Past a double's range, the number parser's own words.
  EXPECT_EQ(read("1e400", why), std::nullopt);
  EXPECT_NE(why.find("too large"), std::string::npos) << why;
}

TEST(ClassPredictions, TheTheoryIsHiddenOnlyWhileTheClassIsAskedAndHasNotSeenIt) {
  const std::string rows = R"(
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "friction", unit = "N", predicted = function() return 1 end, measured = function() return 1 end, tolerance = 0.01 }
)";
  const lessons::ScriptFile asks(lessons::with_heading(rows + R"(predict { "friction", question = "How hard?" })"));
  const lessons::ScriptFile asks_nothing(lessons::with_heading(rows));
  const lessons::Lesson predicting(asks.path());
  const lessons::Lesson not_predicting(asks_nothing.path());
  ClassPredictions predictions;
  EXPECT_TRUE(theory_hidden(predicting, predictions, true));
  EXPECT_FALSE(theory_hidden(predicting, predictions, false)) << "the teacher turned predictions off";
  EXPECT_FALSE(theory_hidden(not_predicting, predictions, true)) << "nothing to predict";
  predictions.revealed = true;
  EXPECT_FALSE(theory_hidden(predicting, predictions, true));
}

}  // namespace
}  // namespace frictionlab::classroom_state
