// The help panel (F1, View > Help): the keys, the mouse and the tools in words, and where the
// window keeps its files. Like Dear ImGui's simple demo windows it is a function over a shown
// flag: whether it is shown is the window's setting (WindowSettings::help, remembered for the
// next class), which its close button clears; nothing else of it outlives the frame.
#pragma once

#include <string>

namespace frictionlab::classroom {

// `scale`: the fonts' scale. On the page (`browser`) F5 runs the script as last applied; with
// `script_paths` the files are saved in `output_folder` (else they arrive as downloads).
void help_panel(bool& shown, float scale, bool browser, bool script_paths, const std::string& output_folder);

}  // namespace frictionlab::classroom
