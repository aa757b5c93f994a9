#include "classroom/text_boxes.h"

#include <imgui.h>
#include <imgui_internal.h>

namespace frictionlab::classroom {
namespace {

// Where the note is kept: in the box's own window's storage, under this key, the id of the box
// being typed in there when it takes a number.
ImGuiID number_key() { return ImHashStr("frictionlab: the box typed in takes a number"); }

}  // namespace

void takes_a_number() {
  // While it is typed in, the last item is the text box itself (a group such as InputInt's gives
  // the active id of the box inside it).
  if (!ImGui::IsItemActive()) return;
  ImGuiContext& g = *ImGui::GetCurrentContext();
  g.CurrentWindow->StateStorage.SetInt(number_key(), static_cast<int>(g.ActiveId));
}

Typing typing() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  if (g.ActiveId == 0 || g.InputTextState.ID != g.ActiveId || g.ActiveIdWindow == nullptr) return Typing::nothing;
  if (g.TempInputId == g.ActiveId) return Typing::number;  // a slider's or a drag's typed value
  const int noted = g.ActiveIdWindow->StateStorage.GetInt(number_key(), 0);
  return static_cast<ImGuiID>(noted) == g.ActiveId ? Typing::number : Typing::text;
}

}  // namespace frictionlab::classroom
