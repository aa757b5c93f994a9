// A lesson through its interface (lessons/runtime/lesson.h): what a script says it is (title,
// question, duration, plots, the contact solver's passes, kept through rebuilds), its
// parameters set live or by a rebuild, a broken reload or a failing run leaving the last good
// lesson, and a plot's failing theory curve kept until it draws again. What each script
// function builds is tested with its unit: tests/lessons/test_script_world.cpp (bodies, forces,
// springs, ropes), test_handles.cpp (what a script reads), test_script_lesson.cpp (pairs,
// probes, expectations, the record), test_script_theory.cpp (theory.*); the sandbox and its
// messages in test_sandbox.cpp; the broken-script corpus (test_lesson_errors) covers the error
// messages one by one.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>

#include "lessons/runtime/catalog.h"
#include "lessons/runtime/model_card.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

double probe_now(const Lesson& lesson, const std::string& name) { return lesson.scene().probe(name).history.back(); }

// A script of a wooden `block`, 0.4 m × 0.2 m, resting on a metal `floor` (mu_s 0.5, mu_k 0.4):
// its own lesson{} line first, then the block, then `rest` (probes, plots, rows).
std::string wood_block_on_metal(const std::string& lesson_line, const std::string& rest = "\n") {
  return "\n" + lesson_line + R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor })" + rest;
}

