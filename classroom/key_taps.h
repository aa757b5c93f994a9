// ImGui 1.86 reads the keyboard as io.KeysDown when a frame starts. A key pressed and let go
// between two frames (a fast typist's Enter, a scripted one) is down at neither start, so ImGui
// never sees it: the teacher's trial typed k = 80, pressed Enter, and the box showed 80 while
// the lesson kept 50. The window notes every press, and a key pressed since the last frame is
// down in the next one, let go after it if the keyboard has let go of it by then. (ImGui 1.87
// queues input events and no longer needs this; Debian 12 ships 1.86.)
#pragma once

#include <imgui.h>

#include <vector>

namespace frictionlab::classroom {

// The modifier keys' indices in io.KeysDown, left and right: ImGui reads a chord's Ctrl from
// io.KeyCtrl, which 1.86's backend works out only when a key event arrives, so a Ctrl tapped
// with V between frames (a paste) must set it here too.
struct ModifierKeys {
  int ctrl[2], shift[2], alt[2], super[2];
};

class KeyTaps {
 public:
  explicit KeyTaps(ModifierKeys modifiers) : modifiers_(modifiers) {}
  // A key went down (the index ImGui reads it at in io.KeysDown).
  void pressed(int key) { pressed_.push_back(key); }
  // Before ImGui::NewFrame: every key pressed since the last frame is down in this one.
  void hold(ImGuiIO& io) {
    for (const int key : pressed_) {
      if (key < 0 || key >= IM_ARRAYSIZE(io.KeysDown)) continue;
      io.KeysDown[key] = true;
      held_.push_back(key);
    }
    pressed_.clear();
    read_modifiers(io);
  }
  // After the frame: a held key the keyboard no longer holds is let go. `down(key)` asks it.
  template <class Down>
  void release(ImGuiIO& io, Down down) {
    for (const int key : held_) {
      if (!down(key)) io.KeysDown[key] = false;
    }
    held_.clear();
    read_modifiers(io);
  }

 private:
  void read_modifiers(ImGuiIO& io) const {
    const auto either = [&](const int (&keys)[2]) {
      for (const int key : keys) {
        if (key >= 0 && key < IM_ARRAYSIZE(io.KeysDown) && io.KeysDown[key]) return true;
      }
      return false;
    };
    io.KeyCtrl = either(modifiers_.ctrl);
    io.KeyShift = either(modifiers_.shift);
    io.KeyAlt = either(modifiers_.alt);
    io.KeySuper = either(modifiers_.super);
  }

  ModifierKeys modifiers_;
  std::vector<int> pressed_;
  std::vector<int> held_;
};

}  // namespace frictionlab::classroom
