// A slider's knob never covers its value (issue 31): ImGui's knob moved under the value written
// across the slider, and "speed ×1" and "5 N/s" lost letters to it on a projector. Every slider of
// the window, the Parameters panel's and the transport bar's speed and time bar, at its minimum,
// middle and maximum, light and dark: the knob's box and the value's box share no pixel.
#include "classroom/knob_slider.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "classroom_state/playback.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

bool overlap(const ImRect& a, const ImVec4& b) { return a.Min.x < b.z && b.x < a.Max.x && a.Min.y < b.w && b.y < a.Max.y; }

// The value's text drawn in the slider's frame, from the frame's record of every text.
const draw::ShownText* value_in(const draw::FrameRecord& record, const ImRect& frame) {
  for (const draw::ShownText& text : record.texts) {
    const float middle_x = 0.5f * (text.needed.x + text.needed.z), middle_y = 0.5f * (text.needed.y + text.needed.w);
    if (frame.Contains(ImVec2(middle_x, middle_y))) return &text;
  }
  return nullptr;
}

// A drag lands on round values: the mass slider, 0.1 to 10 kg over 250 px (0.0396 kg a pixel),
// on steps of 0.05 kg, so 0.98 kg is 1 kg and 2.47 kg 2.45; never past its ends; a logarithmic
// slider's step follows the value.
TEST(KnobSlider, ADragLandsOnTheRoundestStepAPixelAllows) {
  EXPECT_DOUBLE_EQ(round_slider_value(0.98, 0.1, 10.0, 250.0f, false), 1.0);
  EXPECT_DOUBLE_EQ(round_slider_value(2.47, 0.1, 10.0, 250.0f, false), 2.45);
  EXPECT_DOUBLE_EQ(round_slider_value(1.1499, 0.1, 10.0, 250.0f, false), 1.15);
  EXPECT_DOUBLE_EQ(round_slider_value(0.1, 0.1, 10.0, 250.0f, false), 0.1);
  EXPECT_DOUBLE_EQ(round_slider_value(9.99, 0.1, 10.0, 250.0f, false), 10.0);
  // A pull rate of 0.5 to 50 N/s over 250 px: 0.198 N/s a pixel, steps of 0.2.
  EXPECT_DOUBLE_EQ(round_slider_value(5.07, 0.5, 50.0, 250.0f, false), 5.0);
  // Logarithmic, 1 to 1000 over 250 px: a pixel is 2.8 % of the value; at 400, 11 a pixel, steps of 20.
  EXPECT_DOUBLE_EQ(round_slider_value(407.0, 1.0, 1000.0, 250.0f, true), 400.0);
  EXPECT_DOUBLE_EQ(round_slider_value(2.07, 1.0, 1000.0, 250.0f, true), 2.1);
  // Nothing to round on: no travel, or a range of one value.
  EXPECT_DOUBLE_EQ(round_slider_value(0.98, 0.1, 10.0, 0.0f, false), 0.98);
  EXPECT_DOUBLE_EQ(round_slider_value(3.0, 3.0, 3.0, 250.0f, false), 3.0);
}

TEST(KnobSlider, TheKnobNeverCoversItsValue) {
  int checked = 0;
  for (const draw::ThemeName theme : {draw::ThemeName::light, draw::ThemeName::dark}) {
    for (const char* lesson : {"push", "stacked_blocks", "spring_pull"}) {
      ClassroomOptions options;
      options.lesson = lesson;
      options.window.projector = true;
      options.window.theme = theme;
      ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
      hands.frame();
      classroom_state::Playback& playback = hands.classroom().playback();
      // Played a while, so the time bar has a range to be at the start, middle and end of.
      playback.run_to(1.0);
      hands.frame();
      const auto check = [&](const std::string& name, const std::string& where) {
        draw::FrameRecord record;
        hands.frame();
        hands.frame(0.0, &record);
        const ImRect frame = hands.control(name);
        const std::optional<ImRect> knob = hands.classroom().control(name + " knob");
        ASSERT_TRUE(knob.has_value()) << where << ": the slider " << name << " has no knob of its own";
        const draw::ShownText* value = value_in(record, frame);
        ASSERT_NE(value, nullptr) << where << ": no value drawn in " << name;
        EXPECT_FALSE(overlap(*knob, value->needed))
            << where << ": the knob (" << knob->Min.x << ", " << knob->Min.y << ")–(" << knob->Max.x << ", " << knob->Max.y
            << ") covers \"" << value->text << "\"";
        EXPECT_GT(knob->GetWidth(), 0.0f) << where;
        EXPECT_GT(knob->GetHeight(), 0.0f) << where;
        ++checked;
      };
      const std::string in = std::string(lesson) + (theme == draw::ThemeName::dark ? ", dark" : "");
      for (const double speed : {classroom_state::Playback::slowest, 1.0, classroom_state::Playback::fastest}) {
        playback.set_speed(speed);
        check("speed", in + ", speed " + std::to_string(speed));
      }
      const double recorded = playback.recorded_until();
      for (const double t : {0.0, 0.5 * recorded, recorded}) {
        playback.scrub_to(t);
        check("scrub", in + ", t = " + std::to_string(t));
      }
      playback.reset();
      hands.frame();
      const std::vector<lessons::Parameter> parameters = hands.lesson().parameters();
      for (const lessons::Parameter& parameter : parameters) {
        // A material pair's sliders are folded under its row until opened.
        if (parameter.is_choice() || !hands.classroom().control(parameter.name + " slider")) continue;
        for (const double value : {parameter.min, 0.5 * (parameter.min + parameter.max), parameter.max}) {
          playback.set_parameter(parameter.name, value);
          check(parameter.name + " slider", in + ", " + parameter.name + " = " + std::to_string(value));
        }
      }
    }
  }
  EXPECT_GE(checked, 40);
}

}  // namespace
}  // namespace frictionlab::classroom
