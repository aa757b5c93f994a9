#include "ui/imgui_host.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>

#include <cmath>
#include <stdexcept>

namespace frictionlab::ui {

ImGuiHost::ImGuiHost(const char* ini_path) {
  IMGUI_CHECKVERSION();
  ImGuiContext* previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);  // CreateContext makes it current only when there is none
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = ini_path;
  io.LogFilename = nullptr;
  // Keys are GLFW's key codes, in a window (its backend writes them) and in tests alike.
  const int keys[][2] = {{ImGuiKey_Tab, GLFW_KEY_TAB},           {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
                         {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},  {ImGuiKey_UpArrow, GLFW_KEY_UP},
                         {ImGuiKey_DownArrow, GLFW_KEY_DOWN},    {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
                         {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN}, {ImGuiKey_Home, GLFW_KEY_HOME},
                         {ImGuiKey_End, GLFW_KEY_END},           {ImGuiKey_Insert, GLFW_KEY_INSERT},
                         {ImGuiKey_Delete, GLFW_KEY_DELETE},     {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
                         {ImGuiKey_Space, GLFW_KEY_SPACE},       {ImGuiKey_Enter, GLFW_KEY_ENTER},
                         {ImGuiKey_Escape, GLFW_KEY_ESCAPE},     {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
                         {ImGuiKey_A, GLFW_KEY_A},               {ImGuiKey_C, GLFW_KEY_C},
                         {ImGuiKey_V, GLFW_KEY_V},               {ImGuiKey_X, GLFW_KEY_X},
                         {ImGuiKey_Y, GLFW_KEY_Y},               {ImGuiKey_Z, GLFW_KEY_Z}};
  for (const auto& [imgui_key, glfw_key] : keys) io.KeyMap[imgui_key] = glfw_key;
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
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

}  // namespace frictionlab::ui
