#include "physics/validation.h"

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
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

namespace {

// strtod's reading of a decimal text worked out in one step where that is exact (Clinger's
// fast path): at most 15 significant digits are an integer m a double holds exactly, and so is
// 10^k up to 10^22; m·10^k or m/10^k is then one operation, rounded once to nearest: the
// correctly rounded value strtod gives. False, and nothing worked out, for any other text
// (more digits, a larger power of ten, inf, nan, hex, anything after the number): strtod reads
// those. In WebAssembly strtod works in a software long double, and the random settings of
// `check` read and write every value several times over.
bool quick_decimal(const char* text, double& value) {
  static constexpr double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const char* c = text;
  bool negative = false;
  if (*c == '+' || *c == '-') negative = *c++ == '-';
  std::uint64_t mantissa = 0;
  int significant = 0, exponent = 0;
  bool any_digit = false;
  const auto digit = [&](char d) {
    any_digit = true;
    if (significant == 0 && d == '0') return true;  // a leading zero
    if (++significant > 15) return false;
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(d - '0');
    return true;
  };
  for (; *c >= '0' && *c <= '9'; ++c) {
    if (!digit(*c)) return false;
  }
  if (*c == '.') {
    for (++c; *c >= '0' && *c <= '9'; ++c) {
      if (!digit(*c)) return false;
      --exponent;
    }
  }
  if (!any_digit) return false;
  if (*c == 'e' || *c == 'E') {
    ++c;
    bool negative_exponent = false;
    if (*c == '+' || *c == '-') negative_exponent = *c++ == '-';
    if (*c < '0' || *c > '9') return false;
    int given = 0;
    for (; *c >= '0' && *c <= '9'; ++c) {
      if (given > 1000) return false;
      given = given * 10 + (*c - '0');
    }
    exponent += negative_exponent ? -given : given;
  }
  if (*c != '\0') return false;
  if (mantissa == 0) {
    value = negative ? -0.0 : 0.0;
    return true;
  }
  if (exponent < -22 || exponent > 22) return false;
  const auto m = static_cast<double>(mantissa);
  value = exponent < 0 ? m / powers[-exponent] : m * powers[exponent];
  if (negative) value = -value;
  return true;
}

}  // namespace

double read_decimal(const char* text) {
  double value = 0.0;
  return quick_decimal(text, value) ? value : std::strtod(text, nullptr);
}

std::optional<double> parse_decimal(const std::string& text, std::string& why) {
  why.clear();
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  errno = 0;
  // Read whole, finite and far from 0: what strtod would give, with no error to report.
  if (double quick = 0.0; quick_decimal(text.c_str(), quick)) return quick;
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
    if (read_decimal(text) == value) break;
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
