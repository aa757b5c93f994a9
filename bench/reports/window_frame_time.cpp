// frictionlab bench, the window's part: the CPU time one display frame of the classroom window
// takes for each lesson at 60 frames a second (the lesson's steps for 1/60 s, then every
// panel built), measured on the classroom's own code on a headless context. Drawing the lists
// is the GPU's job in a classroom; here llvmpipe does it on other threads, timed apart.
#include "draw/gl.h"
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <sstream>

#include "bench/reports/reports.h"
#include "app/table.h"
#include "classroom/classroom.h"
#include "draw/headless.h"
#include "draw/imgui_host.h"
#include "draw/world_view.h"
#include "lessons/runtime/catalog.h"
#include "bench/cheapest_setting.h"

namespace frictionlab {
namespace {

double percentile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1))];
}

// A headless OpenGL context for a report, or none where the machine has none: the report then
// says so under its title and measures nothing.
std::unique_ptr<draw::HeadlessContext> headless_context(std::ostream& out, const char* report) {
  try {
    return std::make_unique<draw::HeadlessContext>();
  } catch (const std::exception& error) {
    out << "\n" << report << ": not measured, " << error.what() << '\n';
    return nullptr;
  }
}

}  // namespace

std::string window_frame_speed(bool quick, std::ostream& out, const Progress& progress) {
  const std::unique_ptr<draw::HeadlessContext> gl = headless_context(out, "Window frames");
  if (!gl) return "";
  const ImVec2 display(1280.0f, 720.0f);
  // Ten seconds at 60 frames a second; --quick, a third of a second, only shows the report
  // works (its 60 frames were the quick run's longest part, a third of the test suite's longest
  // test under the sanitizers).
  const int frames = quick ? 20 : 600;
  std::ostringstream csv;
  csv << "lesson,hz,frames,physics_cpu_ms_median,physics_and_ui_cpu_ms_median,physics_and_ui_cpu_ms_p95,"
         "physics_and_ui_cpu_ms_max,draw_ms_median\n";
  std::vector<std::vector<std::string>> table{
      {"lesson", "physics", "physics + UI", "95th percentile", "worst", "drawing (llvmpipe)"}};
  const std::vector<std::string> names = lessons::builtin_lessons();
  for (const std::string& name : names) {
    draw::ImGuiHost host(nullptr);
    gl->bind_framebuffer(static_cast<int>(display.x), static_cast<int>(display.y));
    classroom::ClassroomOptions options;
    options.lesson = lessons::resolve_lesson(name);
    options.window.help = false;
    classroom::Classroom classroom(options);
    // The lesson alone, the same frames, for the physics' share.
    classroom_state::Playback physics_only(options.lesson, {}, {});
    physics_only.play();
    std::vector<double> physics, whole, draw;
    for (int f = 0; f < frames; ++f) {
      progress((static_cast<double>(&name - names.data()) + static_cast<double>(f) / frames) / static_cast<double>(names.size()));
      // Past the lesson's run it pauses; a class watching keeps it going.
      if (!classroom.playback().playing()) classroom.playback().play();
      if (!physics_only.playing()) physics_only.play();
      double start = thread_cpu_seconds();
      physics_only.advance(1.0 / 60.0);
      physics.push_back(thread_cpu_seconds() - start);

      const draw::Fonts& fonts = host.prepare(classroom.ui_scale(display), classroom.window_settings().theme);
      ImGuiIO& io = ImGui::GetIO();
      io.DisplaySize = display;
      io.DeltaTime = 1.0f / 60.0f;
      start = thread_cpu_seconds();
      host.begin_frame();
      classroom.frame(fonts, display, 1.0 / 60.0);
      ImGui::Render();
      whole.push_back(thread_cpu_seconds() - start);
      const auto draw_start = std::chrono::steady_clock::now();
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glFinish();
      draw.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - draw_start).count());
    }
    const double hz = classroom.playback().lesson().settings().hz;
    csv << name << ',' << hz << ',' << frames << ',' << median(physics) * 1e3 << ',' << median(whole) * 1e3 << ','
        << percentile(whole, 0.95) * 1e3 << ',' << percentile(whole, 1.0) * 1e3 << ',' << median(draw) * 1e3 << '\n';
    const auto ms = [](double seconds) { return format_number(seconds * 1e3, 3) + " ms"; };
    table.push_back({name, ms(median(physics)), ms(median(whole)), ms(percentile(whole, 0.95)),
                     ms(percentile(whole, 1.0)), ms(median(draw))});
  }
  out << "\nOne display frame of the window, 1280x720 at 60 frames a second, the lesson playing at 1x (thread CPU "
         "time, median of "
      << frames << " frames; target 4 ms)\n";
  print_table(out, table);
  return csv.str();
}

