// The keys the classroom window answers, by name. The window layer (window.cpp) translates its
// window system's key codes into these, so nothing but the platform adapters knows GLFW; tests press them
// the same way.
#pragma once

namespace frictionlab::ui {

enum class Key { space, escape, period, comma, r, f1, f5, f11, p, d, s, e, t, w, l, left, right };

}  // namespace frictionlab::ui
