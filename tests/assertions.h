// Assertions shared by the test suites.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

// |actual - expected| within a fraction `tolerance` of |expected|.
#define EXPECT_RELATIVE(actual, expected, tolerance) \
  EXPECT_NEAR(actual, expected, (tolerance) * std::abs(expected))

#include "physics/materials.h"

namespace frictionlab {

// The call must throw InvalidInput whose message names the parameter and its allowed range.
template <class Call>
void expect_invalid(Call call, const std::string& parameter, const std::string& range) {
  try {
    call();
    ADD_FAILURE() << "no InvalidInput for " << parameter;
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(parameter), std::string::npos) << message;
    EXPECT_NE(message.find(range), std::string::npos) << message;
  }
}

}  // namespace frictionlab
