// The lesson part of the script API (lessons/runtime/script_lesson.cpp). What the runtime works
// out itself each step, without a call into the script: a driven body's path given as numbers
// (a motion), a position read in another body's axes (relative_to), a probe that reads a list
// of samples a model worked out once, and a pair's coefficient given as a schedule, each checked
// against the formula it stands for and against the script function it replaces. And what a
// script declares: a pair's sliders (or none), its coefficients as functions of time, the
// presets' pairs; the record read back (history, value_at), every_step, and expectations in
// numbers and words.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "lessons/runtime/model_card.h"
#include "physics/closed_forms.h"
#include "physics/scenarios.h"
#include "tests/assertions.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

constexpr double g = standard_gravity;
constexpr double degrees = std::numbers::pi / 180.0;

double probe_now(const Lesson& lesson, const std::string& name) { return lesson.scene().probe(name).history.back(); }

// offset + speed·t + ½·acceleration·t² + swing·sin(omega·t + phase)
double motion(double t, double offset, double speed, double acceleration, double swing, double omega, double phase) {
  return offset + speed * t + 0.5 * acceleration * t * t + swing * std::sin(omega * t + phase);
}

const char* const plank_world = R"(
local plank = box { "plank", material = "wood", kind = "kinematic", width = 2, height = 0.1, x = 0.3, y = 1.5 }
)";

