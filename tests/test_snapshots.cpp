// Golden pictures of every built-in lesson at moments that teach something, checked to be
// those moments (the block really sticks, the box really tips) before the picture is compared.
// A channel differing by more than 8 on more than 0.1 % of the pixels fails, as does another
// size or a missing golden. On failure the actual picture and a diff are written under the
// build folder. UPDATE_SNAPSHOTS=1 writes the goldens instead; look at them before committing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>

#include "rendering.h"
#include "ui/image.h"

namespace frictionlab::ui {
namespace {

namespace fs = std::filesystem;

struct Moment {
  std::string name;  // the golden's file name, without .png
  std::string lesson;
  std::map<std::string, std::string> set;
  double t;
  ThemeName theme;
  std::function<void(const Scene&)> is_meaningful;  // asserts the moment shows what its name says
};

bool any_slipping(const Scene& scene) { return !scene.slipping().empty() && scene.slipping().back() != 0; }

const std::vector<Moment>& moments() {
  static const std::vector<Moment> all = {
      {"spring_pull_sticking", "spring_pull", {}, 0.5, ThemeName::light,
       [](const Scene& s) { EXPECT_FALSE(any_slipping(s)); }},
      {"spring_pull_mid_slip", "spring_pull", {}, 1.2, ThemeName::light,
       [](const Scene& s) { EXPECT_TRUE(any_slipping(s)); }},
      // Below and above the sticking angle atan(mu_s) = 31.0° of the block on the slope.
      {"incline_below_critical_angle", "incline", {{"angle", "25"}}, 1.0, ThemeName::light,
       [](const Scene& s) {
         EXPECT_FALSE(any_slipping(s));
         EXPECT_LT(s.body("block")->GetLinearVelocity().Length(), 1e-3f);
       }},
      {"incline_above_critical_angle", "incline", {}, 1.0, ThemeName::light,
       [](const Scene& s) {
         EXPECT_TRUE(any_slipping(s));
         EXPECT_GT(s.body("block")->GetLinearVelocity().Length(), 1.0f);
       }},
      // Pushed below d/(2·mu_s) = 0.5 m the box slides; above, it tips.
      {"tipping_box_pushed_low", "tipping_box", {{"push_height", "0.2"}}, 3.0, ThemeName::light,
       [](const Scene& s) {
         EXPECT_TRUE(any_slipping(s));
         EXPECT_NEAR(s.body("box")->GetAngle(), 0.0f, 0.01f);
       }},
      {"tipping_box_pushed_high", "tipping_box", {}, 2.2, ThemeName::light,
       [](const Scene& s) { EXPECT_LT(s.body("box")->GetAngle(), -0.03f); }},
      {"spring_pull_dark_theme", "spring_pull", {}, 2.5, ThemeName::dark,
       [](const Scene& s) { EXPECT_TRUE(any_slipping(s)); }},
  };
  return all;
}

// Test names and failure messages show the moment's name, not its bytes.
void PrintTo(const Moment& moment, std::ostream* out) { *out << moment.name; }

class Snapshot : public ::testing::TestWithParam<Moment> {};

TEST_P(Snapshot, MatchesItsGolden) {
  const Moment& moment = GetParam();
  LessonAt at(moment.lesson, moment.set, moment.t);
  moment.is_meaningful(at.scene());
  HeadlessRenderer renderer(frame_width, frame_height, moment.theme);
  const Image actual = renderer.render(*at.lesson, at.framing);

  const std::string golden = std::string(FRICTIONLAB_SNAPSHOTS) + "/" + moment.name + ".png";
  const char* update = std::getenv("UPDATE_SNAPSHOTS");
  if (update != nullptr && std::string(update) == "1") {
    write_png(actual, golden);
    std::cout << "wrote " << golden << " (look at it before committing)\n";
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; make it with UPDATE_SNAPSHOTS=1 ctest -R Snapshot, "
                                  << "then look at it";
  const Image expected = read_png(golden);
  const ImageComparison result = compare_images(actual, expected, 8);
  const bool same = result.same_size && result.differing_fraction() <= 0.001;
  if (!same) {
    const fs::path failures = FRICTIONLAB_SNAPSHOT_FAILURES;
    fs::create_directories(failures);
    write_png(actual, (failures / (moment.name + ".actual.png")).string());
    if (result.same_size) write_png(result.diff, (failures / (moment.name + ".diff.png")).string());
  }
  ASSERT_TRUE(result.same_size) << "the picture is " << actual.width << "x" << actual.height << ", the golden "
                                << expected.width << "x" << expected.height;
  EXPECT_LE(result.differing_fraction(), 0.001)
      << result.differing_pixels << " pixels differ by more than 8 (largest " << result.largest_channel_difference
      << "); the picture and a diff are in " << FRICTIONLAB_SNAPSHOT_FAILURES;
}

INSTANTIATE_TEST_SUITE_P(Lessons, Snapshot, ::testing::ValuesIn(moments()),
                         [](const ::testing::TestParamInfo<Moment>& moment) { return moment.param.name; });

}  // namespace
}  // namespace frictionlab::ui
