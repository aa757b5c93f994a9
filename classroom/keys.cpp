// The keys' routing (classroom/keys.h) through ImGui's popups and the box being typed in.
#include "classroom/keys.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

#include "classroom/text_boxes.h"

namespace frictionlab::classroom {
namespace {

// How many of ImGui's open popups are dialogs (modal, up to the topmost one); those above them
// are menus: the menu bar's, a combo's list, a tab's menu.
int dialog_levels() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  int level = g.OpenPopupStack.Size;
  while (level > 0) {
    const ImGuiWindow* popup = g.OpenPopupStack[level - 1].Window;
    if (popup != nullptr && (popup->Flags & ImGuiWindowFlags_Modal) != 0) break;
    --level;
  }
  return level;
}

}  // namespace

bool Shortcuts::hit(Key key, bool ctrl) const {
  return std::find(taps.begin(), taps.end(), std::make_pair(key, ctrl)) != taps.end();
}

Shortcuts KeyRouting::route() {
  Shortcuts keys;
  keys.taps.swap(taps_);
  int dialogs = dialog_levels();
  const bool menu_open = ImGui::GetCurrentContext()->OpenPopupStack.Size > dialogs;
  Typing typed = typing();
  // Escape with a dialog open closes it, doing nothing it offers, as its Cancel does (the trial's
  // teacher pressed Escape to leave "Save as a setup" and it stayed); a menu over a dialog closes
  // first. Before the frame's dialogs are drawn, so the one closed draws nothing this frame and
  // a path being typed in it goes with it.
  if (keys.hit(Key::escape) && dialogs > 0) {
    if (menu_open) {
      close_menus_ = true;
      return {};
    }
    ImGui::ClosePopupToLevel(dialogs - 1, true);
    // The keys pressed after Escape in the same frame are the window's again (a quick Escape,
    // Space closes the dialog and plays), or the dialog's below if one is still open; the typing
    // was in the dialog closed. (The frame's taps keep no order: a key pressed just before the
    // Escape counts too.)
    dialogs = dialog_levels();
    typed = Typing::nothing;
    std::erase(keys.taps, std::make_pair(Key::escape, false));
  }
  // Space in a box that takes a number (classroom/text_boxes.h) ends the typing as Enter does (the value
  // kept; ImGui 1.86 reads Enter from the key's state, so it is pressed for this frame only) and
  // then plays: a teacher types the class's answer and presses Space to start. The box lets no
  // blank in. In a box of free text (a file's name), Space is typed.
  if (typed == Typing::number && keys.hit(Key::space)) {
    ImGuiIO& io = ImGui::GetIO();
    enter_for_typing_ = io.KeysDown[io.KeyMap[ImGuiKey_Enter]];
    io.KeysDown[io.KeyMap[ImGuiKey_Enter]] = true;
    io.KeysDownDuration[io.KeyMap[ImGuiKey_Enter]] = 0.0f;
    if (dialogs == 0) play_after_typing_ = true;
    close_menus_ = menu_open;
    return {};
  }
  // Typing a value or a path, or a dialog open: the other keys are the text's or the dialog's
  // (Escape in a box puts its text back, as ImGui does).
  if (typed != Typing::nothing || dialogs > 0) return {};
  // A menu open: Escape closes it; a shortcut closes it and acts (the class watches the run, not
  // the menu; the trial's Space did nothing while the Tools menu was open).
  if (menu_open && !keys.taps.empty()) close_menus_ = true;
  if (keys.hit(Key::escape)) return {};
  return keys;
}

bool KeyRouting::finish() {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  if (enter_for_typing_) {
    g.IO.KeysDown[g.IO.KeyMap[ImGuiKey_Enter]] = *enter_for_typing_;
    enter_for_typing_.reset();
  }
  if (close_menus_) ImGui::ClosePopupToLevel(dialog_levels(), true);
  close_menus_ = false;
  return std::exchange(play_after_typing_, false);
}

}  // namespace frictionlab::classroom