TEST(LessonRuntime, TitleQuestionDurationAndPlotsAreRead) {
  ScriptFile script(wood_block_on_metal(R"(lesson { title = "Sliding", question = "How far?", duration = 2.5 })", R"(
probe { "x", unit = "m", function() return block.x end }
probe { "vx", unit = "m/s", function() return block.vx end }
probe { "height", unit = "m", function() return block.y end }
plot { "where", y = { "x", "height" } }
plot { "phase", x = "x", y = "vx" }
)"));
  Lesson lesson(script.path());
  EXPECT_EQ(lesson.title(), "Sliding");
  EXPECT_EQ(lesson.question(), "How far?");
  EXPECT_EQ(lesson.duration(), 2.5);
  ASSERT_EQ(lesson.plots().size(), 2u);
  EXPECT_EQ(lesson.plots()[0].x, "time");
  EXPECT_EQ(lesson.plots()[0].y, (std::vector<std::string>{"x", "height"}));
  EXPECT_EQ(lesson.plots()[1].x, "x");
  EXPECT_EQ(lesson.probe_unit("vx"), "m/s");
}

// The one line step_to, the window's run end and the rows kept at the end draw: a step reaches a
// time from half a step before it on (so the earlier of two steps as near is the one), and the
// first step to reach the duration is the one that ends the run.
TEST(LessonRuntime, AStepReachesATimeFromHalfAStepBeforeIt) {
  // h = 0.25 s and t = 1 s are exact in binary, and so is t - h/2 = 0.875 s: the boundary is
  // tested exactly, one representable number either side of it.
  const double h = 0.25, t = 1.0, half_a_step_before = t - 0.5 * h;
  EXPECT_FALSE(Lesson::step_reaches(std::nextafter(half_a_step_before, 0.0), h, t)) << "just below";
  EXPECT_TRUE(Lesson::step_reaches(half_a_step_before, h, t)) << "at: the earlier of two steps as near";
  EXPECT_TRUE(Lesson::step_reaches(std::nextafter(half_a_step_before, 2.0), h, t)) << "just past";
  EXPECT_TRUE(Lesson::step_reaches(t + 3.0 * h, h, t)) << "steps later";

  ScriptFile script(wood_block_on_metal(R"(lesson { title = "Counting", question = "How many steps?", duration = 0.5 })"));
  Lesson lesson(script.path());
  const double end = lesson.duration(), step = lesson.scene().frame_step();
  lesson.step_to(end - step);
  EXPECT_EQ(lesson.scene().frame(), 119) << "0.5 s at 240 steps a second is the 120th step";
  EXPECT_FALSE(lesson.reached(end));
  EXPECT_FALSE(lesson.first_to_reach(end));
  lesson.step();
  EXPECT_TRUE(lesson.reached(end));
  EXPECT_TRUE(lesson.first_to_reach(end)) << "the step that ends the run";
  lesson.step();
  EXPECT_TRUE(lesson.reached(end));
  EXPECT_FALSE(lesson.first_to_reach(end)) << "a step past the end";
}

// A run played on past the lesson's end (the window's Space after "the run ends here") keeps
// the rows it ended with: a row measured over the record ("time slipping in 5 s") read on a
// record gone on to 100 s said 54 s where the run's 5 s gave 3.4 s (check_the_article). A value
// changed live past the end forgets them (the rows are read as they stand again, and the window
// says the value changed); a rebuild starts afresh.
TEST(LessonRuntime, RowsArePastTheEndAsTheRunEndedWith) {
  ScriptFile script(wood_block_on_metal(R"(lesson { title = "Counting", question = "How many steps?", duration = 0.5 })", R"(
probe { "x", unit = "m", function() return block.x end }
expect { "steps recorded", predicted = function() return 0.5 * 240 end, measured = function() return #history("x") end,
         tolerance = 0 }
)"));
  Lesson lesson(script.path());
  const auto steps_recorded = [&] { return lesson.expectations().at(0).measured; };
  lesson.step_to(0.25);
  EXPECT_EQ(steps_recorded(), 60.0) << "before the end, the rows as they stand";
  EXPECT_FALSE(lesson.rows_kept_from_end().has_value());
  lesson.step_to(lesson.duration());
  EXPECT_EQ(steps_recorded(), 120.0);
  EXPECT_FALSE(lesson.rows_kept_from_end().has_value()) << "at the end itself";
  lesson.step_to(2.0);
  EXPECT_EQ(lesson.scene().probe("x").history.size(), 480u);
  EXPECT_EQ(steps_recorded(), 120.0) << "played on to 2 s";
  EXPECT_DOUBLE_EQ(lesson.rows_kept_from_end().value_or(0.0), 0.5) << "the end step's time";
  lesson.set("mu_k", 0.3);
  EXPECT_EQ(steps_recorded(), 480.0) << "a value changed live past the end";
  EXPECT_FALSE(lesson.rows_kept_from_end().has_value());
  lesson.reset();
  lesson.step_to(1.0);
  EXPECT_EQ(steps_recorded(), 120.0) << "a rebuild takes them again at its end";
}

// lesson{ velocity_iterations = N }: a scene whose contacts settle in fewer passes says so, and
// its world steps with N passes, as if they had been the settings, through every rebuild. A
// tower of three boxes dropped on the floor lands differently with 1 pass than with 8.
TEST(LessonRuntime, ALessonMaySayHowManyPassesItsContactSolverNeeds) {
  const std::string tower = R"(
local floor = ground { "floor", material = "wood" }
local low = box { "low", material = "wood", width = 0.4, height = 0.2, x = 0, y = 0.15, mass = 1 }
local middle = box { "middle", material = "wood", width = 0.4, height = 0.2, x = 0.05, y = 0.4, mass = 3 }
box { "high", material = "wood", width = 0.4, height = 0.2, x = 0.1, y = 0.65, mass = 9 }
parameter { "height_of_nothing", 1, min = 0, max = 2 }
)";
  ScriptFile declared("lesson { title = \"test\", question = \"does it work?\", velocity_iterations = 1 }\n" + tower);
  ScriptFile plain(with_heading(tower));
  const auto heights_after = [](Lesson& lesson) {
    run_for(lesson, 0.5);
    return std::array<float, 3>{lesson.scene().body("low")->GetPosition().y, lesson.scene().body("middle")->GetPosition().y,
                                lesson.scene().body("high")->GetPosition().y};
  };
  StepSettings one_pass;
  one_pass.velocity_iterations = 1;
  Lesson with_one(declared.path()), told_one(plain.path(), {}, one_pass), with_eight(plain.path());
  EXPECT_EQ(with_one.scene().settings().velocity_iterations, 1);
  EXPECT_EQ(model_card(with_one).velocity_iterations, 1);
  EXPECT_EQ(model_card(with_eight).velocity_iterations, 8);
  const auto one = heights_after(with_one), eight = heights_after(with_eight);
  EXPECT_EQ(one, heights_after(told_one));
  EXPECT_NE(one, eight);
  // A rebuild (a structural parameter, another step rate) runs the declaration again.
  with_one.set("height_of_nothing", "2");
  EXPECT_EQ(with_one.scene().settings().velocity_iterations, 1);
  StepSettings faster;
  faster.hz = 480;
  with_one.set_settings(faster);
  EXPECT_EQ(with_one.scene().settings().velocity_iterations, 1);
  EXPECT_EQ(with_one.scene().settings().hz, 480);
}

const char* const parameter_script = R"(
lesson { title = "parameters", question = "?" }
local mass = parameter { "mass", 1.0, min = 0.1, max = 10, unit = "kg", text = "mass of the block" }
local kind = parameter { "kind", "wood", choices = { "wood", "rubber" } }
pair { kind, "asphalt" }
local floor = ground { material = "asphalt" }
local block = box { "block", material = kind, width = 0.4, height = 0.2, on = floor, mass = mass }
force { "pull", on = block, force = { 4, 0 } }
probe { "x", unit = "m", function() return block.x end }
)";