std::string force_label_speed(bool quick, std::ostream& out, const Progress& progress) {
  const std::unique_ptr<draw::HeadlessContext> gl = headless_context(out, "Force labels");
  if (!gl) return "";
  // A projector's screen: its thin lanes and large text leave the values fewest places, and
  // send draw_world to its retries most.
  const ImVec2 display(1920.0f, 1080.0f);
  // --quick: a third of a second, which shows the report works (its 60 frames were, after the
  // window's frames, the quick run's longest part under the sanitizers).
  const int frames = quick ? 20 : 600;
  std::ostringstream csv;
  csv << "lesson,width,height,projector,frames,frames_retried,arrows_order_us_median,retries_us_median,"
         "with_retries_us_median,with_retries_us_max,frame_ui_cpu_ms_median\n";
  std::vector<std::vector<std::string>> table{
      {"lesson", "arrows' order", "retries", "with retries", "worst", "frames retried", "whole frame (UI)"}};
  const std::vector<std::string> names = lessons::builtin_lessons();
  for (const std::string& name : names) {
    draw::ImGuiHost host(nullptr);
    gl->bind_framebuffer(static_cast<int>(display.x), static_cast<int>(display.y));
    classroom::ClassroomOptions options;
    options.lesson = lessons::resolve_lesson(name);
    options.window.help = false;
    options.window.projector = true;
    classroom::Classroom classroom(options);
    std::vector<double> first, retries, both, whole;
    int retried = 0;
    for (int f = 0; f < frames; ++f) {
      progress((static_cast<double>(&name - names.data()) + static_cast<double>(f) / frames) / static_cast<double>(names.size()));
      if (!classroom.playback().playing()) classroom.playback().play();
      const draw::Fonts& fonts = host.prepare(classroom.ui_scale(display), classroom.window_settings().theme);
      ImGuiIO& io = ImGui::GetIO();
      io.DisplaySize = display;
      io.DeltaTime = 1.0f / 60.0f;
      draw::force_label_times() = {};
      const double start = thread_cpu_seconds();
      host.begin_frame();
      classroom.frame(fonts, display, 1.0 / 60.0);
      ImGui::Render();
      whole.push_back(thread_cpu_seconds() - start);
      const draw::ForceLabelTimes& times = draw::force_label_times();
      first.push_back(times.arrows_order);
      retries.push_back(times.retries);
      both.push_back(times.arrows_order + times.retries);
      if (times.retried > 0) ++retried;
    }
    const auto us = [](double seconds) { return seconds * 1e6; };
    csv << name << ',' << display.x << ',' << display.y << ",1," << frames << ',' << retried << ',' << us(median(first))
        << ',' << us(median(retries)) << ',' << us(median(both)) << ',' << us(percentile(both, 1.0)) << ','
        << median(whole) * 1e3 << '\n';
    const auto shown = [&](double seconds) { return format_number(us(seconds), 3) + " us"; };
    table.push_back({name, shown(median(first)), shown(median(retries)), shown(median(both)), shown(percentile(both, 1.0)),
                     std::to_string(retried) + " of " + std::to_string(frames),
                     format_number(median(whole) * 1e3, 3) + " ms"});
  }
  out << "\nPlacing the forces' values in one display frame of the window, 1920x1080 in projector mode, the lesson "
         "playing at 1x: in the arrows' order (what is drawn with no retries) and the retries where that order left a "
         "value away from its arrow (wall clock, median of "
      << frames << " frames; the whole frame's UI in thread CPU time)\n";
  print_table(out, table);
  return csv.str();
}

}  // namespace frictionlab