TEST(ScriptFreeReadings, AMotionGivenAsNumbersIsTheDrivenBodysPath) {
  ScriptFile script(with_heading(std::string(plank_world) + R"(
drive { plank, position = { x = { offset = 0.3, speed = 0.2, acceleration = 0.4, swing = 0.1, omega = 3, phase = 0.5 },
                            y = 1.5 },
        angle = { swing = 10, omega = 2 } }
)"));
  Lesson lesson(script.path());
  const double h = 1.0 / 240.0;
  run_for(lesson, 1.0);
  const double t = lesson.scene().time();
  const b2Body* plank = lesson.scene().body("plank");
  // Where the path says, to float precision: an offset of 0.3 and a swing of 0.1 at t = 0 are
  // 0.3479 m, so the body was moved from where box{} put it.
  EXPECT_NEAR(plank->GetPosition().x, motion(t, 0.3, 0.2, 0.4, 0.1, 3.0, 0.5), 2e-6);
  EXPECT_NEAR(plank->GetPosition().y, 1.5, 1e-6);
  EXPECT_NEAR(plank->GetAngle(), motion(t, 0.0, 0.0, 0.0, 10.0, 2.0, 0.0) * degrees, 2e-6);
  // Its velocity over the step just taken is the path's change over it.
  const double vx = (motion(t, 0.3, 0.2, 0.4, 0.1, 3.0, 0.5) - motion(t - h, 0.3, 0.2, 0.4, 0.1, 3.0, 0.5)) / h;
  EXPECT_NEAR(plank->GetLinearVelocity().x, vx, 1e-4);
  const double omega = (std::sin(2.0 * t) - std::sin(2.0 * (t - h))) * 10.0 * degrees / h;
  EXPECT_NEAR(plank->GetAngularVelocity(), omega, 1e-4);
}

TEST(ScriptFreeReadings, AMotionMovesABodyAsTheSameFunctionOfTimeDoes) {
  // A block carried on a shaken, tilting plank: the same path given as numbers and as a
  // function must give the same run (the function is worked out in Lua, the motion in C++,
  // both in doubles).
  const std::string block = R"(
pair { "wood", "wood", mu_s = 0.4, mu_k = 0.3 }
local block = box { "block", material = "wood", width = 0.2, height = 0.1, on = plank, at = 0.2 }
)";
  ScriptFile as_numbers(with_heading(std::string(plank_world) + block + R"(
drive { plank, position = { x = { offset = 0.3, swing = 0.05, omega = 12 }, y = { offset = 1.5, speed = 0.1 } },
        angle = { speed = 3 } }
)"));
  ScriptFile as_function(with_heading(std::string(plank_world) + block + R"(
drive { plank, position = function(t) return 0.3 + 0.05 * math.sin(12 * t), 1.5 + 0.1 * t end,
        angle = function(t) return 3 * t end }
)"));
  Lesson numbers(as_numbers.path()), function(as_function.path());
  run_for(numbers, 2.0);
  run_for(function, 2.0);
  const b2Body* a = numbers.scene().body("block");
  const b2Body* b = function.scene().body("block");
  EXPECT_NEAR(a->GetPosition().x, b->GetPosition().x, 1e-6);
  EXPECT_NEAR(a->GetPosition().y, b->GetPosition().y, 1e-6);
  EXPECT_NEAR(a->GetLinearVelocity().x, b->GetLinearVelocity().x, 1e-5);
  // And it did move: shaken at 0.05·144 = 7.2 m/s², past μs·g, the block slips on the plank.
  EXPECT_GT(std::abs(a->GetPosition().x - 0.5), 1e-3);
}

TEST(ScriptFreeReadings, AMotionsFieldsAreChecked) {
  const auto refused = [](const std::string& drive) { return error_building(with_heading(std::string(plank_world) + drive)); };
  EXPECT_NE(refused("drive { plank, position = { x = { swng = 1 } } }\n").find("drive 'plank': position: x"), std::string::npos);
  EXPECT_NE(refused("drive { plank, position = { x = { swng = 1 } } }\n").find("swng"), std::string::npos);
  EXPECT_NE(refused("drive { plank, angle = \"fast\" }\n").find("angle must be a number, or a motion"), std::string::npos);
  EXPECT_NE(refused("drive { plank, position = { z = 1 } }\n").find("z"), std::string::npos);
  EXPECT_NE(refused("drive { plank, position = 2 }\n").find("position must be a function(t) returning x, y, or { x"),
            std::string::npos);
  EXPECT_NE(refused("drive { plank, angle = { omega = 1e7 } }\n").find("omega"), std::string::npos);
}

TEST(ScriptFreeReadings, APositionRelativeToAnotherBodyIsInThatBodysAxes) {
  // A post stands still while the plank moves right at 0.5 m/s and turns at 30°/s: in the
  // plank's axes the post is where rotating (post − plank) back by the plank's angle puts it.
  ScriptFile script(with_heading(std::string(plank_world) + R"(
local post = box { "post", material = "wood", kind = "static", width = 0.1, height = 0.1, x = 1, y = 0.5 }
drive { plank, position = { x = { offset = 0.3, speed = 0.5 }, y = 1.5 }, angle = { speed = 30 } }
probe { "post_x", unit = "m", read = { post, "x", relative_to = plank } }
probe { "post_y", unit = "m", read = { post, "y", relative_to = plank } }
probe { "post_back", unit = "m", read = { post, "distance", along = { -1, 0 }, relative_to = plank } }
probe { "post_back_lua", unit = "m", function()
  local a = math.rad(30 * time())
  local dx, dy = post.x - plank.x, post.y - plank.y
  return -(dx * math.cos(a) + dy * math.sin(a)) + (1 - 0.3)
end }
)"));
  Lesson lesson(script.path());
  run_for(lesson, 1.0);
  const double t = lesson.scene().time();
  const double angle = 30.0 * t * degrees;
  const double dx = 1.0 - (0.3 + 0.5 * t), dy = 0.5 - 1.5;
  const double local_x = dx * std::cos(angle) + dy * std::sin(angle);
  const double local_y = -dx * std::sin(angle) + dy * std::cos(angle);
  EXPECT_NEAR(probe_now(lesson, "post_x"), local_x, 2e-6);
  EXPECT_NEAR(probe_now(lesson, "post_y"), local_y, 2e-6);
  // Moved back along the plank since the start, when the post was 0.7 m along it.
  EXPECT_NEAR(probe_now(lesson, "post_back"), 0.7 - local_x, 2e-6);
  EXPECT_NEAR(probe_now(lesson, "post_back"), probe_now(lesson, "post_back_lua"), 2e-6);
}

TEST(ScriptFreeReadings, RelativeToIsForPositionsOfBodies) {
  const auto refused = [](const std::string& probe) {
    return error_building(with_heading(std::string(plank_world) + "local post = box { \"post\", material = \"wood\", kind = "
                                       "\"static\", width = 0.1, height = 0.1, x = 1, y = 0.5 }\n" + probe));
  };
  EXPECT_NE(refused("probe { \"v\", read = { post, \"vx\", relative_to = plank } }\n")
                .find("relative_to is for a body's x, y and distance"),
            std::string::npos);
  EXPECT_NE(refused("probe { \"x\", read = { post, \"x\", relative_to = post } }\n").find("names the body read"),
            std::string::npos);
  EXPECT_NE(refused("probe { \"x\", read = { post, \"x\", relative_to = 3 } }\n").find("relative_to must be a body"),
            std::string::npos);
}

// A list of samples 10·k at t = k·every, made longer each time it is asked for (to 1 s past
// the time asked), up to `cap` entries; `asked` counts the calls.
const char* const growing_list = R"(
asked = 0
local every = 0.1
local function list_to(t, cap)
  asked = asked + 1
  local list = {}
  for k = 1, math.min(math.floor((t + 1) / every) + 1, cap) do list[k] = 10 * (k - 1) end
  return list
end
)";

TEST(ScriptFreeReadings, SamplesAreReadAtTheProbesTimeStraightBetweenEntries) {
  ScriptFile script(with_heading(std::string(growing_list) + R"(
probe { "ramp", samples = function(t) return list_to(t, 1000) end, every = every }
probe { "ramp_late", samples = function(t) return list_to(t, 1000) end, every = every, delay = 0.05 }
probe { "held", samples = function(t) return list_to(t, 16) end, every = every }
probe { "asked", function() return asked end }
)"));
  Lesson lesson(script.path());
  for (const double until : {0.3, 1.7, 3.5}) {
    lesson.step_to(until);
    const double t = lesson.scene().time();
    // 10 per 0.1 s: 100·t, between entries too.
    EXPECT_NEAR(probe_now(lesson, "ramp"), 100.0 * t, 1e-9) << t;
    EXPECT_NEAR(probe_now(lesson, "ramp_late"), 100.0 * (t - 0.05), 1e-9) << t;
    // 16 entries reach 1.5 s: held at 150 from then on.
    EXPECT_NEAR(probe_now(lesson, "held"), 100.0 * std::min(t, 1.5), 1e-9) << t;
  }
  // Asked again only when the run passed a list's end: each list reaches 1 s further, so the
  // two ramps were asked about four times each in 3.5 s, the held one twice (its second list
  // was no longer than its first, so it was not asked again).
  EXPECT_LE(probe_now(lesson, "asked"), 12.0);
  EXPECT_GE(probe_now(lesson, "asked"), 6.0);
}

TEST(ScriptFreeReadings, SamplesThatAreNotAListOfNumbersStopTheLessonSayingWhere) {
  const auto stopped = [](const std::string& probe) {
    ScriptFile script(with_heading(probe));
    return error_of([&] {
      Lesson lesson(script.path());
      run_for(lesson, 0.5);
    });
  };
  const std::string nothing = stopped("probe { \"p\", samples = function(t) return 5 end, every = 0.1 }\n");
  EXPECT_NE(nothing.find(":2: probe 'p': samples must return a list of numbers"), std::string::npos) << nothing;
  EXPECT_NE(nothing.find("returned the number 5"), std::string::npos) << nothing;
  const std::string word = stopped("probe { \"p\", samples = function(t) return { 1, 2, \"three\", 4, 5, 6, 7 } end, "
                                   "every = 0.1 }\n");
  EXPECT_NE(word.find(":2: probe 'p': entry 3 of the samples is"), std::string::npos) << word;
  EXPECT_NE(stopped("probe { \"p\", samples = function(t) return { 1 } end }\n").find("every"), std::string::npos);
  EXPECT_NE(stopped("probe { \"p\", samples = function(t) return { 1 } end, every = 0 }\n").find("every"),
            std::string::npos);
  EXPECT_NE(stopped("probe { \"p\", samples = { 1, 2 }, every = 1 }\n").find("samples must be a function(t)"),
            std::string::npos);
  EXPECT_NE(stopped("probe { \"p\", every = 1, function() return 1 end }\n").find("every and delay go with samples"),
            std::string::npos);
  EXPECT_NE(stopped("probe { \"p\", samples = function(t) return { 1 } end, every = 1, function() return 1 end }\n")
                .find("not two"),
            std::string::npos);
}

// A function's probe may say what kind of force it measures, in the legend's words, for plots to
// draw it in that force's colour; any other word is refused with the words allowed, and a read =
// { ... } probe, whose kind the runtime knows, may not say one.
TEST(ScriptFreeReadings, AProbesForceIsAKindTheLegendNames) {
  ScriptFile stated(with_heading("probe { \"along\", unit = \"N\", force = \"friction\", function() return 1 end }\n"));
  const Lesson lesson(stated.path());
  EXPECT_EQ(lesson.probe_force("along"), ForceKind::friction);
  const auto stopped = [](const std::string& probe) {
    ScriptFile script(with_heading(probe));
    return error_of([&] { Lesson refused(script.path()); });
  };
  const std::string misspelt = stopped("probe { \"p\", force = \"frction\", function() return 1 end }\n");
  EXPECT_NE(misspelt.find(":2: probe 'p': force = \"frction\" is no kind of force; give one of applied, spring, friction, "
                          "normal, weight, rope, drag"),
            std::string::npos)
      << misspelt;
  const std::string read =
      stopped("local floor = ground { \"floor\", material = \"wood\" }\nprobe { \"p\", force = \"normal\", read = { floor, \"x\" } }\n");
  EXPECT_NE(read.find("force is known from what it reads"), std::string::npos) << read;
}

// A block pulled across a floor oiled from 0.5 s to 1.2 s: its coefficients as schedules and as
// the same functions of time give the same run, step for step, and the pair holds each value
// from its time on (the last one given for a time counts).
TEST(ScriptFreeReadings, ACoefficientsScheduleIsTheSameRunAsTheFunctionOfTime) {
  const std::string world = R"(
local floor = ground { "floor", material = "wood" }
local block = box { "block", material = "wood", width = 0.3, height = 0.1, on = floor, at = 0, mass = 1 }
force { "pull", on = block, force = { 3, 0 } }
)";
  ScriptFile as_schedule(with_heading(R"(
pair { "wood", "wood", sliders = false, mu_s = { { 0, 0.5 }, { 0.5, 0.1 }, { 1.2, 0.5 } },
       mu_k = { { 0, 0.45 }, { 0, 0.4 }, { 0.5, 0.08 }, { 1.2, 0.4 } } }
)" + world));
  ScriptFile as_function(with_heading(R"(
local function oiled(t) return t >= 0.5 and t < 1.2 end
pair { "wood", "wood", sliders = false, mu_s = function(t) return oiled(t) and 0.1 or 0.5 end,
       mu_k = function(t) return oiled(t) and 0.08 or 0.4 end }
)" + world));
  Lesson scheduled(as_schedule.path()), called(as_function.path());
  const auto coefficients = [](const Lesson& lesson) {
    const FrictionPair& pair = lesson.scene().pairs().pair("wood", "wood");
    return std::array<double, 2>{pair.mu_s, pair.mu_k};
  };
  EXPECT_EQ(coefficients(scheduled), (std::array<double, 2>{0.5, 0.4}));  // { 0, 0.4 } came last for t = 0
  const double h = 1.0 / 240.0;
  bool slid = false;
  for (int k = 0; k < 480; ++k) {
    scheduled.step();
    called.step();
    ASSERT_EQ(scheduled.scene().body("block")->GetPosition().x, called.scene().body("block")->GetPosition().x) << "step " << k;
    ASSERT_EQ(coefficients(scheduled), coefficients(called)) << "step " << k;
    // The values of the sub-step that starts at k·h.
    const double started = k * h;
    const bool oiled = started >= 0.5 - 1e-12 && started < 1.2 - 1e-12;
    EXPECT_EQ(coefficients(scheduled), (oiled ? std::array<double, 2>{0.1, 0.08} : std::array<double, 2>{0.5, 0.4}))
        << "at " << started << " s";
    slid = slid || std::abs(scheduled.scene().body("block")->GetLinearVelocity().x) > 0.1f;
  }
  EXPECT_TRUE(slid) << "the pull of 3 N never moved the block on the oiled stretch";
}

// An entry's time that a step starts at, in doubles up to the rounding of frame · step, has come
// at that step: 7.4 s at 240 Hz starts step 1776, whose start is 1776/240 = 7.3999999999999995 s.
// The entry waited a step more there, and lubricated's oil stayed a step past the instant its
// theory was given (the block stopped 3.9 mm further than theory, 2.3 mm allowed).
TEST(ScriptFreeReadings, AScheduleEntryComesAtTheStepThatStartsAtItsTime) {
  ScriptFile file(with_heading(R"(
pair { "wood", "wood", sliders = false, mu_s = { { 0, 0.5 }, { 7.4, 0.1 } }, mu_k = 0.05 }
local floor = ground { "floor", material = "wood" }
box { "block", material = "wood", width = 0.3, height = 0.1, on = floor, at = 0, mass = 1 }
)"));
  Lesson lesson(file.path());
  const double h = 1.0 / 240.0;
  ASSERT_LT(1776 * h, 7.4) << "the step's start rounds under its time: the case this test is for";
  for (int k = 0; k < 1776; ++k) lesson.step();
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "wood").mu_s, 0.5) << "the step that started at 1775/240 s";
  lesson.step();
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "wood").mu_s, 0.1) << "the step that started at 1776/240 s";
}

TEST(ScriptFreeReadings, AScheduleThatIsNotOneSaysWhereAndWhy) {
  const auto refused = [](const std::string& schedule) {
    return error_building(with_heading("pair { \"wood\", \"wood\", sliders = false, mu_s = 0.5, mu_k = " + schedule + " }\n"));
  };
  const std::string late = refused("{ { 1, 0.4 } }");
  EXPECT_NE(late.find(":2: pair wood/wood: mu_k: a schedule is a list of { time, value } pairs"), std::string::npos) << late;
  EXPECT_NE(late.find("entry 1 starts at t = 1 s, not 0"), std::string::npos) << late;
  EXPECT_NE(refused("{ { 0, 0.4 }, { 2, 0.1 }, { 1, 0.4 } }").find("entry 3 goes back in time, to 1 s after 2 s"),
            std::string::npos);
  EXPECT_NE(refused("{ { 0, 0.4 }, { 1, 3 } }").find("mu_k: entry 2 of the schedule is 3; it must be in [0, 2]"),
            std::string::npos);
  EXPECT_NE(refused("{ { 0, 0.4 }, { 1 } }").find("entry 2 must be two numbers, { time, value }; it is a table"),
            std::string::npos);
  EXPECT_NE(refused("{ { 0, 0.4 }, { 1, \"x\" } }").find("entry 2 must be two numbers, { time, value }; it is a pair that is not"),
            std::string::npos);
  EXPECT_NE(refused("{ 0, 0.4 }").find("entry 1 must be two numbers, { time, value }; it is the number 0"), std::string::npos);
  EXPECT_NE(refused("{ { 0, 0.4 } }, sliders = { \"mu_k\" }").find("mu_k changes with time (a function or a schedule)"),
            std::string::npos);
  EXPECT_NE(refused("{}").find("1 to 10000 of them"), std::string::npos);
  EXPECT_NE(refused("{ { 0, 0.4 }, { 1e6, 0.1 } }").find("past a day"), std::string::npos);
}

TEST(LessonFunctions, APairsSlidersListMakesOnlyThoseAndTheOthersKeepTheScriptsValues) {
  ScriptFile script(with_heading(R"(
pair { "wood", "ice", name = "ice", mu_s = 0.1, mu_k = 0.05, c = 2, sliders = { "mu_s", "mu_k" } }
local floor = ground { "floor", material = "ice" }
box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0 }
)"));
  Lesson lesson(script.path());
  EXPECT_NO_THROW(lesson.parameter("ice.mu_s"));
  EXPECT_NO_THROW(lesson.parameter("ice.mu_k"));
  EXPECT_THROW(lesson.parameter("ice.c"), InvalidInput);
  EXPECT_THROW(lesson.parameter("ice.b"), InvalidInput);
  lesson.set("ice.mu_k", "0.07");  // live: the pair keeps its c
  const FrictionPair& pair = lesson.scene().pairs().pair("wood", "ice");
  EXPECT_EQ(pair.mu_k, 0.07);
  EXPECT_EQ(pair.c, 2.0);
  const ScriptFile wrong(with_heading("pair { \"wood\", \"ice\", mu_s = 0.1, mu_k = 0.05, sliders = { \"mu\" } }\n"));
  EXPECT_NE(error_of([&] { Lesson broken(wrong.path()); }).find("sliders lists coefficients from mu_s, mu_k, c, b"),
            std::string::npos);
}

// A pair's sliders are made from the pair's table (physics/materials.h): each has the table's
// name, unit, range and meaning, and a value set live reaches that coefficient of the pair alone.
TEST(LessonFunctions, APairsSlidersAreTheTablesCoefficientsAndEachSetsItsOwnValue) {
  ScriptFile script(with_heading(R"(
pair { "wood", "ice", name = "ice", mu_s = 0.1, mu_k = 0.05, c = 2, b = 3 }
local floor = ground { "floor", material = "ice" }
box { "block", material = "wood", width = 0.2, height = 0.1, on = floor, at = 0 }
)"));
  Lesson lesson(script.path());
  for (const PairCoefficient& coefficient : pair_coefficients) {
    const Parameter& slider = lesson.parameter(std::string("ice.") + coefficient.name);
    EXPECT_EQ(slider.coefficient, &coefficient);
    EXPECT_EQ(slider.unit, coefficient.unit);
    EXPECT_EQ(slider.min, 0.0);
    EXPECT_EQ(slider.max, coefficient.lesson_largest);
    EXPECT_EQ(slider.text.rfind(coefficient.meaning, 0), 0u) << slider.text;
    const FrictionPair before = lesson.scene().pairs().pair("wood", "ice");
    lesson.set(slider.name, "0.0625");
    const FrictionPair after = lesson.scene().pairs().pair("wood", "ice");
    for (const PairCoefficient& other : pair_coefficients) {
      EXPECT_EQ(after.*other.value, &other == &coefficient ? 0.0625 : before.*other.value)
          << "setting " << coefficient.name << ", " << other.name;
    }
  }
}

// One parameter handed to several pairs with sliders = false: the pairs make no sliders of
// their own, keep the values handed to them (a block on each floor slides v0²/(2·mu_k·g), and
// the drag lane less far), the model card still sees every term, and moving the shared slider
// rebuilds both lanes with the new value.
TEST(LessonFunctions, PairsWithoutSlidersTakeTheScriptsValues) {
  ScriptFile script(with_heading(R"(
local mu_k = parameter { "mu_k", 0.3, min = 0.05, max = 1 }
material { "block", density = 500 }
material { "lane_a", density = 500 }
material { "lane_b", density = 500 }
pair { "block", "lane_a", mu_s = 0.5, mu_k = mu_k, sliders = false }
pair { "block", "lane_b", mu_s = 0.5, mu_k = mu_k, c = 2, sliders = false }
pair { "block", "block", mu_s = 0.5, mu_k = mu_k, sliders = false }
local a = ground { "a", material = "lane_a", y = 0.5, thickness = 0.2 }
local b = ground { "b", material = "lane_b", y = 0, thickness = 0.2 }
local on_a = box { "on_a", material = "block", width = 0.2, height = 0.1, on = a, at = 0, mass = 1, velocity = { 2, 0 } }
local on_b = box { "on_b", material = "block", width = 0.2, height = 0.1, on = b, at = 0, mass = 1, velocity = { 2, 0 } }
probe { "a_speed", unit = "m/s", read = { on_a, "vx" } }
probe { "b_speed", unit = "m/s", read = { on_b, "vx" } }
probe { "a_friction", unit = "N", read = { contact(on_a, a), "fx" } }
probe { "b_friction", unit = "N", read = { contact(on_b, b), "fx" } }
plot { "friction against speed", kind = "xy", x = { "a_speed", "b_speed" }, y = { "a_friction", "b_friction" } }
)"));
  Lesson lesson(script.path());
  std::vector<std::string> names;
  for (const Parameter& parameter : lesson.parameters()) names.push_back(parameter.name);
  EXPECT_EQ(names, std::vector<std::string>{"mu_k"});
  const ModelCard card = model_card(lesson);
  EXPECT_TRUE(card.dry);
  EXPECT_TRUE(card.viscous);
  EXPECT_FALSE(card.quadratic);
  ASSERT_EQ(lesson.plots().size(), 1u);
  EXPECT_EQ(lesson.plots()[0].x_of(0), "a_speed");
  EXPECT_EQ(lesson.plots()[0].x_of(1), "b_speed");

  const auto distances = [&lesson] {
    const b2Vec2 start_a = lesson.scene().body("on_a")->GetPosition(), start_b = lesson.scene().body("on_b")->GetPosition();
    run_for(lesson, 2.0);
    return std::pair{lesson.scene().body("on_a")->GetPosition().x - start_a.x,
                     lesson.scene().body("on_b")->GetPosition().x - start_b.x};
  };
  const auto [slid_a, slid_b] = distances();
  EXPECT_RELATIVE(slid_a, theory::slide_to_rest(2.0, 1.0, {0.5, 0.3, 0, 0}, g).distance, 0.01);
  EXPECT_RELATIVE(slid_b, theory::slide_to_rest(2.0, 1.0, {0.5, 0.3, 2, 0}, g).distance, 0.01);
  lesson.set("mu_k", "0.6");
  const auto [again_a, again_b] = distances();
  EXPECT_RELATIVE(again_a, theory::slide_to_rest(2.0, 1.0, {0.5, 0.6, 0, 0}, g).distance, 0.01);
  EXPECT_RELATIVE(again_b, theory::slide_to_rest(2.0, 1.0, {0.5, 0.6, 2, 0}, g).distance, 0.01);
}

TEST(LessonFunctions, APairsCoefficientsMayBeFunctionsOfTime) {
  // A 1 kg block pulled by 3 N on a table whose mu_s and mu_k drop from 0.5/0.45 to 0.15/0.1
  // at t = 1 s: held until then (long enough for the scene to put it to rest), it must wake
  // and slide at (3 − 0.1·g) m/s² from the first step that starts at 1 s, with no slider for
  // the coefficients that are functions (c and b keep theirs).
  ScriptFile script(with_heading(R"(
pair { "wood", "wood", mu_s = function(t) if t < 1 then return 0.5 end return 0.15 end,
                       mu_k = function(t) if t < 1 then return 0.45 end return 0.1 end }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.1, on = floor, at = 0, mass = 1 }
force { "pull", on = block, force = { 3, 0 } }
probe { "a", unit = "m/s²", read = { block, "acceleration", along = { 1, 0 } } }
probe { "v", unit = "m/s", read = { block, "vx" } }
)"));
  Lesson lesson(script.path());
  EXPECT_THROW(lesson.parameter("mu_s"), std::exception);
  EXPECT_THROW(lesson.parameter("mu_k"), std::exception);
  EXPECT_NO_THROW(lesson.parameter("c"));
  run_for(lesson, 1.0);
  EXPECT_EQ(probe_now(lesson, "v"), 0.0);
  run_for(lesson, 0.5);
  EXPECT_NEAR(probe_now(lesson, "a"), 3.0 - 0.1 * g, 1e-3);
  // The first step from t = 1 s on slides: 0.5 s of it, less nothing.
  EXPECT_NEAR(probe_now(lesson, "v"), 0.5 * (3.0 - 0.1 * g), 2e-3);

  // A block held on a 20° slope by gravity alone is put to rest by the scene; when the slope
  // is oiled at t = 1 s it must wake and slide at g·(sin θ − mu_k·cos θ).
  ScriptFile slope(with_heading(R"(
pair { "wood", "wood", mu_s = function(t) if t < 1 then return 0.5 end return 0.1 end,
                       mu_k = function(t) if t < 1 then return 0.45 end return 0.05 end }
local ramp = incline { "ramp", material = "wood", angle = 20, length = 4 }
local block = box { "block", material = "wood", width = 0.4, height = 0.1, on = ramp, at = 3, mass = 1 }
probe { "down", unit = "m/s²", read = { block, "acceleration", along = { -math.cos(math.rad(20)), -math.sin(math.rad(20)) } } }
)"));
  Lesson oiled_slope(slope.path());
  run_for(oiled_slope, 1.5);
  const double angle = 20.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(probe_now(oiled_slope, "down"), g * (std::sin(angle) - 0.05 * std::cos(angle)), 2e-3);

  // Out of range at some time: the message is placed at the function and says when.
  ScriptFile bad(with_heading(R"(
pair { "wood", "wood", mu_s = 0.5,
  mu_k = function(t) return 0.3 + t end }
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.1, on = floor, at = 0, mass = 1 }
)"));
  const std::string message = error_of([&] {
    Lesson broken(bad.path());
    run_for(broken, 2.0);
  });
  EXPECT_NE(message.find(":4: pair wood/wood: mu_k returned 2.00"), std::string::npos) << message;
  EXPECT_NE(message.find("it must be in [0, 2]"), std::string::npos) << message;

  // A function of time has no slider to list.
  ScriptFile listed(with_heading(R"(
pair { "wood", "wood", mu_s = 0.5, mu_k = function(t) return 0.3 end, sliders = { "mu_k" } }
)"));
  const std::string refused = error_of([&] { Lesson broken(listed.path()); });
  EXPECT_NE(refused.find(":3: pair wood/wood: mu_k changes with time (a function or a schedule), which no slider can set"), std::string::npos)
      << refused;
}

TEST(LessonFunctions, HistoryAndValueAtReadTheRecord) {
  ScriptFile script(with_heading(R"(
probe { "twice_t", unit = "s", function() return 2 * time() end }
expect { "steps recorded", predicted = 48, tolerance = 0, measured = function() return #history("time") end }
expect { "value at 0.1 s", predicted = 0.2, tolerance = 1e-9, measured = function() return value_at("twice_t", 0.1) end }
expect { "nearest step", predicted = 0.2, tolerance = 1e-9, measured = function() return value_at("twice_t", 0.101) end }
expect { "not yet", predicted = "nothing", measured = function() return value_at("twice_t", 5) == nil and "nothing" or "something" end }
-- Read while the run goes on, the record's columns have the same length and hold every step
-- before this one (this step's values join them when every_step is done).
local consistent = true
every_step(function(t)
  local times, twice = history("time"), history("twice_t")
  local before = t - step_length()
  consistent = consistent and #times == #twice and times[#times + 1] == nil and value_at("time", t) == nil
  if #times > 0 then
    consistent = consistent and math.abs(times[#times] - before) < 1e-12 and math.abs(twice[#twice] - 2 * before) < 1e-12
                 and value_at("time", before) == times[#times]
  end
end)
expect { "record while running", predicted = true, measured = function() return consistent end }
expect { "ipairs", predicted = 48, tolerance = 0, measured = function()
  local count = 0
  for _ in ipairs(history("twice_t")) do count = count + 1 end
  return count
end }
)"));
  Lesson lesson(script.path(), {}, StepSettings{240.0});
  run_for(lesson, 0.2);
  for (const ExpectationResult& row : lesson.expectations()) EXPECT_TRUE(row.passes) << row.name;
}

// reached(t) is the window's rule for a run's end (Lesson::step_reaches): the step nearest t, or
// a later one. At 100 Hz, 0.1049 s is first reached by the step at 0.10 s and 0.1051 s by the
// step at 0.11 s; time() >= t would wait for 0.11 s for both.
TEST(LessonFunctions, ReachedIsTrueFromTheStepNearestATime) {
  ScriptFile script(with_heading(R"(
local first = {}
local times = { 0.1049, 0.1051, 0.3 }
every_step(function(t)
  for i, when in ipairs(times) do
    if first[i] == nil and reached(when) then first[i] = t end
  end
end)
for i, when in ipairs(times) do
  expect { "first to reach " .. when, unit = "s", tolerance = 0, measured = function() return first[i] or "never" end,
           predicted = 0 }
end
)"));
  Lesson lesson(script.path(), {}, StepSettings{100.0});
  run_for(lesson, 0.5);
  const std::vector<ExpectationResult> rows = lesson.expectations();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[0].measured, 0.10, 1e-12);
  EXPECT_NEAR(rows[1].measured, 0.11, 1e-12);
  EXPECT_NEAR(rows[2].measured, 0.30, 1e-12);
  // As the lesson itself says it, at every step of the run.
  Lesson again(script.path(), {}, StepSettings{100.0});
  for (int i = 0; i < 20; ++i) {
    again.step();
    EXPECT_EQ(again.reached(0.1049), again.scene().time() > 0.0999) << again.scene().time();
  }
}

TEST(LessonFunctions, ReachedAsksForAFiniteTime) {
  ScriptFile script(with_heading(R"(
expect { "never", predicted = true, measured = function() return reached(0 / 0) end }
)"));
  Lesson lesson(script.path());
  const std::string refused = error_of([&] { lesson.expectations(); });
  EXPECT_NE(refused.find(":3: reached: the time must be a finite number of seconds"), std::string::npos) << refused;
}

TEST(LessonFunctions, EveryStepRunsOncePerFrameWithTheTime) {
  ScriptFile script(with_heading(R"(
local calls, last = 0, -1
every_step(function(t) calls = calls + 1; last = t end)
probe { "calls", function() return calls end }
expect { "calls", predicted = 0, measured = function() return calls end, tolerance = 0 }
expect { "time matches", predicted = true, measured = function() return math.abs(last - time()) < 1e-12 end }
)"));
  Lesson lesson(script.path(), {}, StepSettings{120.0});
  run_for(lesson, 0.5);
  const std::vector<ExpectationResult> rows = lesson.expectations();
  EXPECT_EQ(rows[0].measured, 60.0);
  EXPECT_FALSE(rows[0].passes);  // predicted 0 on purpose: a failing row reads as failing
  EXPECT_TRUE(rows[1].passes);
  EXPECT_EQ(rows[1].measured_text, "true");
  // Probes sample after the step, before every_step: the count they saw lags by one.
  EXPECT_EQ(lesson.scene().probe("calls").history.back(), 59.0);
  EXPECT_EQ(lesson.scene().probe("calls").history.size(), 60u);
}

// A script's rows as its lesson gives them at the start, and after half a second of its run
// (past the 0.2 s at which the rows below are measured).
struct RowsThen {
  std::vector<ExpectationResult> at_start, half_a_second_on;
};
RowsThen rows_at_start_and_half_a_second_on(const std::string& rows) {
  ScriptFile script(with_heading(rows));
  Lesson lesson(script.path());
  RowsThen then;
  then.at_start = lesson.expectations();
  run_for(lesson, 0.5);
  then.half_a_second_on = lesson.expectations();
  return then;
}

TEST(LessonFunctions, ExpectationsTellNumbersWordsAndNotYetMeasured) {
  const RowsThen rows = rows_at_start_and_half_a_second_on(R"(
local seen
every_step(function(t) if t > 0.2 then seen = "slides" end end)
expect { "outcome", predicted = "slides", measured = function() return seen end }
expect { "number", unit = "N", predicted = function() return 10 end, measured = 10.4, tolerance = function() return 0.5 end }
expect { "tight", unit = "N", predicted = 10, measured = 10.4, tolerance = 0.3 }
)");
  EXPECT_FALSE(rows.at_start[0].measured_yet);
  EXPECT_EQ(rows.at_start[0].measured_text, "not measured");
  EXPECT_FALSE(rows.at_start[0].passes);
  const std::vector<ExpectationResult>& later = rows.half_a_second_on;
  EXPECT_TRUE(later[0].passes);
  EXPECT_FALSE(later[0].numeric);
  EXPECT_TRUE(later[1].passes);
  EXPECT_NEAR(later[1].error(), 0.4, 1e-12);
  EXPECT_EQ(later[1].unit, "N");
  EXPECT_FALSE(later[2].passes);
}

TEST(LessonFunctions, AWordFromMeasuredInANumberRowIsNotMeasuredYetAndSaysWhy) {
  const RowsThen rows = rows_at_start_and_half_a_second_on(R"(
expect { "distance", unit = "m", predicted = 0.5, tolerance = 0.01,
  measured = function() if time() < 0.2 then return "still sliding" end return 0.5 end }
)");
  EXPECT_TRUE(rows.at_start[0].numeric);
  EXPECT_FALSE(rows.at_start[0].measured_yet);
  EXPECT_EQ(rows.at_start[0].measured_text, "still sliding");
  EXPECT_FALSE(rows.at_start[0].passes);
  EXPECT_TRUE(rows.half_a_second_on[0].measured_yet);
  EXPECT_TRUE(rows.half_a_second_on[0].passes);
}

// A lesson that takes a pair's values from the presets still has its sliders: every pair that
// can rub gets its coefficients as parameters, and setting them changes the running scene.
TEST(LessonFunctions, PresetPairsGetTheirCoefficientsAsParameters) {
  ScriptFile script(with_heading(R"(ground { material = "ice" }
box { "crate", material = "wood", width = 0.5, height = 0.5, x = 0, y = 0.25 }
)"));
  Lesson lesson(script.path(), {{"mu_k", "0.03"}});
  // wood on ice, from the presets, is the lesson's only pair: its coefficients get plain names.
  EXPECT_EQ(lesson.parameter("mu_s").value, 0.08);
  EXPECT_EQ(lesson.parameter("mu_k").value, 0.03);  // --set applies
  EXPECT_EQ(lesson.parameter("mu_s").material_a + "/" + lesson.parameter("mu_s").material_b, "ice/wood");  // in the order the scene met them
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "ice").mu_k, 0.03);
  EXPECT_FALSE(lesson.parameter("mu_s").structural);
  lesson.set("mu_s", "0.1");
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "ice").mu_s, 0.1);
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "ice").mu_k, 0.03);
  lesson.reset();  // the values set stay
  EXPECT_EQ(lesson.scene().pairs().pair("wood", "ice").mu_s, 0.1);
}

}  // namespace
}  // namespace frictionlab::lessons
