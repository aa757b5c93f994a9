// Fuzz target: the lesson commands' command line. The bytes are split at NUL or newline into
// arguments for `list`, `run` or `check` (the first byte picks which), and the command is carried
// out as main() would. Bad input must end in InvalidInput (exit 2), never a crash. Nothing may be
// written: --csv is dropped with its value, and runs are kept short (the command line's own
// limits allow a day of simulated time) so that one input cannot hold the fuzzer for minutes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "app/modes.h"
#include "physics/materials.h"

namespace {

bool too_long(const std::string& option, const std::string& value) {
  const double number = std::strtod(value.c_str(), nullptr);
  if (option == "--duration") return number > 5.0;
  if (option == "--hz") return number > 2000.0;
  if (option == "--substeps") return number > 8.0;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  ::setenv("FRICTIONLAB_LESSONS", FRICTIONLAB_LESSONS_FOR_FUZZING, 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::vector<std::string> args;
  std::string current;
  for (std::size_t i = 1; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\0' || c == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  args.push_back(current);
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--csv") {
      ++i;  // and its value: the fuzzer writes no files
      continue;
    }
    if (i + 1 < args.size() && too_long(args[i], args[i + 1])) return 0;
    kept.push_back(args[i]);
  }
  std::ostringstream out;
  try {
    switch (data[0] % 3) {
      case 0: frictionlab::run_list(kept, out); break;
      case 1: frictionlab::run_lesson(kept, out); break;
      default: frictionlab::run_check(kept, out); break;
    }
  } catch (const frictionlab::InvalidInput&) {
    // Exit 2 with its message: the answer to bad input.
  }
  return 0;
}
