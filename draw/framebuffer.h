// Reading back what OpenGL drew, on any platform: the desktop window, the headless context and
// the browser's canvas (WebGL 2) alike.
#pragma once

#include "draw/image.h"

namespace frictionlab::draw {

// The bound framebuffer's pixels (a window's back buffer, or an offscreen one), top row first,
// from the current GL context.
Image read_framebuffer(int width, int height);

}  // namespace frictionlab::draw
