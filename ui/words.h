// A script's names (a probe's, a parameter's, a pair's coefficient) as a class reads them. The
// script spells them as identifiers (friction_force, mu_s) for its code; what the window writes
// for the class says them in words (friction force, μs). One function, so that a plot's legend,
// a slider, the values' table and a message all say a name the same way.
#pragma once

#include <string>
#include <string_view>

namespace frictionlab::ui {

// "mu_s" → "μs", "mu_k" → "μk", "mu_s_top" → "μs top", "lubricated_mu" → "lubricated μ",
// "slide_reduced" → "slide reduced", "six_feet_load_" → "six feet load", "theta0" → "θ0",
// "omega" → "ω", "a_x" → "aₓ", "a_x_omega" → "aₓ ω": underscores become spaces (never two in
// a row, none at either end); mu the Greek letter, with its index when s or k follows; theta,
// omega, alpha and epsilon their letters, with the digits after them; a one-letter name and a one-letter
// index its letter with the index below the line, where Unicode has that subscript.
std::string class_words(std::string_view name);

// A file's path as it fits in `room` points of the current ImGui font, never cut: the whole
// path; else its first folders, "…" and the whole file name ("/home/ann/…/wedge.lua"); else the
// file name with "…" in its middle ("check_t…article.lua"); "" when not even "…" fits.
std::string path_that_fits(const std::string& path, float room);

}  // namespace frictionlab::ui
