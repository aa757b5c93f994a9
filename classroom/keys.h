// The keys the classroom window answers, by name, and their routing. The window layer (window.cpp)
// translates its window system's key codes into these, so nothing but the platform adapters knows
// GLFW; tests press them the same way.
#pragma once

#include <optional>
#include <utility>
#include <vector>

namespace frictionlab::classroom {

enum class Key { space, escape, period, comma, r, f1, f5, f11, p, d, s, e, t, w, l, b, left, right };

// A key as the window layer reported it, with whether Ctrl was held.
using KeyTap = std::pair<Key, bool>;

// The keys of a frame that are the window's shortcuts, once the dialogs, menus and boxes being
// typed in have taken theirs (KeyRouting::route).
struct Shortcuts {
  std::vector<KeyTap> taps;
  bool hit(Key key, bool ctrl = false) const;
};

// Each key reported since the last frame, given its one meaning wherever it lands: with a menu
// open Escape closes it and a shortcut acts and closes it; with a dialog open Escape closes it as
// its Cancel does; while a box is typed in, Space ends the typing as Enter does and plays when
// the box takes a number (text_boxes.h), and is typed in a box of free text. It keeps the keys
// between frames and what the frame's start leaves for its end; it acts on ImGui's popups and io.
class KeyRouting {
 public:
  // A key pressed, each press once: a tap pressed and let go between two frames (a slow machine,
  // a quick finger) never shows in ImGui 1.86's per-frame key state, so shortcuts come from here.
  void pressed(Key key, bool ctrl) { taps_.emplace_back(key, ctrl); }
  // At the frame's start, before its dialogs are drawn: the keys since the last frame routed, and
  // the shortcuts left for the window to act on.
  Shortcuts route();
  // At the frame's end (a box in a menu took its Enter first): Enter let go, the menus a key
  // closed closed. True when the Space that ended a number's typing plays the run now, once the
  // value it kept has been set.
  bool finish();

 private:
  std::vector<KeyTap> taps_;
  std::optional<bool> enter_for_typing_;  // Enter pressed for Space in a number box: whether it was down before
  bool play_after_typing_ = false;        // ... and the run to play when its value is set
  bool close_menus_ = false;              // a key pressed while a menu was open
};

}  // namespace frictionlab::classroom
