#include "desktop/window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include "draw/gl.h"
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>

#include "classroom/frame_pacing.h"
#include "classroom/key_taps.h"
#include "desktop/glfw_keys.h"
#include "draw/framebuffer.h"
#include "draw/image.h"
#include "draw/imgui_host.h"

namespace frictionlab::desktop {
namespace {

std::string glfw_error;

void remember_error(int /*code*/, const char* description) { glfw_error = description ? description : "unknown"; }

// GLFW's own lifetime: initialised once per window, terminated whatever happens.
struct Glfw {
  Glfw() {
    glfwSetErrorCallback(remember_error);
    if (glfwInit() == GLFW_FALSE) throw NoDisplay("no display to open a window on (" + glfw_error + ")");
  }
  ~Glfw() { glfwTerminate(); }
};

struct WindowDeleter {
  void operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }
};

using WindowPointer = std::unique_ptr<GLFWwindow, WindowDeleter>;

// A place and size on the screen: x, y, width, height.
using ScreenArea = std::array<int, 4>;

// The window opened with an OpenGL 3.3 context made current: at the settings' size, or over the
// primary monitor's work area for a projector (`fill_screen`). `area` is where it was asked for.
WindowPointer open_window(const classroom::WindowSettings& settings, bool fill_screen, ScreenArea& area) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  area = {0, 0, settings.width, settings.height};
  GLFWmonitor* const screen = fill_screen ? glfwGetPrimaryMonitor() : nullptr;
  if (screen != nullptr) {
    int x = 0, y = 0, width = 0, height = 0;
    glfwGetMonitorWorkarea(screen, &x, &y, &width, &height);
    if (width > 0 && height > 0) {
      area[0] = x;
      area[1] = y;
      area[2] = width;
      area[3] = height;
    }
  }
  WindowPointer window(glfwCreateWindow(area[2], area[3], "FrictionLab", nullptr, nullptr));
  if (!window) throw NoDisplay("the display would not open an OpenGL 3.3 window (" + glfw_error + ")");
  if (screen != nullptr) {
    // The work area's size is the window's inside; a window manager adds its title bar, and
    // maximizing lets it fit the two. With no window manager (Xvfb) the size alone does it.
    glfwSetWindowPos(window.get(), area[0], area[1]);
    glfwMaximizeWindow(window.get());
  }
  glfwMakeContextCurrent(window.get());
  glfwSwapInterval(1);  // paced by the display: 60 frames a second on most projectors
  return window;
}

// What the window's callbacks reach: every key press reaches the classroom, and ImGui's
// widgets, even one let go before the next frame.
struct Listeners {
  classroom::Classroom* classroom;
  classroom::KeyTaps taps;
  bool event = false;  // input, or the window shown again: the sleeping loop must draw
};

void event_came(GLFWwindow* from) { static_cast<Listeners*>(glfwGetWindowUserPointer(from))->event = true; }

// Set before ImGui's backend, which calls these before its own.
void listen(GLFWwindow* window, Listeners& listeners) {
  glfwSetWindowUserPointer(window, &listeners);
  glfwSetKeyCallback(window, [](GLFWwindow* from, int key, int, int action, int mods) {
    auto* to = static_cast<Listeners*>(glfwGetWindowUserPointer(from));
    to->event = true;
    if (action != GLFW_PRESS) return;
    to->taps.pressed(key);  // GLFW's key codes are ImGui's indices under its GLFW backend
    if (const std::optional<classroom::Key> named = classroom_key(key)) to->classroom->key_pressed(*named, (mods & GLFW_MOD_CONTROL) != 0);
  });
  // Every other kind of input wakes the loop too; ImGui's backend, installed next, calls these
  // before its own (ImGui 1.86 reads the pointer's place itself each frame, so the move alone
  // would never tell the loop).
  glfwSetCursorPosCallback(window, [](GLFWwindow* from, double, double) { event_came(from); });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* from, int, int, int) { event_came(from); });
  glfwSetScrollCallback(window, [](GLFWwindow* from, double, double) { event_came(from); });
  glfwSetCharCallback(window, [](GLFWwindow* from, unsigned int) { event_came(from); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* from, int) { event_came(from); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* from, int) { event_came(from); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* from) { event_came(from); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* from, int, int) { event_came(from); });
}

// Full screen on the primary monitor and back to the windowed place and size it left.
struct FullScreen {
  bool on = false;
  ScreenArea windowed{};

  // Wanted full screen with no monitor to fill (yet): the wish is kept, and tried each frame.
  void follow(GLFWwindow* window, bool wanted) {
    if (wanted == on) return;
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!on && mode != nullptr) {
      glfwGetWindowPos(window, &windowed[0], &windowed[1]);
      glfwGetWindowSize(window, &windowed[2], &windowed[3]);
      glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
      on = true;
    } else if (on) {
      glfwSetWindowMonitor(window, nullptr, windowed[0], windowed[1], windowed[2], windowed[3], 0);
      on = false;
    }
  }
};

// Paused and untouched, the picture cannot change: sleeps until input, waking four times a second
// so the watchers see a saved script. True where this turn draws a frame: for input or for what
// the watchers found. `last` is the wall clock's, moved past the sleep.
bool slept_until_something_came(classroom::Classroom& classroom, Listeners& listeners, classroom::FramePacing& pacing,
                                double& last) {
  listeners.event = false;
  const double asleep_from = glfwGetTime();
  glfwWaitEventsTimeout(0.25);
  // Paused time is no time to catch up on: Space pressed now starts from the frame shown.
  last = glfwGetTime();
  const bool found = classroom.waited(last - asleep_from);
  if (listeners.event) {
    pacing.input();
    return true;
  }
  return pacing.draw_on_clock(found);
}

