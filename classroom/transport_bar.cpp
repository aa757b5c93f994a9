// The transport bar (classroom/transport_bar.h): play, step, reset, the speed and the time bar.
#include "classroom/transport_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "classroom/knob_slider.h"
#include "draw/text_record.h"
#include "draw/words.h"

namespace frictionlab::classroom {

TransportBar::Shape TransportBar::shape(const std::string& room_for, float width, float scale, ImFont* words_font) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float s = scale;
  Shape shape;
  // The controls before the time bar, and the time bar's own words for a run under 1000 s: a
  // bar kept for 0000.000 s left a projector's 1920 px no room for the run's end notice beside
  // it (a line under it then took 40 px from the world and the plots). Past 1000 s, where the
  // bar is at its narrowest (a projector), its readout is cut at the bar's ends.
  shape.controls = 3.0f * 80.0f * s + 150.0f * s + 4.0f * style.ItemSpacing.x;
  shape.bar = ImGui::CalcTextSize("t = 000.000 s of 000.00 s recorded").x + 2.0f * style.FramePadding.x;
  const float inside = width - 2.0f * style.WindowPadding.x;
  // A line of the small font: the words are the bar's asides, and each pixel of height the bar
  // takes is the world's and the column's, from the lesson's opening.
  ImGui::PushFont(words_font);
  const float words_width = room_for.empty() ? 0.0f : ImGui::CalcTextSize(room_for.c_str()).x + style.ItemSpacing.x;
  const float line = ImGui::GetTextLineHeight();
  ImGui::PopFont();
  // The words beside the bar when the lesson's own fit there, else on a line of their own under it.
  shape.words_below = shape.controls + shape.bar + words_width > inside;
  const float words = shape.words_below ? line + style.ItemSpacing.y : 0.0f;
  shape.height = ImGui::GetFrameHeight() + words + 2.0f * style.WindowPadding.y + 2.0f * s;
  return shape;
}

namespace {

// Play (Pause while playing), Step, Reset and the speed slider, each noted where it is drawn.
void buttons_and_speed(classroom_state::Playback& playback, float s, double& speed_kept, ControlPlaces& controls) {
  const float button = 80.0f * s;
  const auto noted_button = [&](const char* label, const char* name) {
    const bool pressed = ImGui::Button(label, ImVec2(button, 0.0f));
    remember_item(controls, name);
    draw::note_text_centred(label, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
    return pressed;
  };
  if (noted_button(playback.playing() ? "Pause" : "Play", "play")) playback.toggle();
  ImGui::SameLine();
  if (noted_button("Step", "step")) playback.step_once();
  ImGui::SameLine();
  if (noted_button("Reset", "reset")) playback.reset();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150.0f * s);
  float speed = static_cast<float>(playback.speed());
  const float slowest = static_cast<float>(classroom_state::Playback::slowest), fastest = static_cast<float>(classroom_state::Playback::fastest);
  if (knob_slider("##speed", ImGuiDataType_Float, &speed, &slowest, &fastest, "speed \u00d7%.2g",
                  ImGuiSliderFlags_Logarithmic, controls, "speed")) {
    // Real time is a speed a teacher comes back to: near ×1 (within 10 %) the slider gives
    // exactly ×1, which a logarithmic slider's pixels otherwise seldom land on.
    if (std::abs(std::log(speed)) < 0.1f) speed = 1.0f;
    playback.set_speed(speed);
    speed_kept = playback.speed();
  }
  char shown[32];
  std::snprintf(shown, sizeof shown, "speed \u00d7%.2g", static_cast<double>(speed));
  draw::note_text_centred(shown, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
}

// The window's words (`said`), up to `most_lines` lines of the current font in what the time bar
// leaves of its line, or on the line under it (`below`). True where they are cut and the pointer
// is over them: the caller shows them whole.
bool notice_lines(const std::string& said, bool below, int most_lines, ImVec2 corner, ImVec2 size) {
  const float line = ImGui::GetTextLineHeight();
  const std::vector<std::string> lines = draw::lines_that_fit(said, ImGui::GetContentRegionAvail().x, most_lines);
  if (lines.empty()) return false;
  float widest = 0.0f;
  for (const std::string& words : lines) widest = std::max(widest, ImGui::CalcTextSize(words.c_str()).x);
  const ImVec2 extent(widest, static_cast<float>(lines.size()) * line);
  ImVec2 first;
  if (below) {
    first = ImGui::GetCursorScreenPos();
    ImGui::Dummy(extent);
  } else {
    // Centred in the bar's height: drawn, not laid out as items, so that two lines may use
    // the bar's padding without making it scroll.
    first = ImVec2(ImGui::GetCursorScreenPos().x, corner.y + 0.5f * (size.y - extent.y));
  }
  ImDrawList* drawing = ImGui::GetWindowDrawList();
  const ImU32 colour = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const ImVec2 at(first.x, first.y + static_cast<float>(i) * line);
    drawing->AddText(at, colour, lines[i].c_str());
    draw::note_text_in(lines[i].c_str(), at, ImRect(corner, ImVec2(corner.x + size.x, corner.y + size.y)));
  }
  // Cut or not, told word by word: the lines join their words with one space where the
  // notices were joined with two.
  std::string shown, whole;
  for (const std::string& words : lines) shown += (shown.empty() ? "" : " ") + words;
  for (const std::string& words : draw::lines_that_fit(said, INFINITY, 1)) whole += words;
  return shown != whole && ImGui::IsWindowHovered() &&
         ImGui::IsMouseHoveringRect(first, ImVec2(first.x + extent.x, first.y + extent.y));
}

}  // namespace

