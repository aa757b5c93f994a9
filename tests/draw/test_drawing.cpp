// The drawing helpers' lengths: a scale's nice lengths, rounded to the nearest for an arrow's
// scale and down for a bar that must fit its room.
#include <gtest/gtest.h>

#include <cmath>

#include "draw/drawing.h"

namespace frictionlab::ui {
namespace {

// 1, 2 or 5 times a power of ten, within a float's rounding.
bool is_one_two_or_five(float length) {
  const float power = std::pow(10.0f, std::floor(std::log10(length) + 1e-5f));
  const float fraction = length / power;
  for (const float nice : {1.0f, 2.0f, 5.0f, 10.0f}) {
    if (std::abs(fraction - nice) < 1e-4f * nice) return true;
  }
  return false;
}

// A scale bar in a column of fixed width: a bar rounded up (3.5 → 5) ran past the column's
// edge and was cut shorter than the length written above it.
TEST(Drawing, ABarsNiceLengthWithinItsRoomIsNeverLongerThanTheRoomAndOverTwoFifthsOfIt) {
  for (float most = 0.013f; most < 2000.0f; most *= 1.07f) {
    const float bar = nice_length_within(most);
    EXPECT_LE(bar, most * (1.0f + 1e-6f)) << "room " << most;
    // The next nice length up is at most 2.5 times this one (2 → 5), so a bar keeps over 2/5 of its room.
    EXPECT_GT(bar, 0.4f * most) << "room " << most;
    EXPECT_TRUE(is_one_two_or_five(bar)) << bar;
  }
  EXPECT_FLOAT_EQ(nice_length_within(0.35f), 0.2f);
  EXPECT_FLOAT_EQ(nice_length_within(5.0f), 5.0f);
  EXPECT_FLOAT_EQ(nice_length_within(9.99f), 5.0f);
}

// The nearest nice length is from 0.57 to 1.43 times what was asked (the legend's column is
// sized for the longest).
TEST(Drawing, TheNearestNiceLengthIsWithinAFactorOfOnePointFourThreeOfTheLengthAsked) {
  for (float wanted = 0.013f; wanted < 2000.0f; wanted *= 1.03f) {
    const float nice = nice_length(wanted);
    EXPECT_LE(nice, 1.43f * wanted * (1.0f + 1e-5f)) << wanted;
    EXPECT_GE(nice, 0.57f * wanted) << wanted;
    EXPECT_TRUE(is_one_two_or_five(nice)) << nice;
  }
}

}  // namespace
}  // namespace frictionlab::ui
