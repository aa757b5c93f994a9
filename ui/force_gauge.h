// The force gauge: the mouse's hand pulls a body through a spring scale (the scene's grab,
// physics/scene.h). Its reading is recorded frame by frame against the lesson's time, drawn in
// the world as a spring scale with its reading in newtons, and plotted, so the classic lab works
// by hand: pull slowly, the peak is static friction (mu_s·m·g), the plateau while it slides is
// kinetic friction (mu_k·m·g). The stretches of the run the hand pulled are what the theory
// table marks "hand-pulled": the lesson's predictions know nothing of the hand.
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
  bool slipping = false;    // a contact was slipping at the end of the step
};

// A stretch of the run the hand pulled: from the start of its first step to the end of its last.
struct HandStretch {
  double from = 0.0, to = 0.0;  // s
};

// What the latest stretch shows: its largest reading, and the mean reading while the body slid
// once the pull had settled after the peak (none until it has slid that long).
struct GaugeFigures {
  double peak = 0.0, peak_time = 0.0;
  std::optional<double> plateau;
  double plateau_from = 0.0, plateau_to = 0.0;  // s, the part of the run the plateau averages
};

class GaugeRecord {
 public:
  // Time after the peak the pull is given to settle before the plateau is averaged: four of
  // the gauge's time constants at its 1.5 Hz, in which its swing dies to a tenth.
  static constexpr double settle_time = 0.4;  // s

  // After each frame of the lesson: a sample when the hand holds a body.
  void after_step(const Scene& scene);
  // A replay from t = 0 records the run again.
  void clear() { samples_.clear(); }
  const std::vector<GaugeSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }
  // Consecutive frames of samples, each a stretch; `frame_step` is the lesson's 1/hz.
  std::vector<HandStretch> stretches(double frame_step) const;
  // The latest stretch's figures; none before any sample.
  std::optional<GaugeFigures> figures(double frame_step) const;

 private:
  std::vector<GaugeSample> samples_;
};

// "hand-pulled 0.50–2.30 s", stretches joined by commas; "" when there are none.
std::string stretches_text(const std::vector<HandStretch>& stretches);

// The gauge in the world, between the point the hand holds and the hand's end of the scale: its
// coil and case given to the label placer first (before any label is placed), then drawn with
// its reading. Nothing when no body is held.
void avoid_gauge(const Scene& scene, const Camera& camera, float scale, LabelPlacer& labels);
void draw_gauge(ImDrawList* draw, const Scene& scene, const Camera& camera, const Theme& theme, const Fonts& fonts,
                LabelPlacer& labels);

// The gauge's reading against time over the stretches the hand pulled, the slips shaded.
Chart gauge_chart(const GaugeRecord& record, double frame_step, const Theme& theme);

}  // namespace frictionlab::ui
