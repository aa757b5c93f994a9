// The help panel (F1, View > Help): the keys, the mouse and the tools in words, and where the
// window keeps its files. Like Dear ImGui's simple demo windows it is a function over a shown
// flag: whether it is shown is the window's setting (WindowSettings::help, remembered for the
// next class), which its close button clears; nothing else of it outlives the frame.
#pragma once

#include <imgui.h>

#include <string>

namespace frictionlab::classroom {

// The height of the strip the panel is docked in, in pixels with the current font (0 when it is
// not shown): its title bar and three rows of keys, the rest a scroll away. The classroom
// shortens the column by the strip and docks the panel under it, so the panel covers nothing of
// the frame and the world and plots keep their size. Over the plots' row it hid the key plot
// once the run began, and the prediction boxes where the column took it (two teacher trials on a
// projector); under the whole frame it shrank the world (issue 31): no part of a lesson's frame
// is spare at 1920x1080 in projector mode or at 1280x720.
float help_strip_height(bool shown);

// On the page (`browser`) F5 runs the script as last applied; with
// `script_paths` the files are saved in `output_folder` (else they arrive as downloads).
// `corner`, `size`: its strip, the column's width under the column, help_strip_height high.
void help_panel(bool& shown, bool browser, bool script_paths, const std::string& output_folder, ImVec2 corner,
                ImVec2 size);

}  // namespace frictionlab::classroom
