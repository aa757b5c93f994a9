#include "classroom/knob_slider.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace frictionlab::classroom {

KnobSliderShape knob_slider_shape(const ImRect& frame, const ImRect& grab, ImVec2 text_size) {
  KnobSliderShape shape;
  shape.frame = frame;
  // ImGui centres the value in the frame (RenderTextClipped with align 0.5).
  const ImVec2 corner(frame.Min.x + std::max(0.0f, 0.5f * (frame.GetWidth() - text_size.x)),
                      frame.Min.y + std::max(0.0f, 0.5f * (frame.GetHeight() - text_size.y)));
  shape.text = ImRect(corner, ImVec2(corner.x + text_size.x, corner.y + text_size.y));
  // Under the text, down to the frame's edge: the frame's padding, which no letter reaches. At
  // least a text's height wide, so it reads as a knob, and inside the frame at either end.
  const float width = std::min(frame.GetWidth(), std::max(grab.GetWidth(), text_size.y));
  const float middle = std::clamp(grab.GetCenter().x, frame.Min.x + 0.5f * width, frame.Max.x - 0.5f * width);
  // A pixel of air between the text and the knob, where the padding has it.
  const float top = std::min(shape.text.Max.y + 1.0f, frame.Max.y - 1.0f);
  shape.knob = ImRect(ImVec2(middle - 0.5f * width, top), ImVec2(middle + 0.5f * width, frame.Max.y));
  return shape;
}

double round_slider_value(double value, double min, double max, float travel, bool logarithmic) {
  if (!(travel > 0.0f) || !(max > min)) return value;
  const double per_pixel = logarithmic ? (min > 0.0 ? std::abs(value) * std::log(max / min) / travel : 0.0) : (max - min) / travel;
  if (!(per_pixel > 0.0) || !std::isfinite(per_pixel)) return value;
  const double power = std::pow(10.0, std::floor(std::log10(per_pixel)));
  double step = 10.0 * power;
  for (const double times : {1.0, 2.0, 5.0}) {
    if (times * power >= per_pixel) {
      step = times * power;
      break;
    }
  }
  // Written with twelve figures and read back: 23 steps of 0.05 is 1.1500000000000001, which
  // the typed value's box would show whole.
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", std::round(value / step) * step);
  return std::clamp(std::strtod(text, nullptr), min, max);
}

bool knob_slider(const char* id_text, ImGuiDataType type, void* value, const void* min, const void* max, const char* format,
                 ImGuiSliderFlags flags, ControlPlaces& controls, const std::string& name, KnobSliderShape* shape) {
  ImGuiWindow* window = ImGui::GetCurrentWindow();
  if (window->SkipItems) return false;
  ImGuiContext& g = *ImGui::GetCurrentContext();
  const ImGuiStyle& style = g.Style;
  const ImGuiID id = window->GetID(id_text);
  const float width = ImGui::CalcItemWidth();
  const ImRect frame(window->DC.CursorPos,
                     ImVec2(window->DC.CursorPos.x + width, window->DC.CursorPos.y + g.FontSize + 2.0f * style.FramePadding.y));
  ImGui::ItemSize(frame, style.FramePadding.y);
  if (!ImGui::ItemAdd(frame, id, &frame, ImGuiItemFlags_Inputable)) return false;
  remember_item(controls, name);

  // Taken hold of by a click or by the keyboard's navigation, as ImGui's own slider is; a
  // Ctrl+click or a Tab into it types a value instead (ImGui's text box in the frame).
  const bool hovered = ImGui::ItemHoverable(frame, id);
  bool typing = ImGui::TempInputIsActive(id);
  if (!typing) {
    const bool tabbed = (g.LastItemData.StatusFlags & ImGuiItemStatusFlags_FocusedByTabbing) != 0;
    const bool clicked = hovered && g.IO.MouseClicked[0];
    if (tabbed || clicked || g.NavActivateId == id || g.NavActivateInputId == id) {
      ImGui::SetActiveID(id, window);
      ImGui::SetFocusID(id, window);
      ImGui::FocusWindow(window);
      g.ActiveIdUsingNavDirMask |= (1 << ImGuiDir_Left) | (1 << ImGuiDir_Right);
      typing = tabbed || (clicked && g.IO.KeyCtrl) || g.NavActivateInputId == id;
    }
  }
  if (typing) {
    const bool clamp = (flags & ImGuiSliderFlags_AlwaysClamp) != 0;
    return ImGui::TempInputScalar(frame, id, id_text, type, value, format, clamp ? min : nullptr, clamp ? max : nullptr);
  }
  const ImU32 frame_colour =
      ImGui::GetColorU32(g.ActiveId == id ? ImGuiCol_FrameBgActive : hovered ? ImGuiCol_FrameBgHovered : ImGuiCol_FrameBg);
  ImGui::RenderNavHighlight(frame, id);
  ImGui::RenderFrame(frame.Min, frame.Max, frame_colour, true, style.FrameRounding);
  ImRect grab;
  const bool changed = ImGui::SliderBehavior(frame, id, type, value, min, max, format, flags, &grab);
  if (changed) ImGui::MarkItemEdited(id);

  char text[96];
  const char* text_end = text + ImGui::DataTypeFormatString(text, IM_ARRAYSIZE(text), type, value, format);
  const ImVec2 text_size = ImGui::CalcTextSize(text, text_end);
  const KnobSliderShape parts = knob_slider_shape(frame, grab, text_size);
  // The range up to the knob shaded along the bottom, so where the value sits reads at a glance.
  ImDrawList* draw = window->DrawList;
  const ImU32 knob_colour = ImGui::GetColorU32(g.ActiveId == id ? ImGuiCol_SliderGrabActive : ImGuiCol_SliderGrab);
  draw->AddRectFilled(ImVec2(frame.Min.x, parts.knob.Min.y), ImVec2(parts.knob.Min.x, parts.knob.Max.y),
                      ImGui::GetColorU32(ImGuiCol_SliderGrab, 0.35f), style.FrameRounding, ImDrawFlags_RoundCornersBottomLeft);
  draw->AddRectFilled(parts.knob.Min, parts.knob.Max, knob_colour, 0.0f);
  ImGui::RenderTextClipped(frame.Min, frame.Max, text, text_end, &text_size, ImVec2(0.5f, 0.5f));
  controls[name + " knob"] = parts.knob;
  if (shape != nullptr) *shape = parts;
  return changed;
}

}  // namespace frictionlab::classroom
