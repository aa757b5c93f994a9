#include "draw/headless.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>

#include "draw/framebuffer.h"
#include "draw/gl.h"

namespace frictionlab::draw {
namespace {

// Every context shares the one surfaceless display, and eglTerminate ends them all: the
// display is terminated only when the last context goes.
int live_contexts = 0;

std::string egl_failure(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("headless rendering cannot start: ") + step + " failed (EGL error " + code +
         "); it needs Mesa's EGL (Debian packages libegl1 and libegl-mesa0)";
}

}  // namespace

HeadlessContext::HeadlessContext() {
  // The surfaceless platform needs neither X nor Wayland; EGL_DEFAULT_DISPLAY would.
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display == nullptr) throw HeadlessUnavailable(egl_failure("finding eglGetPlatformDisplayEXT"));
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) throw HeadlessUnavailable(egl_failure("opening the surfaceless display"));
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) throw HeadlessUnavailable(egl_failure("eglInitialize"));
  display_ = display;
  // From here a failure also ends the display, unless other contexts still use it. The error
  // is read first: every later EGL call that succeeds resets it.
  const auto give_up = [&](const char* step, EGLContext made = EGL_NO_CONTEXT) {
    const std::string message = egl_failure(step);
    if (made != EGL_NO_CONTEXT) eglDestroyContext(display, made);
    if (live_contexts == 0) eglTerminate(display);
    return HeadlessUnavailable(message);
  };
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) throw give_up("choosing desktop OpenGL");
  // The default surface type is a window, which the surfaceless platform has none of.
  const EGLint config_wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (eglChooseConfig(display, config_wanted, &config, 1, &configs) != EGL_TRUE || configs < 1) {
    throw give_up("finding an OpenGL configuration");
  }
  const EGLint context_wanted[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_wanted);
  if (context == EGL_NO_CONTEXT) throw give_up("creating an OpenGL 3.3 core context");
  context_ = context;
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    throw give_up("making the context current without a surface", context);
  }
  ++live_contexts;
}

HeadlessContext::~HeadlessContext() {
  make_current();
  release_framebuffer();
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  if (--live_contexts == 0) eglTerminate(display_);
}

void HeadlessContext::make_current() const {
  if (eglGetCurrentContext() != context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
}

void HeadlessContext::release_framebuffer() {
  if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_ != 0) glDeleteRenderbuffers(1, &colour_);
  framebuffer_ = colour_ = 0;
  width_ = height_ = 0;
}

void HeadlessContext::bind_framebuffer(int width, int height) {
  make_current();
  if (width != width_ || height != height_) {
    release_framebuffer();
    glGenRenderbuffers(1, &colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      release_framebuffer();
      throw HeadlessUnavailable("headless rendering: a " + std::to_string(width) + "x" + std::to_string(height) +
                                " framebuffer could not be made");
    }
    width_ = width;
    height_ = height;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
}

Image HeadlessContext::read_pixels() const {
  make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  return read_framebuffer(width_, height_);
}

std::string HeadlessContext::renderer() const {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name != nullptr ? name : "unknown";
}

}  // namespace frictionlab::draw
