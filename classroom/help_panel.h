// The help panel (F1, View > Help): the keys, the mouse and the tools in words, and where the
// window keeps its files. Like Dear ImGui's simple demo windows it is a function over a shown
// flag: whether it is shown is the window's setting (WindowSettings::help, remembered for the
// next class), which its close button clears; nothing else of it outlives the frame.
#pragma once

#include <imgui.h>

#include <string>

namespace frictionlab::classroom {

// The least room the panel opens in, in points at text scale 1: its title and about six rows
// of keys, the rest a scroll away.
inline constexpr float help_least_height_points = 180.0f;

// On the page (`browser`) F5 runs the script as last applied; with
// `script_paths` the files are saved in `output_folder` (else they arrive as downloads).
// `opens_over`: where it first opens (x0, y0, x1, y1): the room the classroom gives it, over the
// plots (empty before the first run), so that a newcomer's first window shows the world, the
// sliders and the class's questions beside it. Moved or resized, it stays where the user put it.
void help_panel(bool& shown, bool browser, bool script_paths, const std::string& output_folder,
                const ImVec4& opens_over);

}  // namespace frictionlab::classroom
