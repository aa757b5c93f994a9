// What the text box being typed in takes, as the window's keys treat it (KeyRouting::route, classroom/keys.h):
// in a box that takes a number, Space ends the typing as Enter does and plays; in a box of free
// text (a file's name), Space is typed. ImGui 1.86 keeps no note of what a box takes, so the boxes
// that take a number say so as they are drawn; a slider's typed value (Ctrl+click) is one by
// nature.
#pragma once

namespace frictionlab::classroom {

// Right after a box that takes a number (or a widget that holds one, as InputInt's group).
void takes_a_number();

enum class Typing { nothing, number, text };
// At the start of a frame: what the box typed in during the last frame takes, if one is.
Typing typing();

}  // namespace frictionlab::classroom
