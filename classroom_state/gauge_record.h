// What the force gauge read, frame by frame: the mouse's hand pulls a body through a spring
// scale (the scene's grab, physics/scene.h), and the record keeps its reading against the
// lesson's time, so the classic lab works by hand: pull slowly, the peak is static friction
// (mu_s·m·g), the plateau while it slides kinetic friction (mu_k·m·g). The playback keeps one;
// the gauge's drawing and chart (classroom/force_gauge.h) read it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "physics/scene_forces.h"

namespace frictionlab::classroom_state {

// One frame the hand held a body through the gauge.
struct GaugeSample {
  long frame = 0;           // the scene's frame count at the end of the step
  double t = 0.0;           // s, the end of the step
  double force = 0.0;       // N, the size of the force the gauge applied over the step
  // N, the hand's and the lesson's pulls on the body (applied forces, springs, ropes) together
  // over the step, along the surface it stands on (along the hand's pull off any surface).
  double pull = 0.0;
  bool lesson_pulls = false;  // the lesson pulled the held body too in this step
  bool slipping = false;    // a contact was slipping at the end of the step
  // kg·m/s, the body's momentum along the pull's direction at the end of the step: from one step
  // to the next, the net force, which tells steady sliding from a body coasting to a stop.
  double momentum = 0.0;
};

// A stretch of the run the hand pulled: from the start of its first step to the end of its last.
struct HandStretch {
  double from = 0.0, to = 0.0;  // s
};

// What the latest stretch shows: the peak, the largest pull while the body held, up to the step
// it broke away in (static friction's limit; none when it was sliding when taken), and the mean
// pull while the body slid steadily once the pull had settled after the breakaway (none until it
// has slid that long). Steadily: the net force on it, its momentum's change a step, within
// steady_share of the pull, so that the pull is friction's within that share. A hand that stops
// lets the body coast to a stop through the gauge's spring, reading less than friction all the
// while; a teacher's trial read a plateau 33 % under μk·m·g, those steps counted. A pull after the breakaway is no peak: the trial's pulley gave "peak 10.5 N" for
// the jolt of its weight landing, and the incline a peak in mid-slide, where the hand sped up.
// The pull is the gauge's reading, or with the lesson's own pulls added when the lesson pulled
// the body too.
struct GaugeFigures {
  std::optional<double> peak;
  double peak_time = 0.0;
  bool broke_away = false;  // it slid after holding: the peak is the breakaway's
  std::optional<double> plateau;
  double plateau_from = 0.0, plateau_to = 0.0;  // s, the part of the run the plateau averages
  // The lesson's pulls on the body that the figures add to the hand's ("spring"); empty when the
  // hand pulled alone.
  std::string lesson_pulls;
};

class GaugeRecord {
 public:
  // Time after the peak the pull is given to settle before the plateau is averaged: four of
  // the gauge's time constants at its 1.5 Hz, in which its swing dies to a tenth.
  static constexpr double settle_time = 0.4;  // s
  // The most net force, as a share of the pull, a step of the plateau may have.
  static constexpr double steady_share = 0.05;

  // After each frame of the lesson: a sample when the hand holds a body.
  void after_step(const Scene& scene);
  // A replay from t = 0 records the run again.
  void clear() {
    samples_.clear();
    lesson_pulls_.clear();
  }
  const std::vector<GaugeSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }
  // Consecutive frames of samples, each a stretch; `frame_step` is the lesson's 1/hz.
  std::vector<HandStretch> stretches(double frame_step) const;
  // The latest stretch's figures; none before any sample.
  std::optional<GaugeFigures> figures(double frame_step) const;
  // The first sample of the latest stretch.
  std::size_t latest_stretch_start() const;
  // The names of the lesson's pulls on the held body, "push" or "spring and rope"; empty when
  // the lesson never pulled it while the hand did.
  const std::string& lesson_pulls() const { return lesson_pulls_; }

 private:
  std::vector<GaugeSample> samples_;
  std::string lesson_pulls_;
};

// "hand-pulled 0.50–2.30 s", stretches joined by commas; "" when there are none.
std::string stretches_text(const std::vector<HandStretch>& stretches);

}  // namespace frictionlab::classroom_state
