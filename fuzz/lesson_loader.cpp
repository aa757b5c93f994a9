// Fuzz target: a lesson script from bytes. It is written to a file of this process's own (the
// loader reads files), built, stepped for a tenth of a second and its expectations read. A
// script's mistakes end in InvalidInput (ScriptError among them), which is the expected answer;
// anything else (a crash, a sanitizer report, a hang past libFuzzer's -timeout) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "lessons/runtime/lesson.h"

namespace {

const std::string& script_path() {
  static const std::string path = "/tmp/frictionlab_fuzz_lesson_" + std::to_string(::getpid()) + ".lua";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream file(script_path(), std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    frictionlab::lessons::Lesson lesson(script_path());
    lesson.step_to(0.1);
    (void)lesson.expectations();
  } catch (const frictionlab::InvalidInput&) {
    // A mistake reported as one: what the loader is for.
  }
  return 0;
}
