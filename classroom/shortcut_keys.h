// The window's keyboard: the keys pressed since the last frame, routed (KeyRouting, keys.h:
// a menu, a dialog or a box being typed in takes its keys first), and what the shortcuts left
// for the window choose. Most are a menu item's key and choose that item, as the menu would
// (WindowChoice, which the classroom carries out); Space, '.', ',', T, W and L are the transport
// bar's, the predictions' and the stopwatch's; ← and → turn the plots' pages, kept here until
// the frame's plots take them.
#pragma once

#include <utility>

#include "classroom/keys.h"
#include "classroom/window_choice.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

class ShortcutKeys {
 public:
  // A key pressed, as the window layer reports it (each press once).
  void pressed(Key key, bool ctrl) { routing_.pressed(key, ctrl); }
  // At the frame's start, before its dialogs are drawn: the keys routed and what their shortcuts
  // choose, with the window in `theme` (D turns it over).
  WindowChoice route(draw::ThemeName theme);
  // At the frame's end (KeyRouting::finish): true when the Space that ended a number's typing
  // plays the run now.
  bool finish() { return routing_.finish(); }
  // The pages the plots turn (→ less ←) since they last took them.
  int take_plot_pages() { return std::exchange(turn_plot_pages_, 0); }

  // What the shortcuts among `keys` choose, with the window in `theme`; pages_turned, the
  // plots' pages they turn.
  static WindowChoice choose(const Shortcuts& keys, draw::ThemeName theme);
  static int pages_turned(const Shortcuts& keys);

 private:
  KeyRouting routing_;
  int turn_plot_pages_ = 0;
};

}  // namespace frictionlab::classroom
