// The drawing helpers' lengths: a scale's nice lengths, rounded to the nearest for an arrow's
// scale and down for a bar that must fit its room; and where the label placer puts a force's
// value that has no free place beside its arrow (its leader).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "draw/drawing.h"

namespace frictionlab::draw {
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

// A friction of a few pixels where a normal force and two others start (a crowded contact): its
// arrow (200, 150)–(206, 150), kept off 3.5 px either side as the world keeps its arrows, with
// arrows up, down, left and along both diagonals to the right from its tail. Every place within
// a line of its text of it is as near another arrow (the diagonals come within 7 px of a box
// beyond its tip that is 10 px from it), so none is beside it and its value goes, with a leader,
// into the free wedge between the diagonals, right of the tip.
struct CrowdedContact {
  LabelPlacer labels{ImVec2(0.0f, 0.0f), ImVec2(400.0f, 300.0f)};
  DrawnSegment friction{ImVec2(200.0f, 150.0f), ImVec2(206.0f, 150.0f), 3.5f};
  ImVec2 size{40.0f, 14.0f};  // a value's text, "2.59 N" in 14 px type
  // Without the lower diagonal (`open_below`), the quarter below and right of the tip is free too.
  explicit CrowdedContact(bool open_below = false) {
    labels.arrow(friction);
    for (const ImVec2 tip : {ImVec2(200.0f, 50.0f), ImVec2(200.0f, 250.0f), ImVec2(100.0f, 150.0f), ImVec2(290.0f, 60.0f),
                             ImVec2(290.0f, 240.0f)}) {
      if (open_below && tip.x == 290.0f && tip.y > 150.0f) continue;
      labels.arrow(DrawnSegment{friction.from, tip, 3.5f});
    }
  }
  // Where the value goes from just beyond the tip, as draw_force() asks, and its leader if it has one.
  std::optional<ImVec2> place(std::optional<DrawnSegment>* leader) {
    bool with_leader = false;
    const std::optional<ImVec2> at = labels.place_beside(ImVec2(206.0f + 0.5f * size.x + 5.0f, 150.0f), size, "2.59 N",
                                                         &friction, &with_leader);
    if (at && with_leader) *leader = leader_line(LabelPlacer::box_around(*at, size), friction);
    return at;
  }
};

// The case itself: the value is drawn, not beside its arrow, with a leader no longer than three
// lines that starts on its own arrow and crosses no other (the rule the placer keeps; the
// world's pictures are measured by test_world_labels).
TEST(Drawing, AValueWithNoPlaceBesideItsArrowGetsALeaderOfAtMostThreeLinesThatCrossesNoOtherArrow) {
  CrowdedContact contact;
  std::optional<DrawnSegment> leader;
  const std::optional<ImVec2> at = contact.place(&leader);
  ASSERT_TRUE(at.has_value());
  ASSERT_TRUE(leader.has_value()) << "at (" << at->x << ", " << at->y << ")";
  EXPECT_LE(length(sub(leader->to, leader->from)), LabelPlacer::longest_leader(contact.size));
  EXPECT_LT(gap(*leader, contact.friction), 1e-3f);  // it starts on the friction's line
  for (std::size_t k = 1; k < 6; ++k) {
    // The others' centre lines: they all start at the friction's tail, which a leader may touch.
    const DrawnSegment& other = contact.labels.segments()[k];
    const ImVec2 d = sub(other.to, other.from);
    const ImVec2 start = add(other.from, mul(d, 2.0f / length(d)));  // 2 px past the shared tail
    EXPECT_GT(gap(*leader, DrawnSegment{start, other.to, 0.0f}), 0.0f) << "the leader crosses arrow " << k;
  }
}

// A line drawn that is not an arrow (a torque's arc, a spring, another value's leader) stands
// right of the tip, from above down to 10 px below the friction's line, where the nearest free
// place's leader runs straight across it (as it did before): a leader that crosses it is read
// as joined to it. The value goes where its leader crosses no such line, below the line's end,
// with the quarter below and right of the tip free.
TEST(Drawing, AValuesLeaderCrossesNoLineDrawnThatIsNotAnArrowWhereAPlaceWithoutOneIsNear) {
  CrowdedContact contact(true);
  const DrawnSegment line{ImVec2(225.0f, 100.0f), ImVec2(225.0f, 160.0f), 2.0f};
  contact.labels.avoid(line);
  std::optional<DrawnSegment> leader;
  const std::optional<ImVec2> at = contact.place(&leader);
  ASSERT_TRUE(at.has_value());
  ASSERT_TRUE(leader.has_value()) << "at (" << at->x << ", " << at->y << ")";
  EXPECT_LE(length(sub(leader->to, leader->from)), LabelPlacer::longest_leader(contact.size));
  EXPECT_FALSE(meet(*leader, DrawnSegment{line.from, line.to, 0.0f}))
      << "the leader from (" << leader->from.x << ", " << leader->from.y << ") to (" << leader->to.x << ", " << leader->to.y
      << ") crosses the line";
}

// Another block's face (a body's box, as the world gives it) fills the wedge right of the tip,
// where the nearest free place is, and the quarter below is free: a value moved off its arrow
// onto a body it does not act on reads as that body's (issue 31). It goes below, off the block.
TEST(Drawing, AValueWithALeaderLiesOnNoOtherBodyWhereAPlaceOffThemIsNear) {
  CrowdedContact contact(true);
  const ImVec4 block(214.0f, 90.0f, 330.0f, 156.0f);
  contact.labels.body(block);
  std::optional<DrawnSegment> leader;
  const std::optional<ImVec2> at = contact.place(&leader);
  ASSERT_TRUE(at.has_value());
  ASSERT_TRUE(leader.has_value()) << "at (" << at->x << ", " << at->y << ")";
  EXPECT_LE(length(sub(leader->to, leader->from)), LabelPlacer::longest_leader(contact.size));
  const ImVec4 box = LabelPlacer::box_around(*at, contact.size);
  EXPECT_FALSE(overlaps(box, block)) << "the value at (" << at->x << ", " << at->y << ") lies on the block";
}

}  // namespace
}  // namespace frictionlab::draw
