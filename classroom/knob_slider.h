// A slider whose knob never covers its value: ImGui 1.86's SliderScalar writes the value across
// the middle of its frame and moves the knob, a block as tall as the frame, under it, so a value
// near the knob ("5 N/s", "speed ×1") lost a letter or two to it. Here the knob is a strip along
// the frame's bottom edge, in the padding under the text, with the range up to it shaded.
#pragma once

#include <imgui.h>
#include <imgui_internal.h>

#include <string>

#include "classroom/control_places.h"

namespace frictionlab::classroom {

// Where a knob slider put its parts, for tests: its frame, its knob and its value's text.
struct KnobSliderShape {
  ImRect frame, knob, text;
};

// As ImGui::SliderScalar: drag or click to set, arrow keys when focused, Ctrl+click to type. The frame is remembered under `name` and the knob under
// `name` + " knob"; the frame is ImGui's last item afterwards (IsItemDeactivated and the like).
bool knob_slider(const char* id, ImGuiDataType type, void* value, const void* min, const void* max, const char* format,
                 ImGuiSliderFlags flags, ControlPlaces& controls, const std::string& name,
                 KnobSliderShape* shape = nullptr);

// The value a drag lands on: the nearest multiple of the roundest step (1, 2 or 5 times a power
// of ten) as large as one pixel of the slider's `travel` (px), within min and max. A drag then
// reaches 1 kg and 2.5 kg, where it gave 0.98 and 1.02 (a teacher's trial: the mass slider,
// 0.1 to 10 kg over 250 px, 0.04 kg a pixel, could not be set to 1 kg). On a logarithmic slider a
// pixel's worth is relative to the value: ln(max/min)/travel of it.
double round_slider_value(double value, double min, double max, float travel, bool logarithmic);

// Where the knob goes in `frame` for ImGui's grab box `grab` (its position along the frame), and
// the value's text box for text `text_size` wide and high, centred as ImGui writes it.
KnobSliderShape knob_slider_shape(const ImRect& frame, const ImRect& grab, ImVec2 text_size);

}  // namespace frictionlab::classroom
