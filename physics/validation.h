// Checks of parameters at the edges of physics/: a bad value becomes InvalidInput with a
// message that names where, what and the allowed range, never a NaN further in.
#pragma once

#include <optional>
#include <string>

#include "physics/materials.h"

namespace frictionlab::validation {

[[noreturn]] void reject(const char* where, const char* name, const std::string& range, double value);
void require_positive(const char* where, const char* name, double value);      // > 0 and finite
void require_non_negative(const char* where, const char* name, double value);  // >= 0 and finite
void require_finite(const char* where, const char* name, double value);
// low < value <= high (low_open) or low <= value <= high; false for NaN.
inline bool in_range(double value, double low, double high, bool low_open) {
  return (low_open ? value > low : value >= low) && value <= high;
}
// The same, reported with the unit. Where it runs every step, ask in_range() first so the
// name is built only for the message.
void require_in_range(const std::string& name, double value, double low, double high, bool low_open,
                      const char* unit);

// A number as the command line and --set take it: decimal only ("0.5", "-2", "1e-3"; not
// "0x10", "inf" or " 1"), the whole text, finite and not so close to 0 that a double cannot
// hold it. nullopt when it is not; `why` then says what is wrong when more than "not a number"
// can be said (left empty otherwise).
std::optional<double> parse_decimal(const std::string& text, std::string& why);

// std::strtod(text, nullptr), the same double for any text; the short decimals ("0.25",
// "1.5e-05") are read without strtod's long double arithmetic (in software in WebAssembly).
double read_decimal(const char* text);

// The shortest text that reads back as the same double ("50", "0.45", "1e+20"), as --set,
// setup files and the sliders' boxes write a value: std::to_chars's, and the same text where a
// standard library lacks it (emscripten's libc++ has no floating-point to_chars).
std::string exact_text(double value);

}  // namespace frictionlab::validation
