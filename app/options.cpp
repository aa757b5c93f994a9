#include "app/options.h"

#include <cmath>
#include <cstdio>

#include "physics/validation.h"

namespace frictionlab {

double option_number(const std::string& option, const std::string& text, double low, double high, bool low_open,
                     const char* unit) {
  std::size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // Decimal only: stod would also read "0x10" as 16 and "inf" as infinity.
  const bool decimal = text.find_first_not_of("0123456789+-.eE") == std::string::npos;
  if (used != text.size() || text.empty() || !decimal) throw InvalidInput(option + " " + text + ": not a number");
  validation::require_in_range(option, value, low, high, low_open, unit);
  return value;
}

void add_override(const std::string& text, std::map<std::string, std::string>& overrides) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw InvalidInput("--set " + text + ": write it as NAME=VALUE, as in --set mu_s=0.5");
  overrides[text.substr(0, equals)] = text.substr(equals + 1);
}

bool step_option(const std::string& option, const std::string& value, StepSettings& settings) {
  if (option == "--hz") {
    settings.hz = option_number(option, value, 1.0, 100000.0, false, " steps per second");
  } else if (option == "--substeps") {
    settings.substeps = static_cast<int>(option_number(option, value, 1.0, 1000.0, false, ""));
    if (std::to_string(settings.substeps) != value) throw InvalidInput("--substeps " + value + ": a whole number from 1 to 1000");
  } else if (option == "--friction") {
    settings.treatment = parse_treatment(value);
  } else {
    return false;
  }
  return true;
}

void require_record_fits(double duration, double hz, std::size_t probes, const std::string& advice) {
  const double values = duration * hz * static_cast<double>(probes + 1);  // and the time itself
  if (values <= 2e8) return;
  char text[256];
  std::snprintf(text, sizeof text, "a run of %.4g s at %.6g Hz with %zu probes would record %.3g values (more than 1.6 GB); ",
                duration, hz, probes, values);
  throw InvalidInput(text + advice);
}

}  // namespace frictionlab
