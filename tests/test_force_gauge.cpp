// The force gauge and the measuring tools, driven as a teacher drives them: ImGui's mouse and
// keys written across frames on an EGL context with no display (as test_classroom does). Each
// test checks a figure against the closed form it must show: static friction mu_s·m·g as the
// gauge's peak, kinetic friction mu_k·m·g as its plateau, the stopwatch against the lesson's
// clock, the speed against the body's velocity, and the weight's parts along and across a slope.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lessons/runtime/catalog.h"
#include "ui/classroom.h"
#include "ui/headless.h"
#include "ui/imgui_host.h"
#include "ui/measuring_tools.h"
#include "ui/overlays.h"

namespace frictionlab::ui {
namespace {

constexpr double g = 9.81;

// The classroom on a headless context, and a teacher's hand on its io.
class Hands {
 public:
  explicit Hands(const std::string& lesson, std::map<std::string, std::string> overrides = {}, bool projector = false)
      : host_(nullptr) {
    ClassroomOptions options;
    options.lesson = lessons::resolve_lesson(lesson);
    options.overrides = std::move(overrides);
    options.window.help = false;
    options.window.projector = projector;
    options.output_folder = folder_;
    std::filesystem::create_directories(folder_);
    classroom_ = std::make_unique<Classroom>(options);
  }
  ~Hands() { std::filesystem::remove_all(folder_); }
  Classroom& classroom() { return *classroom_; }
  lessons::Lesson& lesson() { return classroom_->playback().lesson(); }
  void frame(double wall = 0.0, FrameRecord* record = nullptr) {
    gl_.make_current();
    const Fonts& fonts = host_.prepare(classroom_->ui_scale(display_), classroom_->window_settings().theme);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = display_;
    io.DeltaTime = 1.0f / 60.0f;
    host_.begin_frame();
    classroom_->frame(fonts, display_, wall, record);
    ImGui::Render();
  }
  void mouse_at(ImVec2 at) {
    ImGui::GetIO().MousePos = at;
    frame();
  }
  void button(bool down) {
    ImGui::GetIO().MouseDown[0] = down;
    frame();
  }
  void key(Key key) {
    classroom_->key_pressed(key, false);
    frame();
  }
  void set_display(ImVec2 display) { display_ = display; }

  // Takes hold of the body at its centre, plays, and pulls the mouse `pixels_per_frame` to the
  // right each display frame (60 a second) for `seconds` of lesson time at speed 1.
  void pull_right(const std::string& body_name, float pixels_per_frame, double seconds) {
    const b2Body* body = lesson().scene().body(body_name);
    const ImVec2 held = classroom_->world_camera().to_screen(body->GetWorldCenter());
    mouse_at(held);
    button(true);
    EXPECT_EQ(lesson().scene().grabbed(), body);
    key(Key::space);
    const int frames = static_cast<int>(std::lround(seconds * 60.0));
    for (int i = 1; i <= frames; ++i) {
      ImGui::GetIO().MousePos = ImVec2(held.x + pixels_per_frame * static_cast<float>(i), held.y);
      frame(1.0 / 60.0);
    }
    button(false);
  }

 private:
  HeadlessContext gl_;
  ImGuiHost host_;
  std::string folder_ = (std::filesystem::temp_directory_path() /
                         ("frictionlab_gauge_" + std::to_string(::getpid()) + "_" +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name()))
                            .string();
  std::unique_ptr<Classroom> classroom_;
  ImVec2 display_{1280.0f, 720.0f};
};

// push at its default mu (wood on wood, mu_s 0.4, mu_k 0.3), a 10 kg block, its own push at its
// slowest (0.2 N/s, so that the hand does nearly all the pulling: 0.3 N by 1.5 s, 1 % of the
// friction). Pulled by hand at a steady 0.1 m/s or so, slowly enough that the gauge's force grows
// by a few newtons a second: it holds until the hand's pull and the push reach mu_s·m·g, then
// slides with the pull at mu_k·m·g once the gauge's swing has died.
TEST(ForceGauge, AHandPullShowsStaticFrictionAsThePeakAndKineticAsThePlateau) {
  Hands hands("push", {{"mass", "10"}, {"push_rate", "0.2"}});
  hands.frame();
  const double mu_s = hands.lesson().parameter("mu_s").value, mu_k = hands.lesson().parameter("mu_k").value;
  ASSERT_EQ(mu_s, 0.4);
  ASSERT_EQ(mu_k, 0.3);
  const double m = 10.0;
  // A pixel a frame: 60 px/s, about 0.1 m/s at this view's scale.
  const float ppm = hands.classroom().world_camera().pixels_per_metre;
  hands.pull_right("block", 1.0f, 2.0);
  const double hand_speed = 60.0 / static_cast<double>(ppm);
  EXPECT_GT(hand_speed, 0.03);
  EXPECT_LT(hand_speed, 0.3);

  const Scene& scene = hands.lesson().scene();
  const GaugeRecord& gauge = hands.classroom().playback().gauge();
  ASSERT_FALSE(gauge.empty());
  const std::optional<GaugeFigures> figures = gauge.figures(scene.frame_step());
  ASSERT_TRUE(figures.has_value());
  ASSERT_TRUE(figures->plateau.has_value()) << "it slid for less than 0.1 s after settling";
  const double push_at_peak = 0.2 * (figures->peak_time - scene.frame_step());  // the push over the peak's step
  // The peak: hand and push together are static friction's limit (the push read at the start of
  // the step, the hand's force held over it); 1 % for the gauge's rise within the breaking step.
  EXPECT_NEAR(figures->peak + push_at_peak, mu_s * m * g, 0.01 * mu_s * m * g);
  // The gauge alone, as the class reads it: within 2 % of mu_s·m·g (the push is under 0.5 %).
  EXPECT_NEAR(figures->peak, mu_s * m * g, 0.02 * mu_s * m * g);
  // The plateau: the mean reading while it slid, from 0.4 s after the peak; the pull's swing has
  // died to a tenth by then, and the push grows under 0.35 N (1.2 % of mu_k·m·g) over the run.
  EXPECT_NEAR(*figures->plateau, mu_k * m * g, 0.02 * mu_k * m * g);
  // The peak is static, the plateau kinetic: the drop a class sees is (mu_s − mu_k)·m·g.
  EXPECT_NEAR(figures->peak - *figures->plateau, (mu_s - mu_k) * m * g, 0.1 * (mu_s - mu_k) * m * g);
  std::printf("gauge: peak %.4f N at %.3f s (mu_s·m·g %.4f N), plateau %.4f N over %.2f–%.2f s (mu_k·m·g %.4f N), "
              "hand %.3f m/s\n",
              figures->peak, figures->peak_time, mu_s * m * g, *figures->plateau, figures->plateau_from,
              figures->plateau_to, mu_k * m * g, hand_speed);
}

}  // namespace
}  // namespace frictionlab::ui
