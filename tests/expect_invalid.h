// Shared by the test suites: a call must throw InvalidInput whose message names the
// parameter and its allowed range.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "physics/materials.h"

namespace frictionlab {

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
