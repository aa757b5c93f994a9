// The sandbox a lesson script runs in: nothing outside the script reachable, pairs() in the same
// order on every run, binary chunks and load errors refused with the file's name, and an endless
// loop or a runaway table ended with an error, not a hang (lessons/runtime/sandbox.h); Lua's
// messages about arithmetic on a string said in words.
#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <string>
#include <thread>

#include "lessons/runtime/lesson.h"
#include "lessons/runtime/sandbox.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::lessons {
namespace {

TEST(LessonSandbox, NothingOutsideTheScriptIsReachable) {
  ScriptFile script(with_heading(R"(
for _, name in ipairs { "io", "os", "package", "debug", "require", "load", "loadfile", "dofile", "collectgarbage",
                        "pcall", "xpcall", "coroutine" } do
  if rawget(_ENV, name) ~= nil then error(name .. " is reachable") end
end
if math.random ~= nil or math.randomseed ~= nil then error("math.random is reachable") end
if string.find ~= nil or ("x").match ~= nil or string.gsub ~= nil or string.gmatch ~= nil then error("patterns are reachable") end
assert(string.format("%.1f", math.sqrt(2)) == "1.4" and table.concat({ 1, 2 }, ",") == "1,2" and utf8.char(956) == "μ")
)"));
  EXPECT_NO_THROW(Lesson{script.path()});
}

TEST(LessonSandbox, PairsGoesInTheSameOrderOnEveryRun) {
  // Lua seeds its string hashing from the clock; pairs must not pass that on to the lesson.
  ScriptFile script(with_heading(R"(
local t = { zeta = 1, alpha = 2, mid = 3, [3] = "c", [1] = "a", [2.5] = "b", beta = 4 }
local order = {}
for k in pairs(t) do order[#order + 1] = tostring(k) end
expect { "order", predicted = "1 2.5 3 alpha beta mid zeta", measured = table.concat(order, " ") }
)"));
  Lesson lesson(script.path());
  EXPECT_TRUE(lesson.expectations()[0].passes) << lesson.expectations()[0].measured_text;
}

TEST(LessonSandbox, PairsOverAHugeTableSortsInTimeAndCountsAgainstTheBudget) {
  // 80 000 keys: an insertion sort inside one C call took minutes, out of reach of the budget
  // and the clock; the sort now finishes at once, in the same order as before.
  ScriptFile once(with_heading(R"(
local t = {}
for i = 1, 80000 do t["k" .. (80001 - i)] = i; t[i * 0.5] = i end
local count, sorted, last_number, last_text = 0, true, -math.huge, ""
for k in pairs(t) do
  count = count + 1
  if type(k) == "number" then sorted = sorted and last_text == "" and k > last_number; last_number = k
  else sorted = sorted and k > last_text; last_text = k end
end
expect { "every key in order", predicted = 160000, tolerance = 0, measured = sorted and count or -count }
)"));
  Lesson lesson(once.path());
  EXPECT_TRUE(lesson.expectations()[0].passes) << lesson.expectations()[0].measured_text;
  // Sorting is work the instruction count does not see: it is charged to the budget, so pairs
  // over a huge table in an endless loop ends like any other endless loop.
  ScriptFile again(with_heading(R"(
local t = {}
for i = 1, 80000 do t["k" .. i] = i end
while true do for _ in pairs(t) do break end end
)"));
  const std::string message = error_of([&] { Lesson{again.path()}; });
  EXPECT_NE(message.find(again.path() + ":5: the script ran for more than 50 million instructions"), std::string::npos)
      << message;
}

TEST(LessonSandbox, BinaryChunksAreRefusedWithTheFilesName) {
  ScriptFile script(std::string("\x1bLua\x54\x00", 6) + "rest");
  const std::string message = error_of([&] { Lesson{script.path()}; });
  EXPECT_EQ(message.rfind(script.path() + ": the file is a precompiled (binary) Lua chunk; a lesson is given as its Lua "
                          "source text", 0), 0u) << message;
}

// Lua reads these without saying where: the file's name, at least, and what it means.
TEST(LessonSandbox, LoadErrorsWithoutALineNameTheFile) {
  ScriptFile deep(with_heading("local x = " + std::string(1000, '(') + "1" + std::string(1000, ')') + "\n"));
  const std::string nesting = error_of([&] { Lesson{deep.path()}; });
  EXPECT_EQ(nesting.rfind(deep.path() + ": the script nests brackets, tables or blocks too deeply for Lua to read", 0), 0u)
      << nesting;
  // A string literal larger than the script's memory: 80 MB written out in the file.
  ScriptFile huge(with_heading("local x = \"" + std::string(80u << 20, 'x') + "\"\n"));
  const std::string literal = error_of([&] { Lesson{huge.path()}; });
  EXPECT_EQ(literal.rfind(huge.path() + ": the script is too large to read within 64 MB of memory", 0), 0u)
      << literal.substr(0, 300);
}

// Lua's own loadfile skips a UTF-8 byte-order mark and a first line starting with #, as
// editors and `#!/usr/bin/env lua` write them; so does the lesson loader, every line keeping its
// number.
TEST(LessonSandbox, AByteOrderMarkAndAHashLineAreSkipped) {
  ScriptFile script("\xEF\xBB\xBF#!/usr/bin/env lua\n" + with_heading("local x = nil + 1\n"));
  const std::string message = error_of([&] { Lesson{script.path()}; });
  EXPECT_EQ(message.rfind(script.path() + ":3: attempt to perform arithmetic on a nil value", 0), 0u) << message;
  ScriptFile clean("#!/usr/bin/env lua\n" + with_heading(""));
  EXPECT_NO_THROW(Lesson{clean.path()});
}

// A lesson reads its text once and rebuilds from the compiled script (a slider's change,
// check --random's settings): those builds run the same code, and their errors name the same
// file and line as the text's.
TEST(LessonSandbox, RebuildsRunTheCompiledScriptWithTheTextsLines) {
  ScriptFile script(with_heading("local mass = parameter { \"mass\", 1, min = 0.5, max = 5, unit = \"kg\" }\n"
                                 "if mass > 4 then error(\"too heavy for this ramp\") end\n"));
  const std::string from_text = error_of([&] { Lesson(script.path(), {{"mass", "4.5"}}); });
  EXPECT_EQ(from_text.rfind(script.path() + ":3: too heavy for this ramp", 0), 0u) << from_text;
  Lesson lesson(script.path());
  EXPECT_EQ(error_of([&] { lesson.set("mass", "4.5"); }), from_text);
  ScriptText compiled = lesson.script();
  EXPECT_EQ(error_of([&] { Lesson(compiled, {{"mass", "4.5"}}, {}); }), from_text);
  const Lesson again(compiled, {{"mass", "2"}}, {});
  EXPECT_EQ(again.parameter("mass").value, 2.0);
  // A text changed after it was compiled is read again, never run as the old bytecode.
  compiled.source = "lesson { title = \"changed\", question = \"is it read?\" }\n";
  EXPECT_EQ(Lesson(compiled, {}, {}).title(), "changed");
}

TEST(LessonSandbox, AnEndlessLoopAndARunawayTableEndWithAnError) {
  ScriptFile loop(with_heading("local n = 0\nwhile true do n = n + 1 end\n"));
  const std::string looping = error_of([&] { Lesson{loop.path()}; });
  EXPECT_NE(looping.find(loop.path() + ":3: the script ran for more than 50 million instructions"), std::string::npos)
      << looping;
  ScriptFile hoard(with_heading("local t = {}\nfor i = 1, 1e9 do t[i] = { i } end\n"));
  const std::string hoarding = error_of([&] { Lesson{hoard.path()}; });
  EXPECT_NE(hoarding.find(hoard.path() + ":3: the script uses more than 64 MB of memory"), std::string::npos)
      << hoarding;
  ScriptFile huge(with_heading("local s = string.rep('x', 200 * 1024 * 1024)\n"));
  const std::string at_once = error_of([&] { Lesson{huge.path()}; });
  EXPECT_NE(at_once.find("MB of memory"), std::string::npos) << at_once;
}

TEST(LessonSandbox, AnEndlessLoopWhileRunningStopsTheLessonNotTheProgram) {
  ScriptFile script(with_heading("every_step(function(t) if t > 0.05 then while true do end end end)\n"));
  Lesson lesson(script.path());
  const std::string message = error_of([&] { run_for(lesson, 0.1); });
  EXPECT_NE(message.find(script.path() + ":2: the script ran for more than"), std::string::npos) << message;
  EXPECT_TRUE(lesson.failed());
}

// The time limit is on the processor time the script's thread spends, not on the wall clock: a
// machine busy with other work (two test programs and a compiler on two cores) gives a loop less
// of the processor, and must not stop a script before its instruction limit. A thread asleep
// inside a C function stands in for that load: it is off the processor, as a starved one is.
// (In the browser the page's thread has only the wall clock, and the sandbox uses it.)
#ifndef __EMSCRIPTEN__
TEST(LessonSandbox, TheTimeLimitCountsTheScriptsProcessorTimeNotTheWallClock) {
  SandboxLimits limits;
  limits.instructions_per_call = std::numeric_limits<long>::max();  // so that only the clock can stop the loop below
  limits.seconds_per_call = 1.0;
  Sandbox sandbox(limits);
  lua_register(sandbox.state(), "doze", [](lua_State*) -> int {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return 0;
  });
  // 1.2 s on the wall, a few milliseconds on the processor: 12 x 5 000 turns of an empty loop,
  // each turn a few instructions, so the clock is looked at between the dozes.
  sandbox.load("for i = 1, 12 do doze(); for j = 1, 5000 do end end\n", "dozing.lua");
  EXPECT_NO_THROW(sandbox.call(0, 0));
  // A loop that keeps the processor busy still stops at the limit, at its own line.
  sandbox.load("local n = 0\nwhile true do n = n + 1 end\n", "spinning.lua");
  const std::string message = error_of([&] { sandbox.call(0, 0); });
  EXPECT_NE(message.find("spinning.lua:2: the script ran for more than 1 second without"), std::string::npos) << message;
}
#endif

// Lua names arithmetic on a string by its metamethod ("attempt to mul a 'number' with a
// 'string'"). The message says the operation in words, and says what a string may do only where
// a string is at fault: "2" + nil is the nil's, and a number with nil keeps Lua's own message.
TEST(LessonSandbox, ArithmeticOnAStringIsSaidInWordsAndBlamesTheRightSide) {
  const auto message = [](const std::string& line) {
    const std::string text = error_building(with_heading(line + "\n"));
    return text.substr(text.find(": ", text.find(".lua:")) + 2);
  };
  EXPECT_EQ(message("local half = \"0.4 m\" / 2"),
            "cannot divide a string and a number: a string (text in quotes) takes part in arithmetic only if it reads as "
            "a number, as \"2.5\" does");
  EXPECT_EQ(message("local wrong = -\"fast\""),
            "cannot negate a string: a string (text in quotes) takes part in arithmetic only if it reads as a number, as "
            "\"2.5\" does");
  EXPECT_EQ(message("local missing = \"2\" + nil"), "cannot add a string and a nil");
  EXPECT_EQ(message("local flag = true * \"1\""), "cannot multiply a boolean and a string");
  EXPECT_EQ(message("local missing = 3 + nil"), "attempt to perform arithmetic on a nil value");
}

}  // namespace
}  // namespace frictionlab::lessons
