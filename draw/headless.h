// An OpenGL 3.3 core context with no display and no GPU: EGL's surfaceless platform, which
// Mesa serves with llvmpipe on the CPU, and a framebuffer object to draw frames into.
#pragma once

#include <stdexcept>
#include <string>

#include "draw/image.h"

namespace frictionlab::draw {

// EGL or OpenGL could not start here; the message says which step failed.
struct HeadlessUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class HeadlessContext {
 public:
  HeadlessContext();  // makes the context current; throws HeadlessUnavailable
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  // Makes this context the current one: several may live at once, and GL calls go to the
  // current one.
  void make_current() const;
  // Binds a framebuffer of this size (made anew when the size changes) for the next frame.
  void bind_framebuffer(int width, int height);
  // What was drawn into the framebuffer, top row first (OpenGL reads bottom row first).
  Image read_pixels() const;
  // "llvmpipe (LLVM 15.0.6, 256 bits)": which renderer draws, for the benchmark's record.
  std::string renderer() const;

 private:
  void release_framebuffer();

  void* display_ = nullptr;  // EGLDisplay and EGLContext, kept opaque so EGL stays out of the header
  void* context_ = nullptr;
  unsigned framebuffer_ = 0;
  unsigned colour_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace frictionlab::draw