TEST(LessonParameters, DefaultsOverridesChoicesAndPresets) {
  ScriptFile script(parameter_script);
  Lesson defaults(script.path());
  EXPECT_EQ(defaults.parameter("mass").value, 1.0);
  EXPECT_EQ(defaults.parameter("mass").shown(), "1 kg");
  EXPECT_EQ(defaults.parameter("kind").shown(), "wood");
  EXPECT_EQ(defaults.parameter("mu_s").value, 0.55);  // the wood–asphalt preset
  EXPECT_TRUE(defaults.parameter("mass").structural);
  EXPECT_FALSE(defaults.parameter("mu_s").structural);

  Lesson chosen(script.path(), {{"mass", "2.5"}, {"kind", "rubber"}, {"mu_k", "0.3"}});
  EXPECT_NEAR(chosen.scene().body("block")->GetMass(), 2.5, 1e-5);
  EXPECT_EQ(chosen.parameter("kind").shown(), "rubber");
  EXPECT_EQ(chosen.scene().pairs().pair("rubber", "asphalt").mu_k, 0.3);

  const std::string range = error_of([&] { Lesson(script.path(), {{"mass", "50"}}); });
  EXPECT_NE(range.find("--set mass = 50 kg is outside the allowed range [0.1, 10]"), std::string::npos) << range;
  const std::string unknown = error_of([&] { Lesson(script.path(), {{"mas", "2"}}); });
  EXPECT_NE(unknown.find("has no parameter of that name; its parameters: mass, kind, mu_s, mu_k, c, b"),
            std::string::npos) << unknown;
  const std::string choice = error_of([&] { Lesson(script.path(), {{"kind", "steel"}}); });
  EXPECT_NE(choice.find("kind=steel: not one of the choices wood, rubber"), std::string::npos) << choice;
  const std::string text = error_of([&] { Lesson(script.path(), {{"mass", "2kg"}}); });
  EXPECT_NE(text.find("mass=2kg: not a number"), std::string::npos) << text;
}

// A number set (the window's sliders, presets and mystery set numbers) reaches the lesson as the
// double it is, never written out and read back, through every rebuild. 1e-310 is a double (a
// subnormal one) inside c's range [0, 1000], but its text is refused (strtod cannot read it
// exactly): a number that went through text on its way would be refused too, or dropped with a
// warning by the next rebuild.
TEST(LessonParameters, ANumberIsSetAsTheDoubleItIsThroughRebuilds) {
  ScriptFile script(parameter_script);
  Lesson lesson(script.path());
  const double tiny = 1e-310;
  const std::string as_text = error_of([&] { lesson.set("c", "1e-310"); });
  EXPECT_NE(as_text.find("c=1e-310: too close to 0 for a double to hold"), std::string::npos) << as_text;
  lesson.set("c", tiny);
  EXPECT_EQ(lesson.parameter("c").value, tiny);
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "asphalt").c, tiny);
  lesson.set("mass", 2.5);  // structural: the script runs again, with both numbers
  EXPECT_EQ(lesson.parameter("c").value, tiny);
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "asphalt").c, tiny);
  EXPECT_TRUE(lesson.warnings().empty());
  // A choice by its place in the list, as Parameter::value holds it; a place between two is none.
  lesson.set("kind", 1.0);
  EXPECT_EQ(lesson.parameter("kind").shown(), "rubber");
  const std::string between = error_of([&] { lesson.set("kind", 0.5); });
  EXPECT_NE(between.find("kind = 0.5: not the place of one of the choices wood, rubber (0 to 1)"), std::string::npos) << between;
  // Out of range, as the text says it.
  const std::string range = error_of([&] { lesson.set("mass", 50.0); });
  EXPECT_NE(range.find("mass = 50 kg is outside the allowed range [0.1, 10]"), std::string::npos) << range;
}

