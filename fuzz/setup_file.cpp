// Fuzz target: a prepared setup file from bytes (classroom_state/setup_file.h). Besides not crashing, every
// refusal is InvalidInput with a message, and what is read (the class's predictions too) is
// written back by setup_text to a text that reads as the same setup.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "classroom_state/setup_file.h"

namespace {

bool same(const frictionlab::classroom_state::PreparedSetup& a, const frictionlab::classroom_state::PreparedSetup& b) {
  if (a.lesson != b.lesson || a.lock != b.lock || a.mystery != b.mystery || a.values.size() != b.values.size()) return false;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    if (a.values[i].name != b.values[i].name || a.values[i].text != b.values[i].text) return false;
  }
  if (a.answers.size() != b.answers.size() || a.revealed != b.revealed || a.ask_predictions != b.ask_predictions) return false;
  for (std::size_t i = 0; i < a.answers.size(); ++i) {
    if (a.answers[i].row != b.answers[i].row || a.answers[i].text != b.answers[i].text) return false;
  }
  return a.settings.hz == b.settings.hz && a.settings.substeps == b.settings.substeps &&
         a.settings.treatment == b.settings.treatment;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  frictionlab::classroom_state::PreparedSetup setup;
  try {
    setup = frictionlab::classroom_state::parse_setup(text, "fuzz.setup");
  } catch (const frictionlab::InvalidInput& error) {
    if (std::string(error.what()).rfind("fuzz.setup", 0) != 0) std::abort();  // every message names the file
    return 0;
  }
  try {
    if (!same(setup, frictionlab::classroom_state::parse_setup(frictionlab::classroom_state::setup_text(setup), "again.setup"))) std::abort();
  } catch (const frictionlab::InvalidInput&) {
    std::abort();  // what was read must be written so that it reads again
  }
  return 0;
}
