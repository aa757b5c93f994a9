// Parts of frictionlab bench that live in files of their own.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace frictionlab {

double median(std::vector<double> values);
// The frame_speed.csv text, or empty (with the reason printed) where EGL cannot start.
std::string frame_speed(bool quick, std::ostream& out);
// The window_frame.csv text (CPU time per display frame of the window), or empty where EGL cannot start.
std::string window_frame_speed(bool quick, std::ostream& out);
// stability_map.csv and stability.png (the charts; left out where EGL cannot start), as (path, bytes).
std::vector<std::pair<std::string, std::string>> stability_files(bool quick, const std::string& directory,
                                                                  std::ostream& out);

}  // namespace frictionlab
