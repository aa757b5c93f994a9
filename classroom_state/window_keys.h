// The keys the classroom window answers and what each does, in one list: the help panel (F1),
// the manual page's KEYS section and the teachers' guide's table are written from it or checked
// against it, so none of them leaves a key out (the manual lacked T, W, L, the arrows and Esc).
// Plain words, no ImGui: the manual's program links this layer only.
#pragma once

#include <string_view>
#include <vector>

namespace frictionlab::classroom_state {

struct WindowKey {
  std::string_view key;          // as printed on the keyboard: "Space", "Ctrl+S", "← →"
  std::string_view does;         // what it does in the window
  std::string_view on_the_page;  // what it does on the web page where that differs; "" where not
};

// In the order the help panel lists them: playing, stepping and resetting first.
const std::vector<WindowKey>& window_keys();

}  // namespace frictionlab::classroom_state
