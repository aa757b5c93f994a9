// The built-in lessons meet their expectations at their defaults and on both sides of each
// threshold they teach: breakaway with either block, sticking below and sliding above the
// critical angle, tipping above and sliding below d/(2·mu_s), the regularized law jittering
// past its stability boundary and settling below it.
#include <gtest/gtest.h>

#include "lesson_scripts.h"
#include "lessons/runtime/catalog.h"
#include "physics/closed_forms.h"

namespace frictionlab::lessons {
namespace {

struct Case {
  std::string lesson;
  std::map<std::string, std::string> settings;
  std::string outcome;  // the word the lesson's first word expectation must show, if any
  double hz = 240.0;    // the step rate the lesson runs at
};

std::ostream& operator<<(std::ostream& out, const Case& c) {
  out << c.lesson;
  for (const auto& [name, value] : c.settings) out << ' ' << name << '=' << value;
  if (c.hz != 240.0) out << " at " << c.hz << " Hz";
  return out;
}

class BuiltinLesson : public ::testing::TestWithParam<Case> {};

TEST_P(BuiltinLesson, MeetsEveryExpectation) {
  const Case& c = GetParam();
  StepSettings rate;
  rate.hz = c.hz;
  Lesson lesson(resolve_lesson(c.lesson), c.settings, rate);
  run_for(lesson, lesson.duration());
  const std::vector<ExpectationResult> rows = lesson.expectations();
  ASSERT_FALSE(rows.empty());
  for (const ExpectationResult& row : rows) {
    EXPECT_TRUE(row.passes) << row.name << ": predicted " << (row.numeric ? std::to_string(row.predicted) : row.predicted_text)
                            << ", measured " << (row.numeric ? std::to_string(row.measured) : row.measured_text)
                            << ", tolerance " << row.tolerance;
    if (!row.numeric && !c.outcome.empty()) {
      EXPECT_EQ(row.measured_text, c.outcome) << row.name;
    }
  }
}

// atan(0.6) = 30.96°; atan(0.3) = 16.70°. d/(2 mu_s) = 0.5 m for the default box, 1.0 m when
// it is 1 m wide.
INSTANTIATE_TEST_SUITE_P(
    AtTheirDefaultsAndAcrossTheirThresholds, BuiltinLesson,
    ::testing::Values(Case{"spring_pull", {}, ""}, Case{"spring_pull", {{"block", "plastic"}}, ""},
                      Case{"spring_pull", {{"k", "200"}, {"pull_speed", "0.2"}, {"mass", "2"}}, ""},
                      Case{"spring_pull", {{"mu_s", "0.8"}, {"mu_k", "0.3"}}, ""},
                      Case{"incline", {}, "slides"}, Case{"incline", {{"angle", "29"}}, "sticks"},
                      Case{"incline", {{"angle", "33"}}, "slides"},
                      // 2·eps/(mu_s·g·cos 20°) = 0.72 ms for eps = 2 mm/s: 240 Hz (4.2 ms) is past it,
                      // 20 mm/s (7.2 ms) is not.
                      Case{"where_methods_fail", {}, "jitters"},
                      Case{"where_methods_fail", {{"small_epsilon", "0.02"}}, "settles"},
                      Case{"where_methods_fail", {{"small_epsilon", "0.0005"}, {"angle", "5"}}, "jitters"},
                      // Just past the boundary the speed swings about its creep speed without
                      // crossing zero: still jitter. Just inside it, it settles.
                      Case{"where_methods_fail", {}, "jitters", 480},
                      Case{"where_methods_fail", {}, "jitters", 1380},
                      Case{"where_methods_fail", {}, "settles", 1400},
                      Case{"where_methods_fail", {{"angle", "30"}}, "jitters"},
                      // mu_k = 0.1 < tan 20°: an overshoot past epsilon breaks the block away.
                      Case{"where_methods_fail", {{"mu_k", "0.1"}}, "jitters"},
                      // mu_s = 0: the regularized law has no creep speed and no boundary there;
                      // stick-slip still holds on mu_k = 0.5 > tan 20°, or slides with mu_k = 0.
                      Case{"where_methods_fail", {{"mu_s", "0"}}, "no theory: μs ≤ tan θ"},
                      Case{"where_methods_fail", {{"mu_s", "0"}, {"mu_k", "0"}}, ""},
                      Case{"incline", {{"angle", "20"}, {"mu_s", "0.3"}, {"mu_k", "0.2"}}, "slides"},
                      Case{"incline", {{"angle", "15"}, {"mu_s", "0.3"}, {"mu_k", "0.2"}}, "sticks"},
                      Case{"incline", {{"angle", "45"}, {"c", "2"}, {"mass", "0.5"}}, "slides"},
                      Case{"tipping_box", {}, "tips"}, Case{"tipping_box", {{"push_height", "0.45"}}, "slides"},
                      Case{"tipping_box", {{"push_height", "0.55"}}, "tips"},
                      Case{"tipping_box", {{"width", "1"}, {"push_height", "0.9"}}, "slides"},
                      Case{"tipping_box", {{"mu_s", "0.8"}, {"mu_k", "0.6"}, {"push_height", "0.35"}}, "tips"}));

TEST(BuiltinLessons, AreListedInTeachingOrderAndResolveToTheirScripts) {
  EXPECT_EQ(builtin_lessons(), (std::vector<std::string>{"spring_pull", "incline", "tipping_box", "where_methods_fail"}));
  for (const std::string& name : builtin_lessons()) {
    EXPECT_NO_THROW(Lesson{resolve_lesson(name)}) << name;
  }
  const std::string unknown = error_of([] { resolve_lesson("spring_push"); });
  EXPECT_NE(unknown.find("unknown lesson 'spring_push'; built-in lessons: spring_pull, incline, tipping_box, where_methods_fail"),
            std::string::npos) << unknown;
}

TEST(BuiltinLessons, NameTheBodiesParametersAndProbesTheIssueAsksFor) {
  struct Expected {
    std::string lesson, body;
    std::vector<std::string> parameters, probes;
  };
  const Expected expected[] = {
      {"spring_pull", "block", {"mu_s", "mu_k", "c", "mass", "k", "pull_speed", "block"}, {"spring_force", "friction_force"}},
      {"incline", "block", {"angle", "mu_s", "mu_k", "c", "mass"}, {"distance", "speed"}},
      {"tipping_box", "box", {"push_height", "push_rate", "mu_s", "mu_k", "width", "height", "mass"}, {"tilt", "slide"}},
  };
  for (const Expected& e : expected) {
    Lesson lesson(resolve_lesson(e.lesson));
    EXPECT_NO_THROW(lesson.scene().body(e.body)) << e.lesson;
    for (const std::string& name : e.parameters) EXPECT_NO_THROW(lesson.parameter(name)) << e.lesson << ' ' << name;
    for (const std::string& name : e.probes) EXPECT_NO_THROW(lesson.scene().probe(name)) << e.lesson << ' ' << name;
  }
}

TEST(BuiltinLessons, TippingBoxTiltsAndSlidesAsItsProbesSay) {
  // Pushed high it tips: the tilt grows past 10° and the front corner stays put; pushed low it
  // slides: no tilt and the corner moves.
  Lesson high(resolve_lesson("tipping_box"), {{"push_height", "0.8"}});
  const double end = high.duration();
  do {
    high.step();
  } while (high.scene().probe("tilt").history.back() < 10.0 && high.scene().time() < end);
  EXPECT_GE(high.scene().probe("tilt").history.back(), 10.0);
  EXPECT_LT(std::abs(high.scene().probe("slide").history.back()), 0.002);
  Lesson low(resolve_lesson("tipping_box"), {{"push_height", "0.2"}});
  run_for(low, low.duration());
  EXPECT_LT(std::abs(low.scene().probe("tilt").history.back()), 1.0);
  EXPECT_GT(low.scene().probe("slide").history.back(), 0.05);
}

TEST(BuiltinLessons, WhereMethodsFailStepsItsThreeBlocksEachWithItsOwnTreatment) {
  // Box2D bodies, not 1-DOF probes: the stick-slip block holds, the large-epsilon one creeps
  // a visible 4.5 cm in 1.5 s at eps·tan 20°/mu_s, and the run's treatment (box2d here) does
  // not reach pairs that name their own.
  StepSettings run_box2d;
  run_box2d.treatment = FrictionTreatment::box2d;
  for (const StepSettings& settings : {StepSettings{}, run_box2d}) {
    Lesson lesson(resolve_lesson("where_methods_fail"), {}, settings);
    const Scene& scene = lesson.scene();
    const PairTable& pairs = scene.pairs();
    const int slope = pairs.material_id("slope");
    EXPECT_EQ(scene.friction().treatment_of(pairs.material_id("block"), slope), FrictionTreatment::stick_slip);
    EXPECT_EQ(scene.friction().treatment_of(pairs.material_id("creeping_block"), slope), FrictionTreatment::regularized);
    EXPECT_EQ(scene.friction().epsilon_of(pairs.material_id("creeping_block"), slope), 0.05);
    EXPECT_EQ(scene.friction().epsilon_of(pairs.material_id("jittering_block"), slope), 0.002);
    const b2Vec2 block = scene.body("block")->GetPosition();
    const b2Vec2 creeping = scene.body("creeping")->GetPosition();
    run_for(lesson, 1.5);
    EXPECT_LT((scene.body("block")->GetPosition() - block).Length(), 1e-6f);
    const double creep = 0.05 * std::tan(20.0 * M_PI / 180.0) / 0.6;
    EXPECT_NEAR(scene.probe("large_epsilon_speed").history.back(), creep, 0.01 * creep);
    EXPECT_GT((scene.body("creeping")->GetPosition() - creeping).Length(), 0.04f);
  }
}

TEST(BuiltinLessons, WhereMethodsFailsSlidersReachEveryBlock) {
  // The regularized pairs take mu_s from the stick-slip pair: the live slider changes the
  // creep speed of the block beside it at the next step.
  Lesson lesson(resolve_lesson("where_methods_fail"));
  run_for(lesson, 1.0);
  lesson.set("mu_s", "1.2");
  run_for(lesson, 2.0);
  const double creep = 0.05 * std::tan(20.0 * M_PI / 180.0) / 1.2;
  EXPECT_NEAR(lesson.scene().probe("large_epsilon_speed").history.back(), creep, 0.01 * creep);
}

}  // namespace
}  // namespace frictionlab::lessons
