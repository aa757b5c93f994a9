#include "web/browser_window.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "classroom/frame_pacing.h"
#include "classroom_state/setup_file.h"
#include "desktop/glfw_keys.h"
#include "draw/framebuffer.h"
#include "draw/gl.h"
#include "draw/image.h"
#include "draw/imgui_host.h"
#include "web/browser_files.h"

namespace frictionlab::web {
namespace {

// A finger on the canvas stands for the mouse: emscripten 3.1.6's GLFW presses the button on a
// touch but never moves the pointer to it, so the page reads touches itself.
struct Finger {
  bool down = false;
  bool pressed = false;   // touched since the last frame: down in the next one, however quick the tap
  bool pointing = false;  // the last pointer was a finger: keep it where it was lifted
  ImVec2 at;
  int id = -1;
};

struct Page {
  classroom::Classroom* classroom = nullptr;
  PageRun run;
  GLFWwindow* window = nullptr;
  std::unique_ptr<draw::ImGuiHost> host;
  classroom::KeyTaps taps{desktop::glfw_modifier_keys};
  Finger finger;
  double last = 0.0;
  classroom::FramePacing pacing;  // the desktop window's rule: no frame while nothing can change
  ImVec2 drawn_size;      // the display the last frame was laid out for
  float drawn_scale = 0.0f;
  bool looping = true;
  long drawn = 0;
  std::string shown_title;
  // What the page around the canvas was last told: the running lesson's script (the editor
  // follows it), the error its script raised while running (the editor marks its line), the
  // theme (the page's bar follows it).
  std::string told_lesson, told_error;
  int told_theme = -1;
  // The window as a setup's text, as the page's address last kept it (none until the first frame).
  std::optional<std::string> told_setup;
  classroom::WindowSettings saved;
  bool full_screen = false;
};

Page* page = nullptr;

double seconds_now() { return emscripten_get_now() / 1000.0; }

// The canvas's size in the screen's own pixels (CSS pixels × devicePixelRatio), so text and
// lines are as sharp as the screen allows.
void canvas_size(int& width, int& height) {
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  const double ratio = emscripten_get_device_pixel_ratio();
  width = std::max(1, static_cast<int>(std::lround(css_width * ratio)));
  height = std::max(1, static_cast<int>(std::lround(css_height * ratio)));
}

// Input arrived: draw again, and a few frames after it for ImGui's hover and focus to settle.
void wake() {
  if (page == nullptr) return;
  page->pacing.input();
  if (!page->looping) {
    page->looping = true;
    page->last = seconds_now();  // time spent asleep is no time for the lesson to catch up on
    emscripten_resume_main_loop();
  }
}

EM_BOOL on_any_event(int, const void*, void*) {
  wake();
  return EM_FALSE;  // the event goes on to GLFW and the page as it would
}

EM_BOOL on_mouse(int, const EmscriptenMouseEvent*, void*) {
  if (page != nullptr) page->finger.pointing = false;
  wake();
  return EM_FALSE;
}

EM_BOOL on_touch(int type, const EmscriptenTouchEvent* event, void*) {
  if (page == nullptr) return EM_FALSE;
  Finger& finger = page->finger;
  const double ratio = emscripten_get_device_pixel_ratio();
  for (int i = 0; i < event->numTouches; ++i) {
    const EmscriptenTouchPoint& touch = event->touches[i];
    if (!touch.isChanged) continue;
    if (type == EMSCRIPTEN_EVENT_TOUCHSTART && !finger.down) finger.id = touch.identifier;
    if (touch.identifier != finger.id) continue;  // one finger is the mouse; a second is ignored
    finger.at = ImVec2(static_cast<float>(touch.targetX * ratio), static_cast<float>(touch.targetY * ratio));
    finger.pointing = true;
    if (type == EMSCRIPTEN_EVENT_TOUCHSTART) finger.down = finger.pressed = true;
    if (type == EMSCRIPTEN_EVENT_TOUCHEND || type == EMSCRIPTEN_EVENT_TOUCHCANCEL) finger.down = false;
  }
  wake();
  return EM_TRUE;  // no scrolling or zooming of the page under a finger that pulls a block
}

// The clipboard: ImGui copies through the browser's clipboard; pasting comes from the page's
// paste event (page.js types it into the focused field), since a page cannot read the
// clipboard when ImGui asks.
void copy_to_clipboard(void*, const char* text) {
  EM_ASM({ frictionlabPage.copy(UTF8ToString($0)); }, text);
}
const char* nothing_to_paste(void*) { return ""; }

// The page's own controls follow the classroom: told when what they show changed, not every frame.
void tell_the_page(classroom::Classroom& classroom) {
  Page& p = *page;
  if (const std::string& lesson = classroom.playback().lesson().path(); lesson != p.told_lesson) {
    p.told_lesson = lesson;
    EM_ASM({ frictionlabPage.lessonChanged(UTF8ToString($0)); }, lesson.c_str());
  }
  if (std::string error = classroom.running_script_error(); error != p.told_error) {
    p.told_error = std::move(error);
    EM_ASM({ frictionlabPage.runningError(UTF8ToString($0)); }, p.told_error.c_str());
  }
  if (const int theme = static_cast<int>(classroom.window_settings().theme); theme != p.told_theme) {
    p.told_theme = theme;
    EM_ASM({ frictionlabPage.setTheme($0); }, classroom.window_settings().theme == draw::ThemeName::dark ? 1 : 0);
  }
  // Values typed and predictions made survive a reload: the page's address keeps the window as a
  // setup (what Copy link gives), once it differs from what the page opened with, so a link
  // given by a teacher stays as it was until something is changed. A prediction that does not
  // read yet is left out: the setup would not open.
  if (!p.run.link_setup_path.empty()) {
    classroom_state::PreparedSetup setup = classroom.current_setup(p.run.link_setup_path);
    std::erase_if(setup.answers, [&](const classroom_state::PreparedSetup::Answer& answer) {
      return !classroom_state::prediction_problem(classroom.playback().lesson(), answer.row, answer.text).empty();
    });
    std::string text = classroom_state::setup_text(setup);
    if (!p.told_setup) {
      p.told_setup = std::move(text);
    } else if (text != *p.told_setup) {
      p.told_setup = std::move(text);
      EM_ASM({ frictionlabPage.keepInAddress(UTF8ToString($0)); }, p.told_setup->c_str());
    }
  }
  // The Lesson menu's "Open a file": the browser allows its chooser for a few seconds after the
  // click that asked, and this frame follows that click.
  if (classroom.take_open_file_request()) EM_ASM({ frictionlabPage.chooseFile(); });
}

void draw_frame() {
  Page& p = *page;
  classroom::Classroom& classroom = *p.classroom;
  const double now = seconds_now();
  const double wall = std::clamp(now - p.last, 0.0, 0.25);  // a hidden tab must not ask for minutes at once
  p.last = now;

  int width = 0, height = 0;
  canvas_size(width, height);
  int canvas_width = 0, canvas_height = 0;
  emscripten_get_canvas_element_size("#canvas", &canvas_width, &canvas_height);
  if (canvas_width != width || canvas_height != height) emscripten_set_canvas_element_size("#canvas", width, height);

  const ImVec2 display(static_cast<float>(width), static_cast<float>(height));
  const float scale = classroom.ui_scale(display);
  // A new size or text scale (a resize, projector mode, another screen) moves every panel, and
  // ImGui's windows take a few frames to find their sizes again (scrollbars come and go): a
  // page that slept after three frames showed stray scrollbars until the next input.
  if (display.x != p.drawn_size.x || display.y != p.drawn_size.y || scale != p.drawn_scale) {
    p.pacing.settle(10);
    p.drawn_size = display;
    p.drawn_scale = scale;
  }
  const draw::Fonts& fonts = p.host->prepare(scale, classroom.window_settings().theme);
  ImGui_ImplGlfw_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  // The canvas's own pixels are the display: GLFW's pointer is in them already.
  io.DisplaySize = display;
  io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  if (p.finger.pointing) {
    io.MousePos = p.finger.at;
    io.MouseDown[0] = p.finger.down || p.finger.pressed;
    p.finger.pressed = false;  // a tap lifted before this frame is let go in the next
  }
  p.taps.hold(io);
  p.host->begin_frame();
  classroom.frame(fonts, display, wall);
  if (std::string title = classroom.window_title(); title != p.shown_title) {
    emscripten_set_window_title(title.c_str());
    p.shown_title = std::move(title);
  }
  tell_the_page(classroom);
  glViewport(0, 0, width, height);
  const ImVec4 clear = ImGui::ColorConvertU32ToFloat4(draw::theme(classroom.window_settings().theme).background);
  glClearColor(clear.x, clear.y, clear.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  p.host->end_frame();
  ++p.drawn;
  p.taps.release(io, [&](int key) { return glfwGetKey(p.window, key) == GLFW_PRESS; });

  // A screenshot is read back before the browser shows the frame (and clears it).
  if (std::optional<std::string> screenshot = classroom.take_screenshot_request()) {
    std::string error;
    try {
      draw::write_png(draw::read_framebuffer(width, height), *screenshot);
    } catch (const std::exception& failure) {
      error = failure.what();
    }
    classroom.screenshot_done(*screenshot, error);
  }
  offer_downloads();

  // Full screen is the browser's. A key asks for it here, in the frame after the key's event:
  // browsers allow it for a few seconds after a key or a click, and refuse it otherwise (then
  // fullscreenchange never comes and the wish is dropped, as the page's message says).
  classroom::WindowSettings& settings = classroom.window_settings();
  if (classroom.take_full_screen_toggle()) settings.full_screen = !settings.full_screen;
  if (settings.full_screen != p.full_screen) {
    EM_ASM({ frictionlabPage.setFullScreen($0); }, settings.full_screen ? 1 : 0);
    p.full_screen = settings.full_screen;
  }
  if (settings.help) p.run.help_to_save.reset();  // shown: from now on the user's own choice
  classroom::WindowSettings to_save = settings;
  if (p.run.help_to_save) to_save.help = *p.run.help_to_save;
  if (!p.run.settings_path.empty() && classroom::kept_settings_text(to_save) != classroom::kept_settings_text(p.saved)) {
    classroom::save_settings(to_save, p.run.settings_path);
    keep_home_folder();
    p.saved = to_save;
  }
}

// One turn of the browser's animation frame. Paused and untouched, the picture cannot change:
// the loop stops until input wakes it, so an open page costs a laptop nothing.
void frame_loop() {
  Page& p = *page;
  draw_frame();
  p.pacing.drawn(p.classroom->idle());
  if (p.pacing.may_sleep()) {
    p.looping = false;
    emscripten_pause_main_loop();
  }
}

}  // namespace

long frames_drawn() { return page == nullptr ? 0 : page->drawn; }
bool sleeping() { return page != nullptr && !page->looping; }

void run_page(classroom::Classroom& classroom, const PageRun& run) {
  if (glfwInit() == GLFW_FALSE) throw std::runtime_error("the browser offers no canvas to draw on");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  int width = 0, height = 0;
  canvas_size(width, height);
  GLFWwindow* window = glfwCreateWindow(width, height, "FrictionLab", nullptr, nullptr);
  if (window == nullptr) throw std::runtime_error("this browser would not give the page WebGL 2");
  glfwMakeContextCurrent(window);
  // GLFW sized the canvas's style too; the page's stylesheet decides its size.
  EM_ASM({ frictionlabPage.canvasSized(); });

  page = new Page;  // lives as long as the page
  page->classroom = &classroom;
  page->run = run;
  page->window = window;
  page->saved = classroom.window_settings();
  if (run.help_to_save) page->saved.help = *run.help_to_save;
  page->full_screen = false;
  page->host = std::make_unique<draw::ImGuiHost>(nullptr);
  glfwSetKeyCallback(window, [](GLFWwindow*, int key, int, int action, int mods) {
    if (action != GLFW_PRESS || page == nullptr) return;
    page->taps.pressed(key);
    if (const std::optional<classroom::Key> named = desktop::classroom_key(key)) {
      page->classroom->key_pressed(*named, (mods & GLFW_MOD_CONTROL) != 0);
    }
  });
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGuiIO& io = ImGui::GetIO();
  io.SetClipboardTextFn = copy_to_clipboard;
  io.GetClipboardTextFn = nothing_to_paste;

  // Everything that can change the picture wakes the loop.
  const char* const canvas = "#canvas";
  emscripten_set_mousedown_callback(canvas, nullptr, EM_TRUE, on_mouse);
  emscripten_set_mousemove_callback(canvas, nullptr, EM_TRUE, on_mouse);
  emscripten_set_mouseup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE, on_mouse);
  // The wheel goes to ImGui from here, not through GLFW: emscripten 3.1.6's GLFW hands on the
  // browser's deltaY as it is, in pixels and growing downwards, where the desktop's GLFW gives
  // notches growing upwards. Passed on, a notch down (100 px) scrolled a panel 100 notches up
  // and zoomed the world out to its limit. A notch is 100 pixels or 3 lines (emscripten's own
  // measure). A page (rarely sent: a system set to scroll by pages) is taken as 10 notches, about
  // what a panel shows (an ImGui notch moves it 5 lines), not emscripten's 80, which would zoom
  // the world 1.2^80 times at one turn of the wheel (the zoom stops at 0.1 and 20 anyway).
  glfwSetScrollCallback(window, nullptr);
  emscripten_set_wheel_callback(canvas, nullptr, EM_TRUE, [](int type, const EmscriptenWheelEvent* wheel, void*) {
    const double per_notch = wheel->deltaMode == DOM_DELTA_PIXEL ? 100.0 : wheel->deltaMode == DOM_DELTA_LINE ? 3.0 : 0.1;
    ImGuiIO& wheel_io = ImGui::GetIO();
    wheel_io.MouseWheel -= static_cast<float>(wheel->deltaY / per_notch);
    wheel_io.MouseWheelH -= static_cast<float>(wheel->deltaX / per_notch);
    on_any_event(type, nullptr, nullptr);
    return EM_TRUE;  // the page under the canvas does not scroll with it
  });
  emscripten_set_touchstart_callback(canvas, nullptr, EM_TRUE, on_touch);
  emscripten_set_touchmove_callback(canvas, nullptr, EM_TRUE, on_touch);
  emscripten_set_touchend_callback(canvas, nullptr, EM_TRUE, on_touch);
  emscripten_set_touchcancel_callback(canvas, nullptr, EM_TRUE, on_touch);
  const auto key_woke = [](int type, const EmscriptenKeyboardEvent*, void*) { return on_any_event(type, nullptr, nullptr); };
  emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE, key_woke);
  emscripten_set_keyup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE, key_woke);
  emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE,
                                 [](int type, const EmscriptenUiEvent*, void*) { return on_any_event(type, nullptr, nullptr); });
  emscripten_set_fullscreenchange_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_TRUE,
                                           [](int type, const EmscriptenFullscreenChangeEvent* change, void*) {
                                             // The browser's full screen, however it came or went (Esc,
                                             // the browser's own F11, the page's button), is the window's.
                                             if (page != nullptr) {
                                               page->classroom->window_settings().full_screen = change->isFullscreen;
                                               page->full_screen = change->isFullscreen;
                                             }
                                             return on_any_event(type, nullptr, nullptr);
                                           });
  page->last = seconds_now();
  emscripten_set_main_loop(frame_loop, 0, false);
}

}  // namespace frictionlab::web

// The page's JavaScript wakes the loop when it changes something the picture shows (a lesson
// applied from the editor, a setting), and reads the frame count for its tests.
extern "C" {
EMSCRIPTEN_KEEPALIVE void frictionlab_wake() { frictionlab::web::wake(); }
EMSCRIPTEN_KEEPALIVE long frictionlab_frames_drawn() { return frictionlab::web::frames_drawn(); }
EMSCRIPTEN_KEEPALIVE int frictionlab_sleeping() { return frictionlab::web::sleeping() ? 1 : 0; }
}