// A choice the window set is kept by its name, not its place: a student who put "ice" before
// "rubber" in the list and saved had the lesson silently run on ice; with "rubber" gone it ran
// on ice again, with no word. By name, the choice stays, or the warning says it no longer fits.
TEST(LessonParameters, AChoiceSetByTheWindowIsKeptByItsNameWhenTheScriptsListChanges) {
  ScriptFile script(parameter_script);
  Lesson lesson(script.path());
  lesson.set("kind", 1.0);  // the slider's place: rubber
  ASSERT_EQ(lesson.parameter("kind").shown(), "rubber");
  const std::string list = "choices = { \"wood\", \"rubber\" }";
  const auto with_choices = [&](const std::string& choices) {
    std::string text = parameter_script;
    return text.replace(text.find(list), list.size(), choices);
  };
  script.rewrite(with_choices("choices = { \"wood\", \"ice\", \"rubber\" }"));
  ASSERT_TRUE(lesson.reload()) << lesson.last_error();
  EXPECT_EQ(lesson.parameter("kind").shown(), "rubber");
  EXPECT_TRUE(lesson.warnings().empty());
  script.rewrite(with_choices("choices = { \"wood\", \"ice\" }"));
  ASSERT_TRUE(lesson.reload()) << lesson.last_error();
  EXPECT_EQ(lesson.parameter("kind").shown(), "wood");
  ASSERT_EQ(lesson.warnings().size(), 1u);
  EXPECT_NE(lesson.warnings().front().find("kind was set to rubber, which no longer fits; it is back to wood"), std::string::npos)
      << lesson.warnings().front();
}

TEST(LessonParameters, ACoefficientChangesTheRunningLessonAndAStructuralOneRebuildsIt) {
  ScriptFile script(parameter_script);
  Lesson lesson(script.path());
  // 4 N against mu_s·N = 0.55·9.81 = 5.4 N: it holds.
  lesson.set("mu_k", "0.3");
  run_for(lesson, 0.5);
  const double held = probe_now(lesson, "x");
  EXPECT_NEAR(held, 0.0, 1e-6);
  // Lowering mu_s below 4 N / N lets it go without starting over.
  lesson.set("mu_s", "0.35");
  EXPECT_NEAR(lesson.scene().time(), 0.5, 1e-9);
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "asphalt").mu_s, 0.35);
  run_for(lesson, 0.5);
  EXPECT_GT(probe_now(lesson, "x"), held + 0.01);
  // The mass is built into the scene: changing it starts over from t = 0.
  lesson.set("mass", "3");
  EXPECT_EQ(lesson.scene().time(), 0.0);
  EXPECT_NEAR(lesson.scene().body("block")->GetMass(), 3.0, 1e-5);
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "asphalt").mu_s, 0.35);  // kept through the rebuild
  // A bad value changes nothing.
  EXPECT_NE(error_of([&] { lesson.set("mu_s", "-1"); }).find("[0, 2]"), std::string::npos);
  EXPECT_EQ(lesson.parameter("mu_s").value, 0.35);
}

// A duration function is the sliders' (lesson.md): it is called once, not at each read, and
// again after a slider read inside it moves. tipping_box's integrates the tipping in 1 ms steps,
// and a rehearsal that called it at every one of 8 400 steps took 13 s at its lowest push rate.
TEST(LessonParameters, ADurationFunctionIsReadOnceUntilAValueChanges) {
  ScriptFile script(R"(
local calls = 0
lesson { title = "counted", question = "?", duration = function() calls = calls + 1; return 1 + param.mu_s end }
pair { "wood", "asphalt" }
local floor = ground { material = "asphalt" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor }
expect { "duration calls", predicted = 0, tolerance = 1e9, measured = function() return calls end }
)");
  Lesson lesson(script.path());
  const auto calls = [&] {
    for (const ExpectationResult& row : lesson.expectations()) {
      if (row.name == "duration calls") return row.measured;
    }
    return -1.0;
  };
  const double before = calls();
  for (int i = 0; i < 100; ++i) EXPECT_DOUBLE_EQ(lesson.duration(), 1.55);  // the wood–asphalt preset's mu_s
  run_for(lesson, 0.5);
  EXPECT_LE(calls() - before, 1.0);
  lesson.set("mu_s", "0.7");
  EXPECT_DOUBLE_EQ(lesson.duration(), 1.7);
  const double after = calls();
  for (int i = 0; i < 100; ++i) lesson.duration();
  EXPECT_EQ(calls(), after);
}

