#include "draw/headless_render.h"

#include "draw/gl.h"
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>

#include "draw/frame.h"

namespace frictionlab::draw {

HeadlessRenderer::HeadlessRenderer(int width, int height, ThemeName theme, float scale)
    : width_(width), height_(height), theme_(theme), gl_(std::make_unique<HeadlessContext>()) {
  try {
    // No imgui.ini: a headless picture must not depend on, or leave, files.
    host_ = std::make_unique<ImGuiHost>(nullptr);
  } catch (const std::runtime_error& error) {
    throw HeadlessUnavailable(std::string("headless rendering cannot start: ") + error.what());
  }
  host_->prepare(scale > 0.0f ? scale : frame_scale(width, height), theme);
}

HeadlessRenderer::~HeadlessRenderer() {
  gl_->make_current();
  host_.reset();
}

Image HeadlessRenderer::render(lessons::Lesson& lesson, const lessons::WorldFraming& framing, FrameRecord* record) {
  gl_->make_current();
  host_->make_current();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
  io.DeltaTime = 1.0f / 60.0f;  // no clock: ImGui's animations must not depend on when we draw
  using clock = std::chrono::steady_clock;
  const auto seconds_since = [](clock::time_point start) {
    return std::chrono::duration<double>(clock::now() - start).count();
  };
  FrameStyle style;
  style.theme = theme_;
  style.fonts = &host_->fonts();
  style.hidden = hidden_;
  auto start = clock::now();
  // Twice: the first pass lets tables and windows settle their sizes, so the picture does not
  // depend on which frame came before.
  for (int pass = 0; pass < 2; ++pass) {
    host_->begin_frame();
    if (record != nullptr) *record = FrameRecord{};
    style.record = pass == 1 ? record : nullptr;
    build_frame(lesson, framing, style, io.DisplaySize);
    ImGui::Render();
  }
  times_.ui = seconds_since(start);
  start = clock::now();
  gl_->bind_framebuffer(width_, height_);
  const ImVec4 clear = ImGui::ColorConvertU32ToFloat4(theme(theme_).background);
  glClearColor(clear.x, clear.y, clear.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();
  times_.raster = seconds_since(start);
  start = clock::now();
  Image image = gl_->read_pixels();
  times_.readback = seconds_since(start);
  return image;
}

Image render_charts(const std::vector<Chart>& charts, int columns, int width, int height) {
  HeadlessContext gl;
  ImGuiHost host(nullptr);
  const float scale = frame_scale(width, height) < 1.0f ? 1.0f : frame_scale(width, height);
  const Fonts& fonts = host.prepare(scale, ThemeName::light);
  const Theme& colours = theme(ThemeName::light);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 60.0f;
  gl.bind_framebuffer(width, height);
  host.begin_frame();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  columns = std::max(columns, 1);
  const int rows = (static_cast<int>(charts.size()) + columns - 1) / columns;
  const float cell_width = static_cast<float>(width) / static_cast<float>(columns);
  const float cell_height = static_cast<float>(height) / static_cast<float>(std::max(rows, 1));
  const float gap = 6.0f * scale;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const float x = cell_width * static_cast<float>(static_cast<int>(i) % columns);
    const float y = cell_height * static_cast<float>(static_cast<int>(i) / columns);
    draw_chart(draw, ImVec2(x + gap, y + gap), ImVec2(cell_width - 2.0f * gap, cell_height - 2.0f * gap), charts[i],
               colours, fonts);
  }
  const ImVec4 clear = ImGui::ColorConvertU32ToFloat4(colours.background);
  glClearColor(clear.x, clear.y, clear.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  host.end_frame();
  return gl.read_pixels();
}

}  // namespace frictionlab::draw
