// KeyTaps: a key pressed and let go between two frames (a fast typist, xdotool) still counts
// for the frame after, with its chord's modifier held for that frame.
#include <gtest/gtest.h>

#include "classroom/classroom.h"
#include "classroom/key_taps.h"
#include "draw/headless.h"
#include "draw/imgui_host.h"
#include "lessons/runtime/catalog.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// The modifier keys as the window layer gives them to KeyTaps (GLFW's key codes, ImGui's indices
// under its GLFW backend).
constexpr ModifierKeys test_modifier_keys{{341, 345}, {340, 344}, {342, 346}, {343, 347}};

// Enter pressed and let go between two frames, as a fast typist (or xdotool) does: ImGui 1.86
// reads io.KeysDown when a frame starts, and finds it up at both. The window's KeyTaps holds a
// key pressed since the last frame down through the next one.
TEST(KeyTaps, AnEnterTappedBetweenTwoFramesSetsTheTypedValue) {
  ClassroomHands hands("spring_pull");
  hands.frame();
  ImGuiIO& io = ImGui::GetIO();
  const int enter = io.KeyMap[ImGuiKey_Enter];

  // Without the holder the tap is lost: GLFW's press and release both reach ImGui's backend
  // before the frame, which leaves the key up, and the box keeps 0.3125, the lesson 0.35.
  hands.click("mu_k value");
  hands.type("0.3125");
  io.KeysDown[enter] = true;   // the press
  io.KeysDown[enter] = false;  // its release, before the next frame
  hands.frame();
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.35);
  hands.press(ImGuiKey_Escape);

  KeyTaps taps(test_modifier_keys);
  hands.click("mu_k value");
  hands.type("0.3125");
  taps.pressed(enter);  // down and up again before the frame: io.KeysDown[enter] stays false
  taps.hold(io);
  hands.frame();
  taps.release(io, [](int) { return false; });
  hands.frame();
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.3125);
  EXPECT_FALSE(io.KeysDown[enter]) << "a tapped key is let go after its frame";
}

// Ctrl and V tapped between two frames (a paste): the chord's Ctrl is down in the frame that
// sees the V, as ImGui reads it (io.KeyCtrl), and up again once both are let go.
TEST(KeyTaps, ATappedChordHoldsItsModifierForItsFrame) {
  ImGuiIO io;  // the keyboard's state alone: no frame is drawn
  KeyTaps taps(test_modifier_keys);
  const int ctrl = test_modifier_keys.ctrl[1], v = 86;
  io.KeysDown[ctrl] = io.KeysDown[v] = false;
  io.KeyCtrl = false;
  taps.pressed(ctrl);
  taps.pressed(v);
  taps.hold(io);
  EXPECT_TRUE(io.KeysDown[v]);
  EXPECT_TRUE(io.KeyCtrl) << "the chord is Ctrl+V in its frame";
  EXPECT_FALSE(io.KeyShift);
  taps.release(io, [](int) { return false; });
  EXPECT_FALSE(io.KeyCtrl) << "let go after it";
  EXPECT_FALSE(io.KeysDown[v]);
}

}  // namespace
}  // namespace frictionlab::classroom