// A block at rest on a slope with nothing but gravity on it is let sleep (Scene's rest); a
// slider lowering mu_s below tan θ must still set it sliding in the running lesson.
TEST(LessonParameters, ACoefficientChangeWakesABlockRestingOnStaticFriction) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.6, mu_k = 0.4 }
ground { material = "metal" }
local slope = incline { "slope", material = "metal", angle = 20, length = 6 }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = slope, at = 5 }
probe { "x", unit = "m", read = { block, "x" } }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 0.5);  // tan 20° = 0.36 < 0.6: it holds, and rests
  EXPECT_FALSE(lesson.scene().body("block")->IsAwake());
  const double held = probe_now(lesson, "x");
  lesson.set("mu_k", "0.1");
  lesson.set("mu_s", "0.2");
  run_for(lesson, 0.5);
  EXPECT_LT(probe_now(lesson, "x"), held - 0.1);  // g·(sin 20° − 0.1·cos 20°)·0.5²/2·cos 20° = 0.28 m back
}

TEST(LessonParameters, ACoefficientReadWhileBuildingRebuildsTheScene) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local held_by = param.mu_s * 9.81   -- read at the top: the scene depends on it
local floor = ground { material = "metal" }
box { "block", material = "wood", width = 0.4, height = 0.2, on = floor }
)"));
  Lesson lesson(script.path());
  EXPECT_TRUE(lesson.parameter("mu_s").structural);
  EXPECT_FALSE(lesson.parameter("mu_k").structural);
  run_for(lesson, 0.25);
  lesson.set("mu_s", "0.6");
  EXPECT_EQ(lesson.scene().time(), 0.0);
  lesson.step();
  lesson.set("mu_k", "0.3");
  EXPECT_GT(lesson.scene().time(), 0.0);
}

TEST(LessonReload, ABrokenEditKeepsTheLastGoodLessonRunning) {
  ScriptFile script(with_heading(R"(
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, velocity = { 1, 0 } }
probe { "x", unit = "m", function() return block.x end }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 0.1);
  script.rewrite(with_heading("local floor = ground { material = \"metal\" \n"));  // unfinished edit
  EXPECT_FALSE(lesson.reload());
  EXPECT_NE(lesson.last_error().find(script.path() + ":3:"), std::string::npos) << lesson.last_error();
  // Still the old lesson, still running.
  EXPECT_NEAR(lesson.scene().time(), 0.1, 1e-9);
  lesson.step();
  EXPECT_GT(lesson.scene().time(), 0.1);
  EXPECT_EQ(lesson.scene().probes().size(), 1u);
  // The fixed file is picked up.
  script.rewrite(R"(lesson { title = "fixed", question = "?" }
pair { "wood", "metal", mu_s = 0.5, mu_k = 0.4 }
local floor = ground { material = "metal" }
)");
  EXPECT_TRUE(lesson.reload());
  EXPECT_EQ(lesson.title(), "fixed");
  EXPECT_EQ(lesson.scene().time(), 0.0);
  EXPECT_TRUE(lesson.last_error().empty());
}

TEST(LessonReload, ValuesOfParametersThatAreGoneAreForgotten) {
  ScriptFile script(with_heading("local m = parameter { \"mass\", 1, min = 0.5, max = 2 }\n"));
  Lesson lesson(script.path(), {{"mass", "1.5"}});
  script.rewrite(with_heading("local w = parameter { \"width\", 1, min = 0.5, max = 2 }\n"));
  EXPECT_TRUE(lesson.reload()) << lesson.last_error();
  EXPECT_EQ(lesson.parameters().size(), 1u);
  // And a value for a parameter the edit keeps is kept.
  lesson.set("width", "0.75");
  script.rewrite(with_heading("local w = parameter { \"width\", 1, min = 0.5, max = 2 }\nlocal x = 1\n"));
  EXPECT_TRUE(lesson.reload());
  EXPECT_EQ(lesson.parameter("width").value, 0.75);
}

// The revision names what a whole run depends on (what the plots' planned axes are kept by): a
// new one for a value set, the script read again or other step settings, the same through steps
// and a reset, and never one another lesson has had.
TEST(LessonRevision, ChangesWithTheTextTheValuesAndTheSettingsOnly) {
  ScriptFile script(with_heading("local m = parameter { \"mass\", 1, min = 0.5, max = 2 }\n"));
  Lesson lesson(script.path());
  const Lesson other(script.path());
  EXPECT_NE(lesson.revision(), other.revision()) << "two lessons of one script";
  std::uint64_t before = lesson.revision();
  lesson.step_to(0.1);
  lesson.reset();
  EXPECT_EQ(lesson.revision(), before) << "a run and a reset change nothing it depends on";
  lesson.set("mass", "1.5");
  EXPECT_NE(lesson.revision(), before) << "a value set";
  before = lesson.revision();
  EXPECT_THROW(lesson.set("mass", "5"), InvalidInput);
  EXPECT_EQ(lesson.revision(), before) << "a value refused changes nothing";
  StepSettings settings;
  settings.hz = 120;
  lesson.set_settings(settings);
  EXPECT_NE(lesson.revision(), before) << "other step settings";
  before = lesson.revision();
  script.rewrite(with_heading("local m = parameter { \"mass\", 1, min = 0.5, max = 2 }\nlocal x = 1\n"));
  ASSERT_TRUE(lesson.reload()) << lesson.last_error();
  EXPECT_NE(lesson.revision(), before) << "the script read again";
  EXPECT_NE(lesson.revision(), other.revision());
}