void TransportBar::time_bar(classroom_state::Playback& playback, float width, ControlPlaces& controls) {
  const Scene& scene = playback.lesson().scene();
  ImGui::SetNextItemWidth(width);
  double t = scrubbing_to ? *scrubbing_to : scene.time();
  const double start = 0.0, end = std::max(playback.recorded_until(), scene.frame_step());
  char format[64];
  std::snprintf(format, sizeof format, "t = %%.3f s of %.2f s recorded", playback.recorded_until());
  // Forward is a few steps a frame; back is a replay from t = 0, which on a long run takes a
  // while: it waits until the bar is let go.
  if (knob_slider("##scrub", ImGuiDataType_Double, &t, &start, &end, format, ImGuiSliderFlags_None, controls, "scrub")) {
    if (t >= scene.time() && !scrubbing_to) {
      playback.scrub_to(t);
    } else {
      scrubbing_to = t;
      playback.pause();
    }
  }
  if (ImGui::IsItemDeactivated() && scrubbing_to) {
    playback.scrub_to(*scrubbing_to);
    scrubbing_to.reset();
  }
  char shown[96];
  std::snprintf(shown, sizeof shown, format, t);
  draw::note_text_centred(shown, ImRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax()));
}

void TransportBar::draw(ImVec2 corner, ImVec2 size, classroom_state::Playback& playback, const std::string& said,
                        const std::string& room_for, float scale, ImFont* words_font, double& speed_kept,
                        ControlPlaces& controls) {
  const float s = scale;
  ImGui::SetNextWindowPos(corner);
  ImGui::SetNextWindowSize(size);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (ImGui::Begin("###transport", nullptr, flags)) {
    const Shape shape = TransportBar::shape(room_for, size.x, scale, words_font);
    buttons_and_speed(playback, s, speed_kept, controls);
    ImGui::SameLine();
    // The words on their one line: under the bar, or beside it in the room kept for the run's end
    // notice from the lesson's opening, said or not, so that the bar keeps its width (it shrank
    // as the notice came, its readout moving under the pointer). Longer words are cut to it.
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    ImGui::PushFont(words_font);
    const float room = shape.words_below || room_for.empty() ? 0.0f : ImGui::CalcTextSize(room_for.c_str()).x + spacing;
    // Beside the bar, as many lines of the small font as the bar's whole height holds, up to two
    // (in projector mode one line of 470 px cut every longer notice in its middle); under it, one.
    const float line = ImGui::GetTextLineHeight();
    const int most_lines = shape.words_below ? 1 : std::clamp(static_cast<int>((size.y - 2.0f * s) / line), 1, 2);
    ImGui::PopFont();
    time_bar(playback, std::max(shape.bar, ImGui::GetContentRegionAvail().x - room), controls);
    // The words in what the time bar leaves of the line (its own under it).
    if (!shape.words_below) ImGui::SameLine();
    ImGui::PushFont(words_font);
    const bool cut_and_hovered = notice_lines(said, shape.words_below, most_lines, corner, size);
    ImGui::PopFont();
    if (cut_and_hovered) {
      // In the window's own font, wrapped at half the screen: one line of a long notice ran past
      // both of its edges.
      ImGui::BeginTooltip();
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 0.5f * ImGui::GetIO().DisplaySize.x);
      ImGui::TextUnformatted(said.c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndTooltip();
    }
  }
  ImGui::End();
}

}  // namespace frictionlab::classroom
