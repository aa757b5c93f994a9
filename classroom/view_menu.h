// The View menu: the dark theme, projector mode, full screen and the help panel, each with its
// key, whose forces the world draws (B), and at its foot the prediction panel's items (asking for predictions, the reveal, Predict
// again), which that panel draws. It draws itself and says what was chosen, as the Lesson menu
// does; the classroom changes its window settings and asks the host for full screen.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "classroom/control_places.h"
#include "classroom/settings.h"
#include "draw/theme.h"

namespace frictionlab::classroom {

struct ViewMenuChoice {
  std::optional<draw::ThemeName> theme;  // the theme ticked or unticked
  bool projector = false;                // projector mode turned on or off
  bool help = false;                     // the help panel shown or hidden
  bool full_screen = false;              // full screen asked of the host, or left
  // Whose forces the world draws: a moving body's name, or "" for every body's (the Forces on
  // items); B steps to the next (forces_on_next).
  std::optional<std::string> forces_on;
  bool forces_on_next = false;
};

// Whose forces the world draws: every moving body's, or one's at a time. On stacked_blocks every
// force lies on the blocks' middle line, and where they touch five arrows start within 60 px of
// one another: three teacher's trials in a row called that knot the picture's blocker (issue 31).
// A textbook draws each block's free-body diagram apart; the class sees the top block's forces,
// then the bottom one's, and then both together.
struct ForcesShown {
  std::vector<std::string> bodies;  // the lesson's moving bodies, in the script's order
  std::string on;                   // the one whose forces are drawn; empty: every body's
};

// The body after `shown.on` (after the last, every body again; with fewer than two moving
// bodies there is nothing to choose, and it stays every body).
std::string next_forces_on(const ForcesShown& shown);

// The menu in the menu bar being drawn, ticked as `window` and `forces` have it;
// `predictions_items` draws the prediction panel's items under a separator while the menu is open.
ViewMenuChoice view_menu(const WindowSettings& window, const ForcesShown& forces, ControlPlaces& controls,
                         const std::function<void()>& predictions_items);

}  // namespace frictionlab::classroom
