// A lesson's theory rows as read at a moment, with why they may not answer yet: plain data the
// window's playback keeps and the drawn frame shows (draw/frame.h).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

// What the theory table shows of a lesson at a moment: its rows worked out, and why they may
// not answer yet. The window's playback works them out a few times a second; a headless frame
// works them out once.
struct LessonReadings {
  std::vector<ExpectationResult> expectations;
  double duration = 1.0;  // s
  std::string error;      // the script failed to work them out
  std::string caveat;     // why the measurements do not answer the predictions yet
};

// What one world step of `step` seconds resolves of a body's motion under gravity of magnitude
// `gravity` (m/s²). Box2D keeps a body's velocity in float, and a step changes it by about
// gravity·step, which a float holds to its relative precision ε (2⁻²³): a speed nearer 0 than
// ε·gravity·step is the rounding of the step's numbers, not motion, and so is an acceleration
// (a change of speed over a step) nearer 0 than that over the step, ε·gravity. A held block's
// acceleration was printed as 1.1×10⁻⁹ m/s² (a teacher's trial: incline's 15° slope measures
// −2.5×10⁻¹⁰ m/s² with a 5 kg block, pulley's held block −4.6×10⁻⁸ m/s² at μs 0.7).
struct MotionResolution {
  double speed = 0.0;         // m/s
  double acceleration = 0.0;  // m/s²
};
inline MotionResolution motion_resolution(double step, double gravity) {
  const double rounding = static_cast<double>(std::numeric_limits<float>::epsilon()) * std::abs(gravity) * step;
  return {rounding, step > 0.0 ? rounding / step : 0.0};
}

// `rows` as the panels show them: a measured speed (unit "m/s") or acceleration ("m/s²") nearer
// 0 than `resolution` is 0, so the measured value and its error read as the motion the run has.
// Only what is shown: the rows' verdicts were reached on the values as measured.
inline void zero_unresolved_motion(std::vector<ExpectationResult>& rows, const MotionResolution& resolution) {
  for (ExpectationResult& row : rows) {
    if (!row.numeric || !row.measured_yet) continue;
    const double least = row.unit == "m/s" ? resolution.speed : row.unit == "m/s\u00b2" ? resolution.acceleration : 0.0;
    if (std::abs(row.measured) < least) row.measured = 0.0;
  }
}
// The same at `lesson`'s world step (a frame's step over its substeps) and gravity.
inline void zero_unresolved_motion(std::vector<ExpectationResult>& rows, const Lesson& lesson) {
  const Scene& scene = lesson.scene();
  const double world_step = scene.frame_step() / static_cast<double>(scene.settings().substeps);
  zero_unresolved_motion(rows, motion_resolution(world_step, static_cast<double>(scene.world().GetGravity().Length())));
}

}  // namespace frictionlab::lessons
