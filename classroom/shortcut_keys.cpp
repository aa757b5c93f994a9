// The window's keyboard shortcuts (classroom/shortcut_keys.h).
#include "classroom/shortcut_keys.h"

namespace frictionlab::classroom {

WindowChoice ShortcutKeys::route(draw::ThemeName theme) {
  const Shortcuts keys = routing_.route();
  turn_plot_pages_ += pages_turned(keys);
  return choose(keys, theme);
}

WindowChoice ShortcutKeys::choose(const Shortcuts& keys, draw::ThemeName theme) {
  const auto hit = [&](Key key, bool ctrl) { return keys.hit(key, ctrl); };
  WindowChoice chosen;
  // The menu items' keys, as their menus show them.
  chosen.lesson.screenshot = hit(Key::s, true);
  chosen.lesson.export_history = hit(Key::e, true);
  chosen.lesson.reload = hit(Key::f5, false);
  chosen.simulation.reset = hit(Key::r, false);
  chosen.view.full_screen = hit(Key::f11, false);
  chosen.view.help = hit(Key::f1, false);
  chosen.view.projector = hit(Key::p, false);
  if (hit(Key::d, false)) chosen.view.theme = theme == draw::ThemeName::dark ? draw::ThemeName::light : draw::ThemeName::dark;
  // The keys' own.
  chosen.play_pause = hit(Key::space, false);
  chosen.step = hit(Key::period, false);
  chosen.step_back = hit(Key::comma, false);
  chosen.reveal = hit(Key::t, false);
  chosen.stopwatch_start_stop = hit(Key::w, false);
  chosen.stopwatch_lap = hit(Key::l, false);
  chosen.view.forces_on_next = hit(Key::b, false);
  return chosen;
}

int ShortcutKeys::pages_turned(const Shortcuts& keys) {
  // The plots' page buttons are drawn as ← and →: the keys turn the pages too.
  return (keys.hit(Key::right, false) ? 1 : 0) - (keys.hit(Key::left, false) ? 1 : 0);
}

}  // namespace frictionlab::classroom
