// The mystery surface's state: the draw (the same seed gives the same values on every machine,
// μk < μs always, within the documented range), the pair named on the command line, and how far
// off the class's answers are (the window's side is tests/classroom/test_mystery_panel.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>

#include "classroom_state/mystery.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"
#include "physics/validation.h"

namespace frictionlab::classroom_state {
namespace {

TEST(MysteryDraw, TheEngineIsTheStandardsMersenneTwister) {
  // The C++ standard fixes this output ([rand.predef]): the draw rests on nothing a library chooses.
  std::mt19937_64 engine;
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042ULL);
}

TEST(MysteryDraw, EverySeedGivesHundredthsInTheRangeWithMuKBelowMuS) {
  for (std::uint64_t seed = 0; seed <= 20000; ++seed) {
    const MysteryValues values = mystery_values(seed);
    ASSERT_GE(values.mu_s, 0.20 - 1e-12) << seed;
    ASSERT_LE(values.mu_s, 0.90 + 1e-12) << seed;
    ASSERT_LT(values.mu_k, values.mu_s) << seed;
    // μk is 50 % to 90 % of μs, rounded to a hundredth.
    ASSERT_GE(values.mu_k, 0.5 * values.mu_s - 0.005 - 1e-12) << seed;
    ASSERT_LE(values.mu_k, 0.9 * values.mu_s + 0.005 + 1e-12) << seed;
    ASSERT_EQ(std::round(values.mu_s * 100.0) / 100.0, values.mu_s) << seed;
    ASSERT_EQ(std::round(values.mu_k * 100.0) / 100.0, values.mu_k) << seed;
  }
  // The largest seed too.
  EXPECT_LT(mystery_values(mystery_seed_max).mu_k, mystery_values(mystery_seed_max).mu_s);
}

TEST(MysteryDraw, TheSameSeedGivesTheSameValuesAndOthersOtherValues) {
  const MysteryValues first = mystery_values(42), again = mystery_values(42);
  EXPECT_EQ(first.mu_s, again.mu_s);
  EXPECT_EQ(first.mu_k, again.mu_k);
  // Fixed here so that another machine or standard library drawing anything else fails: the
  // values follow from the standard's engine and this file's arithmetic alone.
  EXPECT_EQ(validation::exact_text(first.mu_s), "0.58");
  EXPECT_EQ(validation::exact_text(first.mu_k), "0.49");
  // Neighbouring seeds are not neighbouring values: of 100 seeds, nearly all draw a pair of their own.
  std::set<std::pair<double, double>> drawn;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) drawn.insert({mystery_values(seed).mu_s, mystery_values(seed).mu_k});
  EXPECT_GE(drawn.size(), 95u);
  EXPECT_FALSE(mystery_values(1).mu_s == mystery_values(2).mu_s && mystery_values(1).mu_k == mystery_values(2).mu_k);
}

TEST(MysteryDraw, ASeedIsAWholeNumberInItsRange) {
  EXPECT_EQ(parse_mystery_seed("--seed", "0"), 0u);
  EXPECT_EQ(parse_mystery_seed("--seed", "999999"), 999999u);
  for (const char* bad : {"", "-1", "1000000", "1.5", "1e3", " 7", "0x10", "12345678901234567890"}) {
    try {
      parse_mystery_seed("--seed", bad);
      ADD_FAILURE() << "'" << bad << "' was taken";
    } catch (const InvalidInput& error) {
      EXPECT_NE(std::string(error.what()).find("--seed " + std::string(bad) + ": "), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("a whole number from 0 to 999999"), std::string::npos) << error.what();
    }
  }
}

TEST(MysteryPairs, APairIsNamedByItsMaterialsEitherWayRoundAndAnUnknownOneListsThem) {
  const lessons::Lesson stacked(lessons::resolve_lesson("stacked_blocks"));
  EXPECT_EQ(mystery_pairs(stacked), (std::vector<std::string>{"wood/aluminium", "aluminium/stone"}));
  EXPECT_EQ(mystery_parameters(stacked, "aluminium/stone"),
            (std::pair<std::string, std::string>{"bottom_on_floor.mu_s", "bottom_on_floor.mu_k"}));
  EXPECT_EQ(mystery_parameters(stacked, "aluminium/wood").first, "top_on_bottom.mu_s");
  try {
    mystery_parameters(stacked, "wood/stone");  // a pair of the lesson, but without sliders
    ADD_FAILURE();
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("--mystery wood/stone: "), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("its pairs: wood/aluminium, aluminium/stone"), std::string::npos) << error.what();
  }
}

TEST(MysteryCloseness, AnAnswerIsJudgedInPercentOfTheTrueValue) {
  EXPECT_NEAR(percent_off(0.55, 0.5), 10.0, 1e-9);
  EXPECT_NEAR(percent_off(0.45, 0.5), 10.0, 1e-9);
  EXPECT_EQ(closeness_text(0.33, 0.3), "10.0 % off");
  EXPECT_EQ(closeness_text(0.3, 0.3), "0.0 % off");
}

}  // namespace
}  // namespace frictionlab::classroom_state
