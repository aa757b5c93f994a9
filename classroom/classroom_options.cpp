#include "classroom/classroom_options.h"

#include <filesystem>

#include "classroom_state/setup_file.h"
#include "physics/validation.h"

namespace frictionlab::classroom {

namespace fs = std::filesystem;

ClassroomOptions setup_options(const std::string& setup_path, ClassroomOptions base) {
  // A link that carries its lesson: kept among the user's lessons, and the window says where.
  std::string kept;
  const std::optional<std::string> received = classroom_state::received_setup_text(setup_path, &kept);
  const classroom_state::PreparedSetup setup = received ? classroom_state::parse_setup(*received, "setup link") : classroom_state::read_setup(setup_path);
  const std::string lesson_path = classroom_state::setup_lesson_path(setup, setup_path);
  try {
    lessons::Lesson lesson(lesson_path, {}, setup.settings);
    classroom_state::check_setup(setup, setup_path, lesson);
  } catch (const lessons::ScriptError& error) {
    // The lesson line names a script that does not build: the script's own place, after the setup's.
    throw InvalidInput(setup_path + ":" + std::to_string(setup.lesson_line) + ": " + error.what());
  }
  base.lesson = lesson_path;
  base.opening_notice = kept.empty() ? "" : "The link brought its lesson: it is yours now as " + fs::path(kept).filename().string() +
                                                " (Lesson > Your lessons).";
  base.overrides.clear();
  for (const classroom_state::PreparedSetup::Value& value : setup.values) base.overrides[value.name] = value.text;
  base.lock = setup.lock;
  base.lock_from = setup.lock.empty() ? "" : setup_path;
  base.mystery = setup.mystery;
  base.settings = setup.settings;
  base.predictions = classroom_state::ClassPredictions{};
  for (const classroom_state::PreparedSetup::Answer& answer : setup.answers) base.predictions.answers[answer.row] = answer.text;
  base.predictions.revealed = setup.revealed;
  if (setup.ask_predictions) base.window.predictions = *setup.ask_predictions;
  return base;
}

}  // namespace frictionlab::classroom
