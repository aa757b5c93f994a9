// The lesson's plots: the probes' record, the scene's record of which frames had a slipping
// contact (shaded on time plots, colouring an X–Y plot of one quantity) and the script's
// theory curves, handed to the chart engine (draw/chart.h) that also draws the benchmark's charts.
#pragma once

#include <imgui.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "draw/chart.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

// A time axis' length, from the opening: the lesson's duration (or the time reached, once the run
// has gone past it) up to the next of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10ⁿ s, before the reveal
// and after it alike. Its end, a tick, says the duration to within a quarter; the parameters it
// comes from are on the sliders. With `secret` (a mystery's values hidden) it must say nothing of
// them: a lesson runs until what it teaches has been seen, and push's axis, drawn before Play,
// gave a mystery's μs away (it runs a while past the breakaway at μs·m·g). It grows with the run
// instead, to the next of 1, 2, 5, 10, 20, ... s, until the mystery's reveal.
double time_axis_span(double duration, double now, bool secret = false);

// How many times the plots have looked for a lesson's run ahead (what fixes their axes) by its
// script's text, values and settings, having not seen its revision lately: the cost the lesson's
// revision saves, for the tests.
std::size_t planned_reach_lookups();

// The force the world's arrows are scaled for (arrow_scale, draw/frame.h), from the same run
// ahead: the largest force on a moving body in nine frames of ten of the run (not its heaviest
// weight alone: stacked_blocks' floor carries both blocks, a pull or a spring may pull harder;
// not the run's very largest: a box tipped over lands with a blow of a few frames many times its
// weight, which would shrink every other arrow). Nothing where the run is too long to run ahead,
// fails, or has no force.
std::optional<float> run_force_for_scale(const lessons::Lesson& lesson);

// Plot number `plot` of the lesson as a chart for the chart engine: the probes' record as
// series (coloured by regime on an X–Y plot of one probe), the slip shaded on a time plot, the
// present marked, and the theory curves sampled across the x range (kept between frames while
// the range and parameters stay; a script error in one becomes the chart's message).
// `time_span` is the time axis' length (time_axis_span). Without `with_theory` the probes
// alone: the class has not seen the theory yet, or a mystery's values would be read off the
// curves. The plot's levels (levels = { ... }) are theory too: drawn with the curves,
// "label = value". The axes are the same with the theory and without it, and from the opening
// to the run's end: each side of zero ends at the next of 1, 2, 5 × 10ⁿ past what a run of the
// lesson to its end at its present values records (worked out once on a copy), the record and
// the theory's values, so the plot keeps its scale as the run goes on and at the reveal. The y ticks are as fine as the data area's height reads.
// `steady`: a plot on a page of its own (projector mode), its data area kept the same whatever
// the run and the reveal add. `secret`: a mystery's values are hidden, and the theory worked out
// from them counts for no axis until its reveal (the record alone sets them).
Chart plot_chart(lessons::Lesson& lesson, std::size_t plot, double time_span, const Theme& theme,
                 bool with_theory = true, bool steady = false, bool secret = false);

// Where plot number `plot` of the lesson goes in the rectangle, for tests and the drawing.
ChartLayout layout_plot(lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner, ImVec2 size,
                        const Fonts& fonts, bool with_theory = true, bool steady = false);

// Draws plot number `plot` of the lesson into the rectangle; where its parts went.
ChartLayout draw_plot(ImDrawList* draw, lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner,
                      ImVec2 size, const Theme& theme, const Fonts& fonts, bool with_theory = true,
                      const std::function<std::string(const std::string&)>& script_words = {}, bool steady = false,
                      bool secret = false);

}  // namespace frictionlab::draw
