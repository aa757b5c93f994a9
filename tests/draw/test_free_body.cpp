// The free-body inset's numbers add up as printed (issue 31): a student who adds the printed
// forces by hand, as vectors along their arrows, gets the printed net force. push's inset read
// 6.92 − 2.94 = 3.98 N above "net force: 3.97 N", the net of the forces before rounding.
#include "draw/free_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "draw/frame.h"
#include "draw/headless_render.h"
#include "draw/overlays.h"
#include "tests/rendering.h"

namespace frictionlab::draw {
namespace {

// "3.98 N" as 3.98; the inset's forces are printed in plain decimals.
double number_in(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  EXPECT_NE(end, text.c_str()) << "no number in \"" << text << "\"";
  return value;
}

TEST(FreeBody, ThePrintedNetIsTheSumOfTheForcesAsPrinted) {
  // push's forces at one moment: the push and the friction against it, the normal force and the
  // weight. The unrounded net, 3.9798 N, prints 3.98; the printed values give 6.92 − 2.95 = 3.97.
  const std::vector<b2Vec2> forces = {{6.9249f, 0.0f}, {-2.9451f, 0.0f}, {0.0f, 9.81f}, {0.0f, -9.81f}};
  EXPECT_NEAR(printed_net(forces), 3.97, 1e-9);
  // Weight and normal force printed alike cancel, even a hair off vertical: no 1.2×10⁻⁷ N left.
  EXPECT_EQ(printed_net({{1e-6f, 9.8100004f}, {0.0f, -9.81f}}), 0.0);
  // Along a slope: the printed values as vectors, 3-4-5.
  EXPECT_NEAR(printed_net({{3.0012f, 0.0f}, {0.0f, 3.9996f}}), 5.0, 1e-9);
  EXPECT_EQ(printed_net({}), 0.0);
}

// The inset as drawn, in the lessons with a few forces on one body, at many moments, with
// projector text: each force's value as printed, along its arrow, sums to the printed net force
// within half of the net's last printed digit.
TEST(FreeBody, TheInsetsNumbersAddUpAsPrinted) {
  HeadlessRenderer renderer(1920, 1080, ThemeName::light, 1.35f * 1.5f);
  int checked = 0;
  for (const char* name : {"push", "incline", "tipping_box", "stacked_blocks", "spring_pull", "driven_wheel"}) {
    LessonAt at(name, {}, 0.0);
    const double end = at.lesson->duration();
    for (double t = 0.05; t <= end; t += 0.05) {
      at.step_to(t);
      FrameRecord record;
      renderer.render(*at.lesson, at.framing, &record);
      const FreeBodyRecord& inset = record.free_body;
      if (!inset.drawn) continue;
      ASSERT_EQ(inset.forces.size(), inset.directions.size());
      double x = 0.0, y = 0.0, finest = 1.0;
      std::string sum;
      for (std::size_t i = 0; i < inset.forces.size(); ++i) {
        const double value = number_in(inset.forces[i].text);
        finest = std::min(finest, printed_number(value).step);
        const b2Vec2 direction = inset.directions[i];
        x += value * direction.x / direction.Length();
        y += value * direction.y / direction.Length();
        sum += " " + inset.forces[i].text;
      }
      const std::string prefix = "net force: ";
      ASSERT_EQ(inset.net_text.rfind(prefix, 0), 0u) << inset.net_text;
      const double net = number_in(inset.net_text.substr(prefix.size()));
      // Written, as a student would, to the digits of the values added (weight and normal force,
      // 9.81 N each, a hair apart in direction, add to 0).
      const double by_hand = std::round(std::hypot(x, y) / finest) * finest;
      // The net is printed to its own digits: a sum of 12.756 N reads 12.8 N.
      EXPECT_LE(std::abs(net - by_hand), 0.5 * printed_number(by_hand).step + 1e-9)
          << name << " at " << t << " s: the forces" << sum << " add up to " << by_hand << " N, printed \""
          << inset.net_text << "\"";
      ++checked;
    }
  }
  EXPECT_GE(checked, 200);
}

}  // namespace
}  // namespace frictionlab::draw
