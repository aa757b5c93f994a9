// The View menu: the dark theme, projector mode, full screen and the help panel, each with its
// key, and at its foot the prediction panel's items (asking for predictions, the reveal, Predict
// again), which that panel draws. It draws itself and says what was chosen, as the Lesson menu
// does; the classroom changes its window settings and asks the host for full screen.
#pragma once

#include <functional>
#include <optional>

#include "classroom/control_places.h"
#include "classroom/settings.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

struct ViewMenuChoice {
  std::optional<draw::ThemeName> theme;  // the theme ticked or unticked
  bool projector = false;                // projector mode turned on or off
  bool help = false;                     // the help panel shown or hidden
  bool full_screen = false;              // full screen asked of the host, or left
};

// The menu in the menu bar being drawn, ticked as `window` has it; `predictions_items` draws the
// prediction panel's items under a separator while the menu is open.
ViewMenuChoice view_menu(const WindowSettings& window, ControlPlaces& controls, const std::function<void()>& predictions_items);

}  // namespace frictionlab::classroom
