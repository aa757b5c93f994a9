#include "physics/validation.h"

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

std::optional<double> parse_decimal(const std::string& text, std::string& why) {
  why.clear();
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  if (!std::isfinite(value)) {
    why = "too large a number for a double (beyond ±1.8e308)";
    return std::nullopt;
  }
  // strtod gives a subnormal or 0 for 1e-320 and says ERANGE: too close to 0 to be held.
  if (errno == ERANGE && std::abs(value) < DBL_MIN) {
    why = "too close to 0 for a double to hold (below 2.2e-308); give 0 or a larger number";
    return std::nullopt;
  }
  return value;
}

std::string exact_text(double value) {
  char text[32];
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
#else
  // emscripten's libc++ has no floating-point to_chars: what it gives, worked out by hand. The
  // fewest significant digits that read back as the same double, written plainly ("50",
  // "0.0025") unless scientific notation is shorter ("1e+20"), as to_chars chooses.
  if (!std::isfinite(value)) {
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
  const std::string scientific = text;
  const int exponent = std::atoi(std::strchr(text, 'e') + 1);
  std::snprintf(text, sizeof text, "%.*f", std::max(0, digits - 1 - exponent), value);
  const std::string plain = text;
  // %e drops a mantissa's trailing point but to_chars writes "1e+20" for one digit: the same.
  return plain.size() <= scientific.size() ? plain : scientific;
#endif
}

}  // namespace frictionlab::validation
