// frictionlab bench, the pictures' part: how long one 1280×720 frame of each lesson takes
// headless (step, UI, rasterization, readback) and how long its PNG takes to encode and write.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <unistd.h>

#include "bench/reports/reports.h"
#include "app/table.h"
#include "draw/headless_render.h"
#include "lessons/runtime/catalog.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab {

std::string frame_speed(bool quick, std::ostream& out, const Progress& progress) {
  using clock = std::chrono::steady_clock;
  const auto seconds_since = [](clock::time_point start) {
    return std::chrono::duration<double>(clock::now() - start).count();
  };
  std::unique_ptr<draw::HeadlessRenderer> renderer;
  try {
    renderer = std::make_unique<draw::HeadlessRenderer>(1280, 720);
  } catch (const std::exception& error) {
    out << "\nFrames: not measured, " << error.what() << '\n';
    return "";
  }
  std::ostringstream csv;
  csv << "lesson,width,height,frames,step_ms,ui_ms,raster_ms,readback_ms,frame_ms,png_encode_ms,png_write_ms,png_bytes\n";
  std::vector<std::vector<std::string>> table{{"lesson", "step", "UI", "raster", "readback", "frame", "PNG encode",
                                               "PNG write", "PNG size"}};
  const std::string scratch =
      (std::filesystem::temp_directory_path() / ("frictionlab_bench_" + std::to_string(::getpid()) + ".png")).string();
  const std::vector<std::string> names = lessons::builtin_lessons();
  for (const std::string& name : names) {
    lessons::Lesson lesson(lessons::resolve_lesson(name));
    const lessons::WorldFraming framing = lessons::WorldFraming::of(lesson);
    // Frames spread over the lesson, so plots with long records are timed too.
    // --quick: two, at half the run and at its end, which shows the report works.
    const int frames = quick ? 2 : 40;
    const long steps_between = static_cast<long>(lesson.duration() * lesson.settings().hz / frames);
    std::vector<double> step, ui, raster, readback, frame, encode, write;
    std::size_t bytes = 0;
    for (int f = 0; f < frames; ++f) {
      progress((static_cast<double>(&name - names.data()) + static_cast<double>(f) / frames) / static_cast<double>(names.size()));
      for (long s = 1; s < steps_between; ++s) lesson.step();
      const auto step_start = clock::now();
      lesson.step();
      step.push_back(seconds_since(step_start));
      const draw::Image image = renderer->render(lesson, framing);
      const draw::FrameTimes& times = renderer->last_times();
      ui.push_back(times.ui);
      raster.push_back(times.raster);
      readback.push_back(times.readback);
      frame.push_back(step.back() + times.total());
      auto png_start = clock::now();
      bytes = draw::encode_png(image).size();
      encode.push_back(seconds_since(png_start));
      png_start = clock::now();
      draw::write_png(image, scratch);
      write.push_back(seconds_since(png_start));
    }
    const auto ms = [](const std::vector<double>& values) { return median(values) * 1e3; };
    csv << name << ",1280,720," << frames << ',' << ms(step) << ',' << ms(ui) << ',' << ms(raster) << ','
        << ms(readback) << ',' << ms(frame) << ',' << ms(encode) << ',' << ms(write) << ',' << bytes << '\n';
    const auto shown = [&](const std::vector<double>& values) { return format_number(ms(values), 3) + " ms"; };
    table.push_back({name, shown(step), shown(ui), shown(raster), shown(readback), shown(frame), shown(encode),
                     shown(write), std::to_string(bytes / 1024) + " KiB"});
  }
  std::filesystem::remove(scratch);
  out << "\nOne 1280x720 frame headless on " << renderer->context().renderer() << " (median of "
      << (quick ? 2 : 40) << " frames over each lesson; wall clock)\n";
  print_table(out, table);
  return csv.str();
}

}  // namespace frictionlab