TEST(LessonReload, AFailedReloadKeepsTheSliderValuesAndANarrowerRangeDropsThem) {
  ScriptFile script(with_heading("local m = parameter { \"mass\", 1, min = 0.5, max = 10 }\n"));
  Lesson lesson(script.path(), {{"mass", "5"}});
  // A broken edit that also drops the parameter: the failed reload must not forget the 5.
  script.rewrite(with_heading("plot { \"nothing\", y = \"missing\" }\n"));
  EXPECT_FALSE(lesson.reload());
  lesson.reset();
  EXPECT_EQ(lesson.parameter("mass").value, 5.0);
  // The range narrowed under the slider: the lesson reloads, at the default, and says why.
  script.rewrite(with_heading("local m = parameter { \"mass\", 1, min = 0.5, max = 2 }\n"));
  EXPECT_TRUE(lesson.reload()) << lesson.last_error();
  EXPECT_EQ(lesson.parameter("mass").value, 1.0);
  ASSERT_EQ(lesson.warnings().size(), 1u);
  EXPECT_NE(lesson.warnings()[0].find("mass was set to 5, which no longer fits; it is back to 1"), std::string::npos)
      << lesson.warnings()[0];
}

TEST(LessonReload, AnErrorWhileRunningStopsTheLessonUntilItIsReset) {
  ScriptFile script(with_heading(R"(
probe { "fragile", function() if time() > 0.1 then return nil end return 1 end }
)"));
  Lesson lesson(script.path());
  const std::string message = error_of([&] { run_for(lesson, 0.2); });
  EXPECT_NE(message.find(script.path() + ":3: probe 'fragile' returned nil at t = 0.1"), std::string::npos) << message;
  EXPECT_TRUE(lesson.failed());
  const double stopped_at = lesson.scene().time();
  lesson.step();  // does nothing: the lesson waits for a reset or a reload
  EXPECT_EQ(lesson.scene().time(), stopped_at);
  lesson.reset();
  EXPECT_FALSE(lesson.failed());
  EXPECT_EQ(lesson.scene().time(), 0.0);
}

// A plot's theory curve that fails on a value a slider gives it (not at load): the chart shows
// the message, and the lesson keeps it for whoever shows the script (the web page's editor)
// until the curve draws again.
TEST(LessonRuntime, ATheoryCurveFailingOnASlidersValueIsKeptUntilItDrawsAgain) {
  std::ifstream in(resolve_lesson("push"));
  const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string sticking = "function(F) if F <= math.max(param.mu_s, param.mu_k) * N then return -F end end";
  ASSERT_NE(original.find(sticking), std::string::npos);
  std::string text = original;
  text.replace(text.find(sticking), sticking.size(),
               "function(F) if param.mu_s > 0.5 then error(\"the theory broke\") end if F <= param.mu_s * N then return -F end end");
  const ScriptFile script(text);
  Lesson lesson(script.path());
  const std::size_t plot = 0;  // friction against the lesson's push
  ASSERT_EQ(lesson.plots().at(plot).title, "Friction against the lesson's push");
  lesson.theory_samples(plot, 0.0, 10.0, 50);
  EXPECT_EQ(lesson.theory_error(), "");
  lesson.set("mu_s", "0.6");
  EXPECT_THROW(lesson.theory_samples(plot, 0.0, 10.0, 50), ScriptError);
  const std::string error = lesson.theory_error();
  EXPECT_EQ(error.rfind(script.path() + ":", 0), 0u) << error;
  EXPECT_NE(error.find("the theory broke"), std::string::npos) << error;
  lesson.set("mu_s", "0.4");
  lesson.theory_samples(plot, 0.0, 10.0, 50);
  EXPECT_EQ(lesson.theory_error(), "");
}

}  // namespace
}  // namespace frictionlab::lessons
