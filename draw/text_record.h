// Where each piece of text a panel drew went, and how much of the panel could show it: the
// layout test reads these rectangles to find text cut by its panel's edge, a table cell, a
// slider's frame or a shrunken tab, without looking at pixels.
//
// Recording is off unless a TextRecording is alive; the calls below then cost nothing but a
// test of one pointer. ImGui itself keeps one current context, so one current record is enough.
#pragma once

#include <imgui.h>
#include <imgui_internal.h>

#include <string>
#include <vector>

namespace frictionlab::draw {

struct ShownText {
  std::string panel;  // the ImGui window it was drawn in
  std::string text;
  ImVec4 needed;      // x0, y0, x1, y1: where the whole text goes
  ImVec4 visible;     // what of the screen shows it: its clip rectangle, panel and display
  bool scrolls = false;  // its panel has a vertical scroll bar: text above or below is a scroll away
  // Half a pixel: ImGui rounds positions.
  bool whole_across() const { return needed.x >= visible.x - 0.5f && needed.z <= visible.z + 0.5f; }
  bool whole() const { return whole_across() && needed.y >= visible.y - 0.5f && needed.w <= visible.w + 0.5f; }
};

// While alive, every note_* call adds to `texts`; the one before comes back when it goes.
class TextRecording {
 public:
  explicit TextRecording(std::vector<ShownText>* texts);
  ~TextRecording();
  TextRecording(const TextRecording&) = delete;
  TextRecording& operator=(const TextRecording&) = delete;

 private:
  std::vector<ShownText>* previous_;
};

bool recording_text();
// The last item was `text` laid out whole (ImGui::Text and its kin, wrapped or not): its rect
// against the clip rectangle in force (a table's cell, the panel's inside).
void note_text(const char* text);
// `text` drawn from `start` into `frame` (a slider's value, a box's typed text, a tab's name,
// a button's label): what shows is the frame, within the clip rectangle in force.
void note_text_in(const char* text, ImVec2 start, const ImRect& frame);
// The same, centred in `frame` as sliders and buttons draw it.
void note_text_centred(const char* text, const ImRect& frame);
// `text` drawn by the draw list into `item` (wrapped as it needed): its rect against the clip
// rectangle in force, as note_text has it.
void note_text_at(const char* text, const ImRect& item);
// The current panel's title, in its title bar.
void note_title(const char* title);
// ImGui::TextUnformatted, noted.
void shown_text(const char* text);

}  // namespace frictionlab::draw
