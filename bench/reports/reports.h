// Parts of frictionlab bench that live in files of their own.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "draw/chart.h"

namespace frictionlab {

double median(std::vector<double> values);

// How far a long part of the bench has got, 0 to 1, for the progress bar on a terminal.
using Progress = std::function<void(double fraction)>;

// One run of a method on a benchmark problem: its error against the exact answer and what it cost.
struct AccuracyRun {
  std::string method;
  double hz;     // step rate (or, for a chart of another knob, its value: the point's label)
  double error;  // against the exact answer (the spring: max position error over the run, m)
  double cost;   // CPU s per simulated s
  std::string fails;  // "" or why the run failed ("chatters", "not a number")
};
// The runs no other beats on both cost and error: (cost, error) pairs, cheapest first.
std::vector<std::pair<double, double>> pareto_front(std::vector<std::pair<double, double>> points);
// Charts drawn headless as PNG bytes; empty where EGL cannot start, and then, given `out`, a
// line there saying why `name` was not drawn.
std::string charts_png(const std::vector<draw::Chart>& charts, int columns, int width, int height, const std::string& name,
                       std::ostream* out);
// The crosses a work-precision chart marks runs with: failed (drawn where the run's error lies)
// and wrong answers (no error to draw: along the top).
std::pair<draw::ChartSeries, draw::ChartSeries> failure_marks();
// A work-precision chart of runs: error against cost, a curve per method (in the order met,
// its fitted order of convergence in the legend when `fit_orders`), points labelled by rate,
// exact answers at 10⁻¹², failed runs crossed where they lie and wrong answers along the top,
// and the Pareto front of the runs that did not fail. Given `orders`, each method's fitted
// order is also put there.
draw::Chart work_precision_chart(const std::string& title, const std::string& y_label, const std::vector<AccuracyRun>& runs,
                               bool fit_orders = true, std::vector<std::pair<std::string, double>>* orders = nullptr);
// The work-precision and convergence charts of those runs as PNG bytes; empty where EGL cannot start.
std::string work_precision_png(const std::vector<AccuracyRun>& runs);
// The listener_cost.csv text: CPU ms per step of piles of boxes with the pair-table listener and
// with Box2D's own mixer; its table printed to `out`.
std::string listener_cost(bool quick, std::ostream& out);
// The stick_slip_accuracy.csv text: each treatment and reduced model at each rate on the spring's
// stick-slip problem, its error against the exact solution and its cost; the runs also into `runs`.
std::string stick_slip_accuracy(bool quick, std::ostream& out, std::vector<AccuracyRun>& runs);
// The lesson_speed.csv text: each built-in lesson's speed headless at 240 Hz and its script's share.
std::string lesson_speed(bool quick, std::ostream& out);
// The frame_speed.csv text, or empty (with the reason printed) where EGL cannot start.
std::string frame_speed(bool quick, std::ostream& out, const Progress& progress);
// The window_frame.csv text (CPU time per display frame of the window), or empty where EGL cannot start.
std::string window_frame_speed(bool quick, std::ostream& out, const Progress& progress);
// The force_labels.csv text (what placing the forces' values takes in a projector's window frame,
// with and without draw_world's retries), or empty where EGL cannot start.
std::string force_label_speed(bool quick, std::ostream& out, const Progress& progress);
// work_precision.csv (every problem × treatment × rate, and the spring's iterations and
// sub-steps) and problems.png (a work-precision chart per problem), as (path, bytes).
std::vector<std::pair<std::string, std::string>> problem_files(bool quick, const std::string& directory,
                                                                std::ostream& out, const Progress& progress);
// stability_map.csv and stability.png (the charts; left out where EGL cannot start), as (path, bytes).
std::vector<std::pair<std::string, std::string>> stability_files(bool quick, const std::string& directory,
                                                                  std::ostream& out, const Progress& progress);

}  // namespace frictionlab