// One frame of the classroom, `wall` seconds after the last, into the window's `width` × `height`
// pixels; its title follows the lesson's (`shown_title`, what it shows now).
void draw_frame(classroom::Classroom& classroom, draw::ImGuiHost& host, Listeners& listeners, classroom::FramePacing& pacing,
                GLFWwindow* window, int width, int height, double wall, std::string& shown_title) {
  const classroom::WindowSettings& settings = classroom.window_settings();
  host.make_current();
  const draw::Fonts& fonts = host.prepare(classroom.ui_scale(ImVec2(static_cast<float>(width), static_cast<float>(height))),
                                          settings.theme);
  ImGui_ImplGlfw_NewFrame();
  listeners.taps.hold(ImGui::GetIO());
  host.begin_frame();
  classroom.frame(fonts, ImGui::GetIO().DisplaySize, wall);
  // The lesson's title, and whether a surface is a mystery (never its values).
  if (std::string title = classroom.window_title(); title != shown_title) {
    glfwSetWindowTitle(window, title.c_str());
    shown_title = std::move(title);
  }
  glViewport(0, 0, width, height);
  const ImVec4 clear = ImGui::ColorConvertU32ToFloat4(theme(settings.theme).background);
  glClearColor(clear.x, clear.y, clear.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  host.end_frame();
  pacing.drawn(classroom.idle());
  listeners.taps.release(ImGui::GetIO(), [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; });
}

// The frame just drawn written to PNG where one was asked for: by the classroom (Ctrl+S; a
// failure is told in the window), or by the command line's --screenshot once `frames_left`
// frames are drawn (a failure ends the run). True when that last one is written: the run is over.
bool took_screenshot(classroom::Classroom& classroom, const WindowRun& run, int& frames_left, int width, int height) {
  std::optional<std::string> screenshot = classroom.take_screenshot_request();
  if (frames_left > 0 && --frames_left == 0) screenshot = run.screenshot;
  if (!screenshot) return false;
  glReadBuffer(GL_BACK);
  std::string error;
  try {
    write_png(draw::read_framebuffer(width, height), *screenshot);
  } catch (const std::exception& failure) {
    error = failure.what();
    if (frames_left == 0) throw;
  }
  classroom.screenshot_done(*screenshot, error);
  return frames_left == 0;
}

}  // namespace

void run_window(classroom::Classroom& classroom, const WindowRun& run) {
  Glfw glfw;
  classroom::WindowSettings& settings = classroom.window_settings();
  ScreenArea area{};
  const WindowPointer window = open_window(settings, run.fill_screen, area);

  draw::ImGuiHost host(run.imgui_ini.empty() ? nullptr : run.imgui_ini.c_str());
  Listeners listeners{&classroom, classroom::KeyTaps(glfw_modifier_keys)};
  listen(window.get(), listeners);
  ImGui_ImplGlfw_InitForOpenGL(window.get(), true);
  struct GlfwInput {
    ~GlfwInput() { ImGui_ImplGlfw_Shutdown(); }
  } input;

  if (run.at) classroom.run_to(*run.at);
  int frames_left = run.screenshot.empty() ? -1 : 4;  // a few frames for panels and tables to settle
  FullScreen full_screen{false, area};
  double last = glfwGetTime();
  classroom::WindowSettings saved = settings;
  classroom::FramePacing pacing;
  std::string shown_title = "FrictionLab";
  while (!glfwWindowShouldClose(window.get()) && !classroom.quit_requested()) {
    if (classroom.idle() && frames_left < 0 && pacing.may_sleep()) {
      if (!slept_until_something_came(classroom, listeners, pacing, last)) continue;
    } else {
      glfwPollEvents();
    }
    int width = 0, height = 0;
    glfwGetFramebufferSize(window.get(), &width, &height);
    const double now = glfwGetTime();
    // Minimised: nothing to draw; wait without spinning, and let no time pile up.
    if (width <= 0 || height <= 0) {
      glfwWaitEventsTimeout(0.1);
      last = glfwGetTime();
      continue;
    }
    // A stall (a debugger, a suspended laptop) must not ask the lesson for minutes at once.
    const double wall = run.screenshot.empty() ? std::clamp(now - last, 0.0, 0.25) : 0.0;
    last = now;
    draw_frame(classroom, host, listeners, pacing, window.get(), width, height, wall, shown_title);
    if (took_screenshot(classroom, run, frames_left, width, height)) break;
    if (classroom.take_full_screen_toggle()) settings.full_screen = !settings.full_screen;
    full_screen.follow(window.get(), settings.full_screen);
    glfwSwapBuffers(window.get());
    // A choice the teacher made (theme, projector, help, full screen) is kept at once, so a window
    // that is killed rather than closed still remembers it.
    if (!run.settings_path.empty() && kept_settings_text(settings) != kept_settings_text(saved)) {
      save_settings(settings, run.settings_path);
      saved = settings;
    }
  }

  // The windowed size is kept, full screen or not: leaving full screen next time goes back to it.
  // A window opened over the whole screen for a projector keeps the size read at the start: the
  // screen's would open the next plain window as large, its title bar past the screen's edge.
  if (!run.fill_screen) {
    if (full_screen.on) {
      settings.width = full_screen.windowed[2];
      settings.height = full_screen.windowed[3];
    } else {
      glfwGetWindowSize(window.get(), &settings.width, &settings.height);
    }
  }
  if (!run.settings_path.empty()) save_settings(settings, run.settings_path);
}

}  // namespace frictionlab::desktop
