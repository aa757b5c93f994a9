// GLFW's names for keys, for the two platforms that read the keyboard through GLFW: the desktop
// window (GLFW 3.3 on X11) and the browser page (emscripten's GLFW, which gives DOM keys the
// same codes).
#pragma once

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <optional>

#include "classroom/key_taps.h"
#include "classroom/keys.h"

namespace frictionlab::desktop {

// GLFW's key codes for the keys the classroom answers: the one place they are named.
inline std::optional<classroom::Key> classroom_key(int glfw_key) {
  switch (glfw_key) {
    case GLFW_KEY_SPACE: return classroom::Key::space;
    case GLFW_KEY_ESCAPE: return classroom::Key::escape;
    case GLFW_KEY_PERIOD: return classroom::Key::period;
    case GLFW_KEY_COMMA: return classroom::Key::comma;
    case GLFW_KEY_R: return classroom::Key::r;
    case GLFW_KEY_F1: return classroom::Key::f1;
    case GLFW_KEY_F5: return classroom::Key::f5;
    case GLFW_KEY_F11: return classroom::Key::f11;
    case GLFW_KEY_P: return classroom::Key::p;
    case GLFW_KEY_D: return classroom::Key::d;
    case GLFW_KEY_T: return classroom::Key::t;
    case GLFW_KEY_S: return classroom::Key::s;
    case GLFW_KEY_E: return classroom::Key::e;
    case GLFW_KEY_W: return classroom::Key::w;
    case GLFW_KEY_L: return classroom::Key::l;
    case GLFW_KEY_B: return classroom::Key::b;
    case GLFW_KEY_LEFT: return classroom::Key::left;
    case GLFW_KEY_RIGHT: return classroom::Key::right;
    default: return std::nullopt;
  }
}

// The modifier keys' GLFW codes, which ImGui's GLFW backend uses as io.KeysDown indices.
inline constexpr classroom::ModifierKeys glfw_modifier_keys{{GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL},
                                                 {GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT},
                                                 {GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT},
                                                 {GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER}};

}  // namespace frictionlab::desktop
