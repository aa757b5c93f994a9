// A script's names (a probe's, a parameter's, a pair's coefficient) as a class reads them. The
// script spells them as identifiers (friction_force, mu_s) for its code; what the window writes
// for the class says them in words (friction force, μs). One function, so that a plot's legend,
// a slider, the values' table and a message all say a name the same way.
#pragma once

#include <string>
#include <string_view>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

// "mu_s" → "μs", "mu_k" → "μk", "mu_s_top" → "μs top", "lubricated_mu" → "lubricated μ",
// "slide_reduced" → "slide reduced", "six_feet_load_" → "six feet load", "theta0" → "θ0",
// "omega" → "ω", "a_x" → "aₓ", "a_x_omega" → "aₓ ω": underscores become spaces (never two in
// a row, none at either end); mu the Greek letter, with its index when s or k follows; theta,
// omega, alpha and epsilon their letters, with the digits after them; a one-letter name and a one-letter
// index its letter with the index below the line, where Unicode has that subscript.
std::string class_words(std::string_view name);

// A parameter as a class reads it: a pair's coefficient in the books' letters with its pair
// ("μs  aluminium / wood"), any other by its name.
std::string parameter_title(const Parameter& parameter);

}  // namespace frictionlab::lessons
