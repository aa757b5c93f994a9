// Golden pictures of every built-in lesson at the moments it declares (lesson{ moments = ... }),
// one golden each, tests/snapshots/<lesson>_<moment>.png. Each moment is first checked to be
// what its name says (its shows function: the block really sticks, the box really tips), then
// its picture compared: a channel differing by more than 8 on more than 0.1 % of the pixels
// fails, as does another size or a missing golden. On failure the actual picture and a diff are
// written under the build folder. UPDATE_SNAPSHOTS=1 writes the goldens instead; look at them
// before committing. Every built-in lesson must declare moments, one of them its README frame,
// and no golden may be left that no moment takes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "draw/image.h"
#include "draw/theme.h"
#include "tests/rendering.h"

namespace frictionlab::draw {
namespace {

namespace fs = std::filesystem;

struct LessonMoment {
  std::string lesson;
  lessons::Moment moment;
  std::string broken;  // why the list of lessons could not be read, if it could not
  std::string name() const { return lesson + "_" + moment.name; }  // the golden's, without .png
};

// Built when the tests are listed: a lesson that cannot be built becomes one failing test
// instead of a crash before any test runs.
std::vector<LessonMoment> every_moment() {
  std::vector<LessonMoment> all;
  try {
    for (const lessons::CatalogEntry& entry : lessons::catalog()) {
      for (const lessons::Moment& moment : entry.moments) all.push_back({entry.name, moment, ""});
    }
  } catch (const InvalidInput& error) {
    all = {{"lessons", lessons::Moment{"cannot_be_listed", 0.0, {}, "light", false, false, ""}, error.what()}};
  }
  return all;
}

std::vector<std::string> every_lesson() {
  try {
    return lessons::builtin_lessons();
  } catch (const InvalidInput&) {
    return {};  // every_moment() reports it
  }
}

// Test names and failure messages show the moment's name, not its bytes.
void PrintTo(const LessonMoment& moment, std::ostream* out) { *out << moment.name(); }

class Snapshot : public ::testing::TestWithParam<LessonMoment> {};

TEST_P(Snapshot, ShowsWhatItsNameSaysAndMatchesItsGolden) {
  const LessonMoment& param = GetParam();
  ASSERT_TRUE(param.broken.empty()) << param.broken;
  const lessons::Moment& moment = param.moment;
  LessonAt at(param.lesson, moment.set, moment.at);
  // At its defaults the runtime checks this itself; with the moment's values only here.
  EXPECT_LE(moment.at, at.lesson->duration()) << moment.declared_at << ": the moment comes after the lesson's end";
  const std::optional<bool> shown = at.lesson->shows(moment.name);
  EXPECT_TRUE(shown.value_or(true)) << moment.declared_at << ": moment '" << moment.name
                                    << "' does not show what its name says (its shows function returned false)";
  HeadlessRenderer renderer(frame_width, frame_height, parse_theme(moment.theme));
  const Image actual = renderer.render(*at.lesson, at.framing);

  const std::string golden = std::string(FRICTIONLAB_SNAPSHOTS) + "/" + param.name() + ".png";
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
    write_png(actual, (failures / (param.name() + ".actual.png")).string());
    if (result.same_size) write_png(result.diff, (failures / (param.name() + ".diff.png")).string());
  }
  ASSERT_TRUE(result.same_size) << "the picture is " << actual.width << "x" << actual.height << ", the golden "
                                << expected.width << "x" << expected.height;
  EXPECT_LE(result.differing_fraction(), 0.001)
      << result.differing_pixels << " pixels differ by more than 8 (largest " << result.largest_channel_difference
      << "); the picture and a diff are in " << FRICTIONLAB_SNAPSHOT_FAILURES;
}

INSTANTIATE_TEST_SUITE_P(Lessons, Snapshot, ::testing::ValuesIn(every_moment()),
                         [](const ::testing::TestParamInfo<LessonMoment>& moment) { return moment.param.name(); });

class LessonMoments : public ::testing::TestWithParam<std::string> {};

TEST_P(LessonMoments, AreDeclaredWithOneReadmeFrame) {
  const std::string& name = GetParam();
  const lessons::Lesson lesson(lessons::resolve_lesson(name));
  EXPECT_FALSE(lesson.moments().empty()) << name << ": a built-in lesson declares its teaching moments, as in lesson{ "
                                         << "moments = { { \"sticking\", at = 0.5 } } }";
  int readme = 0;
  for (const lessons::Moment& moment : lesson.moments()) readme += moment.readme ? 1 : 0;
  EXPECT_EQ(readme, 1) << name << ": one moment is the README's frame, with readme = true";
}

INSTANTIATE_TEST_SUITE_P(Lessons, LessonMoments, ::testing::ValuesIn(every_lesson()),
                         [](const ::testing::TestParamInfo<std::string>& name) { return name.param; });

// A moment is a picture for a class: its theory table shows no row the lesson fails. A row
// read "at the end" before the end has no answer yet (terrain's hack box at 2.5 s on 15° was
// read early, with more of its launch left than the end's allowance, and showed ✗).
TEST(LessonMomentsTables, ShowNoFailingRow) {
  for (const LessonMoment& moment : every_moment()) {
    ASSERT_TRUE(moment.broken.empty()) << moment.broken;
    LessonAt at(moment.lesson, moment.moment.set, moment.moment.at);
    for (const lessons::ExpectationResult& row : at.lesson->expectations()) {
      EXPECT_FALSE(row.failed) << moment.name() << ": " << row.name << " raised an error";
      EXPECT_TRUE(!row.measured_yet || row.passes || row.hand_pulled)
          << moment.name() << ": " << row.name << " fails at " << moment.moment.at << " s (predicted "
          << (row.numeric ? std::to_string(row.predicted) : row.predicted_text) << ", measured "
          << (row.numeric ? std::to_string(row.measured) : row.measured_text) << ")";
    }
  }
}

TEST(Goldens, EachBelongsToAMomentOfALesson) {
  std::set<std::string> taken;
  for (const LessonMoment& moment : every_moment()) taken.insert(moment.name() + ".png");
  for (const fs::directory_entry& file : fs::directory_iterator(FRICTIONLAB_SNAPSHOTS)) {
    EXPECT_TRUE(taken.count(file.path().filename().string()) == 1)
        << file.path() << " is no lesson's moment: remove it, or git mv it to its moment's name";
  }
}

}  // namespace
}  // namespace frictionlab::draw
