// The lesson's plots, drawn from the probes' record with ImGui's draw lists: axes with tick
// labels and units, a legend, the current time marked on time series, and the slip regime
// shaded (time series) or coloured (X–Y against one quantity) from the scene's record of
// which frames had a slipping contact.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"
#include "ui/theme.h"

namespace frictionlab::ui {

// Tick positions for an axis from low to high: 1, 2 or 5 times a power of ten apart, about
// `count` of them.
std::vector<double> axis_ticks(double low, double high, int count);
// A tick's label with as many decimals as the step needs, and a true minus sign.
std::string tick_text(double value, double step);

// Draws `plot` into the rectangle. `time_span` is the time axis' length (the lesson's
// duration, or longer once the lesson has run past it).
void draw_plot(ImDrawList* draw, const lessons::Lesson& lesson, const lessons::Plot& plot, double time_span,
               ImVec2 corner, ImVec2 size, const Theme& theme, const Fonts& fonts);

}  // namespace frictionlab::ui
