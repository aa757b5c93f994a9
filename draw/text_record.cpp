#include "draw/text_record.h"

#include <imgui_internal.h>

#include <algorithm>

namespace frictionlab::draw {
namespace {

std::vector<ShownText>* active = nullptr;

ImVec4 meet(const ImRect& a, const ImRect& b) {
  return ImVec4(std::max(a.Min.x, b.Min.x), std::max(a.Min.y, b.Min.y), std::min(a.Max.x, b.Max.x),
                std::min(a.Max.y, b.Max.y));
}

// The clip rectangle in force, within the panel and the display.
ImRect seen_area(const ImRect& within) {
  const ImGuiWindow* window = ImGui::GetCurrentWindowRead();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const ImVec4 in_window = meet(window->ClipRect, within);
  const ImVec4 on_screen = meet(ImRect(in_window), ImRect(ImVec2(0.0f, 0.0f), display));
  return ImRect(on_screen);
}

void add(const char* text, const ImRect& needed, const ImRect& visible) {
  const ImGuiWindow* window = ImGui::GetCurrentWindowRead();
  // An empty text cannot be cut.
  if (text == nullptr || *text == '\0') return;
  active->push_back({window->Name, text, ImVec4(needed.Min.x, needed.Min.y, needed.Max.x, needed.Max.y),
                     ImVec4(visible.Min.x, visible.Min.y, visible.Max.x, visible.Max.y), window->ScrollbarY});
}

}  // namespace

TextRecording::TextRecording(std::vector<ShownText>* texts) : previous_(active) { active = texts; }
TextRecording::~TextRecording() { active = previous_; }

bool recording_text() { return active != nullptr; }

void note_text(const char* text) { note_text_at(text, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax())); }

void note_text_at(const char* text, const ImRect& item) {
  if (active == nullptr) return;
  add(text, item, seen_area(ImGui::GetCurrentWindowRead()->Rect()));
}

void note_text_in(const char* text, ImVec2 start, const ImRect& frame) {
  if (active == nullptr) return;
  const ImVec2 size = ImGui::CalcTextSize(text, nullptr, true);
  add(text, ImRect(start, ImVec2(start.x + size.x, start.y + size.y)), seen_area(frame));
}

void note_text_centred(const char* text, const ImRect& frame) {
  if (active == nullptr) return;
  const ImVec2 size = ImGui::CalcTextSize(text, nullptr, true);
  const ImVec2 centre = frame.GetCenter();
  const ImVec2 start(centre.x - 0.5f * size.x, centre.y - 0.5f * size.y);
  add(text, ImRect(start, ImVec2(start.x + size.x, start.y + size.y)), seen_area(frame));
}

void note_title(const char* title) {
  if (active == nullptr) return;
  const ImGuiWindow* window = ImGui::GetCurrentWindowRead();
  if ((window->Flags & ImGuiWindowFlags_NoTitleBar) != 0) return;
  const ImRect bar = window->TitleBarRect();
  const ImVec2 padding = ImGui::GetStyle().FramePadding;
  const ImVec2 size = ImGui::CalcTextSize(title, nullptr, true);
  const ImVec2 start(bar.Min.x + padding.x, bar.Min.y + padding.y);
  // The title bar's own clip rectangle: the panel's outer edge less its border.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  add(title, ImRect(start, ImVec2(start.x + size.x, start.y + size.y)),
      ImRect(meet(bar, ImRect(ImVec2(0.0f, 0.0f), display))));
}

void shown_text(const char* text) {
  ImGui::TextUnformatted(text);
  note_text(text);
}

}  // namespace frictionlab::draw
