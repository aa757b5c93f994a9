#include "classroom_state/window_keys.h"

namespace frictionlab::classroom_state {

const std::vector<WindowKey>& window_keys() {
  static const std::vector<WindowKey> keys = {
      {"Space", "play / pause; typing a number, ends the typing and plays", ""},
      {"Esc", "closes a menu or a dialog (with a menu open, keys act too)", ""},
      {". (period)", "one step of the lesson (1/hz s), paused", ""},
      {", (comma)", "one step back (replays the record)", ""},
      {"R", "reset to t = 0, keeping the values set", ""},
      // On the page the editor's Apply is how a change arrives: no file is saved anywhere the
      // student sees, so F5 runs the script as last applied.
      {"F5", "reload the script from its file (saving it does too)",
       "run the lesson's script again from t = 0 (the editor's Apply runs your changes)"},
      {"Ctrl+S", "screenshot of the window (PNG)", ""},
      {"Ctrl+E", "export the history (CSV)", ""},
      {"P", "projector mode: larger text, thicker lines", ""},
      {"D", "dark or light theme", ""},
      {"T", "reveal the theory after the class's predictions; T again hides it (a reveal by mistake)", ""},
      {"F11", "full screen", ""},
      {"W", "start / stop the stopwatch (lesson time)", ""},
      {"L", "the stopwatch's lap", ""},
      {"B", "the forces on one moving body at a time, then on every body again (View > Forces on)", ""},
      {"\u2190 \u2192", "the plots' pages, when they are shown a page at a time", ""},
      {"F1", "the help panel: these keys and the mouse", ""},
  };
  return keys;
}

}  // namespace frictionlab::classroom_state
