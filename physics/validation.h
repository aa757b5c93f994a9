// Checks of parameters at the edges of physics/: a bad value becomes InvalidInput with a
// message that names where, what and the allowed range, never a NaN further in.
#pragma once

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

}  // namespace frictionlab::validation
