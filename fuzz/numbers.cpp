// Fuzz target: the numbers the command line reads (--hz, --duration, --at, --size) and --set's
// values, one parser for both. Besides not crashing, the two must agree: a text one takes the
// other takes, to the same value; what is taken is finite and written in decimal.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>

#include "app/options.h"
#include "lessons/runtime/build.h"
#include "physics/validation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::string why;
  const std::optional<double> parsed = frictionlab::validation::parse_decimal(text, why);
  if (parsed) {
    if (!std::isfinite(*parsed) || text.find_first_not_of("0123456789+-.eE") != std::string::npos) std::abort();
  }
  double from_option = NAN;
  try {
    from_option = frictionlab::option_number("--hz", text, -1e300, 1e300, false, "");
  } catch (const frictionlab::InvalidInput&) {
  }
  frictionlab::lessons::Parameter parameter;
  parameter.name = "x";
  parameter.min = -1e300;
  parameter.max = 1e300;
  double from_set = NAN;
  try {
    from_set = frictionlab::lessons::parse_parameter_value(parameter, text);
  } catch (const frictionlab::InvalidInput&) {
  }
  // The same reading everywhere (NaN: refused).
  if (std::isnan(from_option) != std::isnan(from_set)) std::abort();
  if (!std::isnan(from_option) && from_option != from_set) std::abort();
  std::map<std::string, std::string> overrides;
  try {
    frictionlab::add_override(text, overrides);
    frictionlab::add_override(text, overrides);  // the same twice is not a conflict
  } catch (const frictionlab::InvalidInput&) {
  }
  return 0;
}
