// A built-in lesson as its own benchmark problem: each run builds the lesson's own script with
// a step setting and the given parameter values, runs it for the lesson's duration and judges
// it by the lesson's expectations, so no C++ copy of the lesson can drift from it.
#pragma once

#include <map>
#include <string>

#include "bench/problems.h"

namespace frictionlab::lessons {

// The lesson at `path` (a built-in name or a .lua path), with `overrides` (--set NAME=VALUE
// or the window's slider values). A run's error is the largest |measured − predicted| over the
// numeric rows, each in units of that row's tolerance as it is at the default setting
// (stick-slip at 240 Hz, 1 sub-step), so a tolerance that grows with the step does not loosen
// the judging at coarse steps; a word row that differs, or a row never measured, is an infinite
// error ("wrong answer"). A run also fails as "not a number" (a body's state or a row not
// finite), "blew up" (a body a hundred times farther or faster than the reference run's
// largest) or "chatters" (a body's velocity reversing at eight world steps in a row).
// Throws ScriptError or InvalidInput as Lesson does, and InvalidInput when the lesson has no
// expectation to judge by.
BenchmarkProblem lesson_problem(const std::string& path, const std::map<std::string, std::string>& overrides = {});

class Lesson;
// A lesson's parameters as they stand (its sliders), as overrides for lesson_problem: numbers
// to full precision, choices by name.
std::map<std::string, std::string> parameter_values(const Lesson& lesson);

}  // namespace frictionlab::lessons
