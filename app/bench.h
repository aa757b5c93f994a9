// Parts of frictionlab bench that live in files of their own.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace frictionlab {

double median(std::vector<double> values);
// The frame_speed.csv text, or empty (with the reason printed) where EGL cannot start.
std::string frame_speed(bool quick, std::ostream& out);
// The window_frame.csv text (CPU time per display frame of the window), or empty where EGL cannot start.
std::string window_frame_speed(bool quick, std::ostream& out);

}  // namespace frictionlab
