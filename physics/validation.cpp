#include "physics/validation.h"

#include <cmath>
#include <sstream>

namespace frictionlab::validation {

void reject(const char* where, const char* name, const std::string& range, double value) {
  std::ostringstream message;
  message << where << ": " << name << " must be " << range << ", got " << value;
  throw InvalidInput(message.str());
}

void require_positive(const char* where, const char* name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) reject(where, name, "> 0 and finite", value);
}

void require_non_negative(const char* where, const char* name, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) reject(where, name, ">= 0 and finite", value);
}

void require_finite(const char* where, const char* name, double value) {
  if (!std::isfinite(value)) reject(where, name, "finite", value);
}

void require_in_range(const std::string& name, double value, double low, double high, bool low_open,
                      const char* unit) {
  if (!in_range(value, low, high, low_open)) {
    std::ostringstream message;
    message << name << " = " << value << unit << " is outside the allowed range " << (low_open ? "(" : "[") << low
            << ", " << high << "]";
    throw InvalidInput(message.str());
  }
}

}  // namespace frictionlab::validation
