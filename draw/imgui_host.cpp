#include "draw/imgui_host.h"

#include <backends/imgui_impl_opengl3.h>

#include <cmath>
#include <stdexcept>

namespace frictionlab::draw {

ImGuiHost::ImGuiHost(const char* ini_path) {
  IMGUI_CHECKVERSION();
  ImGuiContext* previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);  // CreateContext makes it current only when there is none
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = ini_path;
  io.LogFilename = nullptr;
  // ImGui 1.86 reads keys from io.KeysDown at the indices io.KeyMap names. A window's backend
  // writes its own codes there; with none (tests, pictures), each key's index is its ImGuiKey.
  for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;
#if defined(__EMSCRIPTEN__)
  const char* const shading_language = "#version 300 es";  // WebGL 2
#else
  const char* const shading_language = "#version 330 core";
#endif
  if (!ImGui_ImplOpenGL3_Init(shading_language)) {
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(previous);
    throw std::runtime_error("ImGui's OpenGL 3 renderer could not load OpenGL (it needs libGL.so.1 from Debian's libgl1)");
  }
}

ImGuiHost::~ImGuiHost() {
  ImGui::SetCurrentContext(context_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(context_);
}

const Fonts& ImGuiHost::prepare(float scale, ThemeName theme) {
  make_current();
  if (std::abs(scale - built_scale_) > 0.02f * scale) {
    ImGuiIO& io = ImGui::GetIO();
    const bool first = built_scale_ == 0.0f;
    io.Fonts->Clear();
    fonts_ = load_fonts(scale, glyph_ranges_);
    built_scale_ = scale;
    // The renderer's font texture was made from the old atlas: make it again from the new one.
    // (Before the first frame the renderer makes it itself.)
    if (!first) {
      ImGui_ImplOpenGL3_DestroyFontsTexture();
      ImGui_ImplOpenGL3_CreateFontsTexture();
    }
  }
  if (theme != styled_theme_ || scale != styled_scale_) {
    apply_imgui_style(theme, scale);
    styled_theme_ = theme;
    styled_scale_ = scale;
  }
  return fonts_;
}

void ImGuiHost::begin_frame() {
  make_current();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

void ImGuiHost::end_frame() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace frictionlab::draw
