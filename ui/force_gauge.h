// The force gauge: the mouse's hand pulls a body through a spring scale (the scene's grab,
// physics/scene.h). Its reading is recorded frame by frame against the lesson's time, drawn in
// the world as a spring scale with its reading in newtons, and plotted, so the classic lab works
// by hand: pull slowly, the peak is static friction (mu_s·m·g), the plateau while it slides is
// kinetic friction (mu_k·m·g). The stretches of the run the hand pulled are what the theory
// table marks "hand-pulled": the lesson's predictions know nothing of the hand.
//
// A lesson may pull the held body too (push's push, spring_pull's spring). Then the gauge alone
// is not what friction answers: its peak and plateau are taken from the pull along the surface
// of the hand and the lesson together (while the body sticks, friction answers exactly that),
// and they say so ("hand + spring"). The scale drawn reads the hand's own pull.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include "physics/scene.h"
#include "ui/camera.h"
#include "ui/chart.h"
#include "ui/drawing.h"
#include "ui/theme.h"

namespace frictionlab::ui {

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
};

// A stretch of the run the hand pulled: from the start of its first step to the end of its last.
struct HandStretch {
  double from = 0.0, to = 0.0;  // s
};

// What the latest stretch shows: the peak, the largest pull while the body held, up to the step
// it broke away in (static friction's limit; none when it was sliding when taken), and the mean
// pull while the body slid once the pull had settled after the breakaway (none until it has slid
// that long). A pull after the breakaway is no peak: the trial's pulley gave "peak 10.5 N" for
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

// Where the gauge lies on the screen: its hook on the body, the hand's end of the coil (where the
// scale's spring ends), the case from `case_start` to the ring, and the ring the hand holds,
// centred on the pointer (the hand's target). The case is as long as the room between hook and
// ring allows, up to its full length; with no room it is not drawn.
struct GaugeShape {
  ImVec2 hook, hand, case_start, ring, along;
  float half_width, ring_radius;
};
GaugeShape gauge_shape(const Scene& scene, const Camera& camera, float scale);

// The gauge in the world, between the point the hand holds and the pointer: its coil and case
// given to the label placer first (before any label is placed), then drawn with its reading.
// Nothing when no body is held.
void avoid_gauge(const Scene& scene, const Camera& camera, float scale, LabelPlacer& labels);
void draw_gauge(ImDrawList* draw, const Scene& scene, const Camera& camera, const Theme& theme, const Fonts& fonts,
                LabelPlacer& labels);

// The gauge's reading against time over the latest stretch the hand pulled (from a little
// before it took hold), the slips shaded; the hand's and the lesson's pull together instead when
// the lesson pulled the body too, as the figures are taken.
Chart gauge_chart(const GaugeRecord& record, double frame_step, const Theme& theme);

}  // namespace frictionlab::ui
