// The lesson's plots: the probes' record, the scene's record of which frames had a slipping
// contact (shaded on time plots, colouring an X–Y plot of one quantity) and the script's
// theory curves, handed to the chart engine (draw/chart.h) that also draws the benchmark's charts.
#pragma once

#include <imgui.h>

#include <functional>
#include <string>
#include <vector>

#include "draw/chart.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::draw {

// Plot number `plot` of the lesson as a chart for the chart engine: the probes' record as
// series (coloured by regime on an X–Y plot of one probe), the slip shaded on a time plot, the
// present marked, and the theory curves sampled across the x range (kept between frames while
// the range and parameters stay; a script error in one becomes the chart's message).
// `time_span` is the time axis' length (the lesson's duration, or longer once the lesson has
// run past it). Without `with_theory` the probes alone: the class has not seen the theory yet,
// or a mystery's values would be read off the curves.
// The plot's levels (levels = { ... }) are theory too: drawn with the curves, "label = value".
// `steady`: a plot on a page of its own (projector mode), its data area kept the same whatever
// the run and the reveal add, its y ticks as fine as its height reads.
Chart plot_chart(lessons::Lesson& lesson, std::size_t plot, double time_span, const Theme& theme,
                 bool with_theory = true, bool steady = false);

// Where plot number `plot` of the lesson goes in the rectangle, for tests and the drawing.
ChartLayout layout_plot(lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner, ImVec2 size,
                        const Fonts& fonts, bool with_theory = true, bool steady = false);

// Draws plot number `plot` of the lesson into the rectangle; where its parts went.
ChartLayout draw_plot(ImDrawList* draw, lessons::Lesson& lesson, std::size_t plot, double time_span, ImVec2 corner,
                      ImVec2 size, const Theme& theme, const Fonts& fonts, bool with_theory = true,
                      const std::function<std::string(const std::string&)>& script_words = {}, bool steady = false);

}  // namespace frictionlab::draw
