// A prepared setup: what a teacher sets up before class (the lesson, its values, the lock of
// controls, a mystery pair and its seed, the step settings, and the class's predictions), as a
// small text file to open in class with `frictionlab --setup FILE` or the Lesson menu. A
// mystery is saved as its pair and seed, never its values.
//
// The file, one instruction a line (a word, then what it takes); `#` starts a comment:
//
//   # FrictionLab setup
//   lesson spring_pull
//   set mass = 1.5
//   lock mu_s, mu_k
//   mystery aluminium/wood seed 42
//   hz 240
//   substeps 1
//   friction stick-slip
//   predictions on
//   predict breakaway force = 4.5
//   predict sticks or slides = slides
//   theory revealed
//
// `lesson` is a built-in lesson's name or a script's path (from the setup file's folder, or
// from /); every other line may be left out. Each line's first word says what it is, so a
// later kind of line is a new word, and a file without it still reads. `predictions on|off`
// is whether the class is asked to predict (the View menu's choice; left as the window has it
// when the line is missing); each `predict ROW = ANSWER` is the class's answer to the lesson's
// predict row of that name, split at the line's last '=' (a row's name may hold one; a number
// or a choice word holds none); `theory revealed` says the teacher has shown the theory.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "classroom_state/mystery.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom_state {

// The names --lock takes besides a lesson's parameters.
inline const char* const lockable_settings[] = {"hz", "substeps", "friction"};

// The first line a setup file begins with: only a file that does is ever replaced by a save.
inline constexpr const char* setup_first_line = "# FrictionLab setup";

struct PreparedSetup {
  std::string lesson;  // a built-in name or a script's path, as written
  struct Value {
    std::string name, text;
    int line = 0;  // where the file gave it (0: not read from a file)
  };
  std::vector<Value> values;
  std::vector<std::string> lock;
  std::optional<MysteryChoice> mystery;
  StepSettings settings;
  // The class's predictions: each answer by its predict row, as typed or picked, in order.
  struct Answer {
    std::string row, text;
    int line = 0;  // where the file gave it (0: not read from a file)
  };
  std::vector<Answer> answers;
  bool revealed = false;                  // the theory has been shown
  std::optional<bool> ask_predictions;    // predictions on/off; none: the window's own choice
  // Where the file gave each line, for messages that point at it: lesson, lock, mystery, hz, substeps, friction.
  int lesson_line = 0, lock_line = 0, mystery_line = 0;
};

// Reads a setup from its text; `path` names it in messages. Throws InvalidInput as
// "path:line: what is wrong" for a line it cannot read, and "path: ..." when it has no lesson.
PreparedSetup parse_setup(const std::string& text, const std::string& path);
// The same from the file at `path` (or from a link that holds one: setup_text_from_link; a
// lesson the link carries is not kept, which setup_options does);
// refuses what is not a readable regular file of a setup's size.
PreparedSetup read_setup(const std::string& path);

// A setup as a link to the web page (web/): PAGE#setup=TEXT, the setup file's text encoded as
// JavaScript's encodeURIComponent does, so a teacher can send a prepared setup as an address.
// With a `script`, the link carries the lesson too (&script=TEXT, as the page's Copy link adds
// for a student's own lesson, which lives on one computer only): see received_setup_text.
std::string setup_link(const std::string& text, const std::string& page, const std::string& script = "");
// The most a link's &script= part may hold, as encoded (the page's own limit: links far longer
// are cut by mail programs and refused by some browsers).
constexpr std::size_t largest_linked_script = 200 * 1024;
// How long `script` is as a link's &script= part.
std::size_t linked_script_length(const std::string& script);
// The link for the setup file at `path` (read_setup's checks first): carrying the lesson the
// setup names when that is a script file rather than a built-in lesson's name, as long as it
// fits (largest_linked_script); a script left out for its length is named in *left_out.
std::string setup_file_link(const std::string& path, const std::string& page, std::string* left_out = nullptr);
// The setup text a link holds in its fragment's "setup=" part, wherever that stands among the
// fragment's '&'-joined parts ("#setup=...", "#lesson=push&setup=...", or a fragment alone);
// nullopt when the text is not such a link. Throws InvalidInput naming the link for a broken
// %-escape or a text longer than a setup file may be.
std::optional<std::string> setup_text_from_link(const std::string& link);
// The lesson a link carries in its "script=" part; nullopt when it carries none.
std::optional<std::string> script_text_from_link(const std::string& link);
// A link's setup as the page receives it: a lesson the link carries is kept among the user's
// own lessons (keep_user_lesson: beside a different lesson of that name, never over it), and
// the setup's lesson line names where it was kept (in *kept too, when given). nullopt when
// `link` is not a setup link; the setup's text alone when it carries no lesson.
std::optional<std::string> received_setup_text(const std::string& link, std::string* kept = nullptr);

// The setup as the file holds it (setup_text then parse_setup gives it back).
std::string setup_text(const PreparedSetup& setup);
// Writes it whole (a temporary file beside it, renamed over it) to `path`. Refuses a .lua path,
// anything there but a setup file FrictionLab wrote, and a prediction whose row or answer a
// line cannot hold as it is (a line break, a blank at either end, an '=' in the answer).
// Throws InvalidInput naming the path.
void write_setup(const std::string& path, const PreparedSetup& setup);

// The script a setup's lesson names: a built-in name, or a path from the setup's own folder.
std::string setup_lesson_path(const PreparedSetup& setup, const std::string& setup_path);
// The setup's lesson name as a setup file writes it: a built-in lesson's name, else the
// script's path from the folder the setup is saved in.
std::string setup_lesson_name(const std::string& script_path, const std::string& setup_path);

// Checks the setup against its lesson built at the script's values: every value set (in order),
// then the lock's names, the mystery's pair and the predictions (each a predict row of the
// lesson set at those values). Throws InvalidInput "path:line: ..." at the line that is wrong.
void check_setup(const PreparedSetup& setup, const std::string& setup_path, lessons::Lesson& lesson);

// What is wrong with `answer` as the class's answer to the lesson's predict row `row`: "" when
// it is one of the row's choices or a number as the window takes it (classroom_state/class_predictions.h), else
// why not, naming the lesson's predictions or the row's choices.
std::string prediction_problem(const lessons::Lesson& lesson, const std::string& row, const std::string& answer);

}  // namespace frictionlab::classroom_state
