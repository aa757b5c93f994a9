#include "classroom_state/setup_file.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "classroom_state/class_predictions.h"
#include "classroom_state/user_lessons.h"
#include "files/output_file.h"
#include "lessons/runtime/catalog.h"
#include "physics/validation.h"

namespace frictionlab::classroom_state {
namespace {

namespace fs = std::filesystem;

// A setup is a few dozen lines: anything much larger is not one.
constexpr std::size_t largest_setup = 64 * 1024;

// Spaces, tabs and carriage returns at either end are not part of what a line says (a file
// saved on Windows, then edited elsewhere, can end a line in two of them).
std::string trimmed(const std::string& text) {
  const char* const blank = " \t\r";
  const std::size_t first = text.find_first_not_of(blank);
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(blank) - first + 1);
}

// Where a line of the file is, for messages: "class.setup:4: ".
struct At {
  const std::string& path;
  int line;
  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput(path + ":" + std::to_string(line) + ": " + what);
  }
};

// A line kind that may come once: refused the second time, with where the first was.
void once(int& seen_at, const At& at, const std::string& word, const std::string& why) {
  if (seen_at != 0) at.fail(word + " given twice (lines " + std::to_string(seen_at) + " and " + std::to_string(at.line) + "); " + why);
  seen_at = at.line;
}

double number(const At& at, const std::string& word, const std::string& text, double low, double high, const char* unit) {
  std::string why;
  const std::optional<double> value = validation::parse_decimal(text, why);
  if (!value) at.fail(word + " " + text + ": " + (why.empty() ? "not a number" : why));
  try {
    validation::require_in_range(word, *value, low, high, false, unit);
  } catch (const InvalidInput& error) {
    at.fail(error.what());
  }
  return *value;
}

// Each line's form, for the message when a line has only its word.
std::string example_of(const std::string& word) {
  if (word == "lesson") return "lesson spring_pull";
  if (word == "set") return "set mass = 1.5";
  if (word == "lock") return "lock mu_s, mu_k";
  if (word == "mystery") return "mystery aluminium/wood seed 42";
  if (word == "hz") return "hz 240";
  if (word == "substeps") return "substeps 1";
  if (word == "predictions") return "predictions on";
  if (word == "predict") return "predict breakaway force = 4.5";
  if (word == "theory") return "theory revealed";
  return "friction stick-slip";
}

// The line words a setup has, in the order a saved setup writes them.
const char* const line_words[] = {"lesson", "set", "lock", "mystery", "hz", "substeps", "friction", "predictions", "predict", "theory"};

std::string quoted_list(const std::vector<std::string>& words) {
  std::string list;
  for (const std::string& word : words) list += (list.empty() ? "\"" : ", \"") + word + "\"";
  return list;
}

// The lesson's predict rows, for a message: "\"breakaway force\", \"re-stick force\"".
std::string predictions_listed(const lessons::Lesson& lesson) {
  std::vector<std::string> rows;
  for (const lessons::Prediction& prediction : lesson.predictions()) rows.push_back(prediction.expectation);
  return quoted_list(rows);
}

// Whether a line holds `text` as it is: read back trimmed, a line at a time.
bool fits_a_line(const std::string& text) {
  return !text.empty() && text == trimmed(text) && text.find_first_of("\n\r") == std::string::npos;
}

bool is_setup_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string line;
  return std::getline(file, line) && line.rfind(setup_first_line, 0) == 0;
}

}  // namespace

namespace {

// "set NAME = VALUE": each parameter once.
void read_set_line(PreparedSetup& setup, const At& at, const std::string& rest) {
  const std::size_t equals = rest.find('=');
  const std::string name = trimmed(rest.substr(0, equals));
  const std::string value = equals == std::string::npos ? "" : trimmed(rest.substr(equals + 1));
  if (equals == std::string::npos || name.empty() || value.empty()) at.fail("set " + rest + ": write it as set NAME = VALUE, as in set mass = 1.5");
  for (const PreparedSetup::Value& given : setup.values) {
    if (given.name == name) {
      at.fail("set " + name + " given twice (lines " + std::to_string(given.line) + " and " + std::to_string(at.line) +
              "); give each parameter once");
    }
  }
  setup.values.push_back({name, value, at.line});
}

// "lock NAME, NAME, ...": one line, names between commas.
void read_lock_line(PreparedSetup& setup, const At& at, const std::string& rest) {
  once(setup.lock_line, at, "lock", "list every control on one lock line");
  std::stringstream names(rest);
  std::string name;
  while (std::getline(names, name, ',')) {
    name = trimmed(name);
    if (name.empty()) at.fail("lock " + rest + ": give names separated by commas, as in lock mu_s, mu_k");
    setup.lock.push_back(name);
  }
  if (rest.back() == ',') at.fail("lock " + rest + ": give names separated by commas, as in lock mu_s, mu_k");
}

// "mystery MATERIAL/MATERIAL seed N": one pair.
void read_mystery_line(PreparedSetup& setup, const At& at, const std::string& rest) {
  once(setup.mystery_line, at, "mystery", "a setup has one mystery pair");
  std::istringstream parts(rest);
  std::string pair, seed_word, seed, more;
  parts >> pair >> seed_word >> seed;
  if (pair.find('/') == std::string::npos || seed_word != "seed" || seed.empty() || (parts >> more)) {
    at.fail("mystery " + rest + ": write it as mystery MATERIAL/MATERIAL seed N, as in mystery aluminium/wood seed 42");
  }
  try {
    setup.mystery = MysteryChoice{pair, parse_mystery_seed("seed", seed)};
  } catch (const InvalidInput& error) {
    at.fail(error.what());
  }
}

// "predict ROW = ANSWER": each row once.
void read_predict_line(PreparedSetup& setup, const At& at, const std::string& rest) {
  // At the last '=': a row's name may hold one ("μk = tan θ"); a number or a choice word does not.
  const std::size_t equals = rest.rfind('=');
  const std::string row = trimmed(rest.substr(0, equals));
  const std::string answer = equals == std::string::npos ? "" : trimmed(rest.substr(equals + 1));
  if (equals == std::string::npos || row.empty() || answer.empty()) {
    at.fail("predict " + rest + ": write it as predict ROW = ANSWER, as in predict breakaway force = 4.5");
  }
  for (const PreparedSetup::Answer& given : setup.answers) {
    if (given.row == row) {
      at.fail("predict " + row + " given twice (lines " + std::to_string(given.line) + " and " + std::to_string(at.line) +
              "); give each prediction once");
    }
  }
  setup.answers.push_back({row, answer, at.line});
}

// A line's first word, refused unless it is one a setup has.
std::string line_word(const std::string& line, const At& at) {
  const std::string word = line.substr(0, line.find_first_of(" \t\r"));
  if (std::find_if(std::begin(line_words), std::end(line_words), [&](const char* known) { return word == known; }) ==
      std::end(line_words)) {
    std::string words;
    for (const char* known : line_words) words += (words.empty() ? "" : ", ") + std::string(known);
    at.fail("'" + word + "' is not a line a setup has; its lines: " + words);
  }
  return word;
}

}  // namespace

PreparedSetup parse_setup(const std::string& text, const std::string& path) {
  PreparedSetup setup;
  int hz_line = 0, substeps_line = 0, friction_line = 0, predictions_line = 0, theory_line = 0;
  std::istringstream lines(text);
  std::string raw;
  for (int number_of_line = 1; std::getline(lines, raw); ++number_of_line) {
    if (number_of_line == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0) raw.erase(0, 3);
    const std::string line = trimmed(raw);
    if (line.empty() || line[0] == '#') continue;
    const At at{path, number_of_line};
    const std::string word = line_word(line, at);
    const std::string rest = word.size() == line.size() ? "" : trimmed(line.substr(word.size()));
    if (rest.empty()) at.fail(word + " needs what it sets, as in: " + example_of(word));
    if (word == "lesson") {
      once(setup.lesson_line, at, "lesson", "a setup opens one lesson");
      setup.lesson = rest;
    } else if (word == "set") {
      read_set_line(setup, at, rest);
    } else if (word == "lock") {
      read_lock_line(setup, at, rest);
    } else if (word == "mystery") {
      read_mystery_line(setup, at, rest);
    } else if (word == "hz") {
      once(hz_line, at, "hz", "give the step rate once");
      setup.settings.hz = number(at, "hz", rest, 1.0, 100000.0, " steps per second");
    } else if (word == "predict") {
      read_predict_line(setup, at, rest);
    } else if (word == "predictions") {
      once(predictions_line, at, "predictions", "say once whether the class is asked");
      if (rest != "on" && rest != "off") {
        at.fail("predictions " + rest + ": write predictions on (the class predicts before the theory shows) or predictions off");
      }
      setup.ask_predictions = rest == "on";
    } else if (word == "theory") {
      once(theory_line, at, "theory", "say once whether the theory is shown");
      if (rest != "revealed" && rest != "hidden") {
        at.fail("theory " + rest + ": write theory revealed (the class's predictions are set beside it) or theory hidden");
      }
      setup.revealed = rest == "revealed";
    } else if (word == "substeps") {
      once(substeps_line, at, "substeps", "give the sub-steps once");
      const double substeps = number(at, "substeps", rest, 1.0, 1000.0, "");
      if (substeps != static_cast<int>(substeps)) at.fail("substeps " + rest + ": a whole number from 1 to 1000");
      setup.settings.substeps = static_cast<int>(substeps);
    } else {
      once(friction_line, at, "friction", "give the treatment once");
      try {
        setup.settings.treatment = parse_treatment(rest);
      } catch (const InvalidInput& error) {
        at.fail("friction " + rest + ": " + error.what());
      }
    }
  }
  if (setup.lesson.empty()) throw InvalidInput(path + ": no lesson line; a setup names the lesson it opens, as in: lesson spring_pull");
  return setup;
}

namespace {

// encodeURIComponent's unreserved characters stay as they are; every other byte of the UTF-8
// text is %XX.
std::string encoded_for_link(const std::string& text) {
  static const char hex[] = "0123456789ABCDEF";
  std::string encoded;
  for (const char character : text) {
    const auto byte = static_cast<unsigned char>(character);
    const bool unreserved = (byte >= 'A' && byte <= 'Z') || (byte >= 'a' && byte <= 'z') || (byte >= '0' && byte <= '9') ||
                            (byte != 0 && std::strchr("-_.!~*'()", byte) != nullptr);
    if (unreserved) {
      encoded += character;
    } else {
      encoded += '%';
      encoded += hex[byte >> 4];
      encoded += hex[byte & 15];
    }
  }
  return encoded;
}

// The text of the fragment's part `key`=... (after '#', or the whole text when it is a fragment
// alone), among parts joined by '&' in any order, as the page reads them: "#lesson=push&setup=...",
// "#projector=1&setup=...". At most `largest` bytes once decoded; `what` names it in messages.
std::optional<std::string> link_part(const std::string& link, const std::string& key, std::size_t largest,
                                     const std::string& what) {
  const std::string named = key + "=";
  const std::size_t hash = link.find('#');
  const std::size_t fragment = hash == std::string::npos ? 0 : hash + 1;
  std::size_t start = std::string::npos;
  for (std::size_t part = fragment;;) {
    if (link.compare(part, named.size(), named) == 0) {
      start = part + named.size();
      break;
    }
    const std::size_t next = link.find('&', part);
    if (next == std::string::npos) break;
    part = next + 1;
  }
  if (start == std::string::npos) return std::nullopt;
  const std::size_t end = link.find('&', start);
  const std::string encoded = link.substr(start, end == std::string::npos ? std::string::npos : end - start);
  const auto digit = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
  };
  std::string text;
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    if (encoded[i] == '+') {
      text += ' ';  // a form's space, as some mail programs write it
    } else if (encoded[i] != '%') {
      text += encoded[i];
    } else {
      const int high = i + 2 < encoded.size() ? digit(encoded[i + 1]) : -1;
      const int low = i + 2 < encoded.size() ? digit(encoded[i + 2]) : -1;
      if (high < 0 || low < 0) {
        throw InvalidInput(what + ": '" + encoded.substr(i, 3) + "' at character " + std::to_string(start + i + 1) +
                           " is not a %-escape (% and two hexadecimal digits); was the link cut or changed?");
      }
      text += static_cast<char>(high * 16 + low);
      i += 2;
    }
    if (text.size() > largest) {
      throw InvalidInput(what + ": holds more than " + std::to_string(largest / 1024) + " KB, the most a link carries");
    }
  }
  return text;
}

// A setup's lesson line names a script file ("my_slope.lua", "lessons/push.lua"), not a
// built-in lesson by its name ("push").
bool names_a_script_file(const std::string& lesson) {
  return lesson.find('/') != std::string::npos || fs::path(lesson).extension() == ".lua";
}

// A setup file's text, refused with a clear message where it is not one: missing, a folder, a
// FIFO or device (which would be waited on, or read for ever), or more than a setup holds.
std::string setup_file_text(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) throw InvalidInput("setup " + path + ": no such file");
  if (S_ISDIR(status.st_mode)) throw InvalidInput("setup " + path + ": that is a folder, not a setup file");
  if (!S_ISREG(status.st_mode)) throw InvalidInput("setup " + path + ": that is not a regular file");
  if (static_cast<std::size_t>(status.st_size) > largest_setup) {
    throw InvalidInput("setup " + path + ": " + std::to_string(status.st_size) + " bytes is too large for a setup file (at most 64 KB)");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InvalidInput("setup " + path + ": cannot be read");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// A setup's text with its line `number` (its lesson line) made "lesson LESSON".
std::string with_lesson_line(const std::string& text, int number, const std::string& lesson) {
  std::istringstream lines(text);
  std::string line, rewritten;
  for (int at = 1; std::getline(lines, line); ++at) rewritten += (at == number ? "lesson " + lesson : line) + '\n';
  return rewritten;
}

}  // namespace

std::string setup_link(const std::string& text, const std::string& page, const std::string& script) {
  std::string link = page + "#setup=" + encoded_for_link(text);
  if (!script.empty()) link += "&script=" + encoded_for_link(script);
  return link;
}

std::size_t linked_script_length(const std::string& script) { return encoded_for_link(script).size(); }

std::optional<std::string> setup_text_from_link(const std::string& link) {
  return link_part(link, "setup", largest_setup, "setup link");
}

std::optional<std::string> script_text_from_link(const std::string& link) {
  return link_part(link, "script", largest_linked_script, "setup link's lesson");
}

std::string setup_file_link(const std::string& path, const std::string& page, std::string* left_out) {
  // Read once: the link carries the very text that was checked.
  std::string text = setup_file_text(path);
  const PreparedSetup setup = parse_setup(text, path);
  // A setup naming a script file (a lesson of one's own, not a built-in one by name) carries it,
  // as the page's Copy link does: the page that opens the link has only its built-in lessons.
  std::string script;
  if (names_a_script_file(setup.lesson)) {
    const std::string lesson_path = setup_lesson_path(setup, path);
    std::error_code error;
    const std::uintmax_t size = fs::file_size(lesson_path, error);
    if (error) throw InvalidInput(path + ":" + std::to_string(setup.lesson_line) + ": cannot read " + lesson_path + ": " + error.message());
    // Each byte takes at least one character in a link: a longer file is not read.
    if (size <= largest_linked_script) {
      std::ifstream lesson(lesson_path, std::ios::binary);
      std::ostringstream lesson_text;
      lesson_text << lesson.rdbuf();
      if (!lesson) throw InvalidInput(path + ":" + std::to_string(setup.lesson_line) + ": cannot read " + lesson_path);
      script = lesson_text.str();
    }
    if (size > largest_linked_script || linked_script_length(script) > largest_linked_script) {
      if (left_out != nullptr) *left_out = lesson_path;
      script.clear();
    } else {
      // The lesson line names the file alone: a teacher's folders are no part of the link (the
      // page keeps the lesson under that name).
      text = with_lesson_line(text, setup.lesson_line, fs::path(lesson_path).filename().string());
    }
  }
  return setup_link(text, page, script);
}

std::optional<std::string> received_setup_text(const std::string& link, std::string* kept) {
  std::optional<std::string> text = setup_text_from_link(link);
  if (!text) return std::nullopt;
  const std::optional<std::string> script = script_text_from_link(link);
  if (!script) return text;
  // The setup names the lesson as it was where the link was made (the page's folders, or a
  // teacher's): kept here under that file's name, the lesson line pointed at it.
  const PreparedSetup setup = parse_setup(*text, "setup link");
  const std::string path = keep_user_lesson(fs::path(setup.lesson).filename().string(), *script);
  if (kept != nullptr) *kept = path;
  return with_lesson_line(*text, setup.lesson_line, path);
}

PreparedSetup read_setup(const std::string& path) {
  if (const std::optional<std::string> text = setup_text_from_link(path)) return parse_setup(*text, "setup link");
  return parse_setup(setup_file_text(path), path);
}

std::string setup_text(const PreparedSetup& setup) {
  std::ostringstream text;
  text << setup_first_line << "\n# Open it with: frictionlab --setup FILE, or the window's Lesson menu (Open a setup).\n";
  text << "lesson " << setup.lesson << '\n';
  for (const PreparedSetup::Value& value : setup.values) text << "set " << value.name << " = " << value.text << '\n';
  if (!setup.lock.empty()) {
    text << "lock ";
    for (std::size_t i = 0; i < setup.lock.size(); ++i) text << (i > 0 ? ", " : "") << setup.lock[i];
    text << '\n';
  }
  if (setup.mystery) text << "mystery " << setup.mystery->pair << " seed " << setup.mystery->seed << '\n';
  text << "hz " << validation::exact_text(setup.settings.hz) << '\n';
  text << "substeps " << setup.settings.substeps << '\n';
  text << "friction " << treatment_name(setup.settings.treatment) << '\n';
  if (setup.ask_predictions) text << "predictions " << (*setup.ask_predictions ? "on" : "off") << '\n';
  for (const PreparedSetup::Answer& answer : setup.answers) text << "predict " << answer.row << " = " << answer.text << '\n';
  if (setup.revealed) text << "theory revealed\n";
  return text.str();
}

void write_setup(const std::string& path, const PreparedSetup& setup) {
  if (path.empty()) throw InvalidInput("give the setup a file name, such as class.setup");
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".lua") throw InvalidInput(path + ": that looks like a lesson script; give the setup a name of its own, such as class.setup");
  for (const PreparedSetup::Answer& answer : setup.answers) {
    if (!fits_a_line(answer.row)) {
      throw InvalidInput(path + ": the prediction \"" + answer.row + "\" cannot be written on a line of a setup (a blank at either end, "
                         "or a line break); give its expect row another name in the lesson");
    }
    if (!fits_a_line(answer.text) || answer.text.find('=') != std::string::npos) {
      throw InvalidInput(path + ": the class's answer \"" + answer.text + "\" to \"" + answer.row + "\" cannot be written on a line of a setup "
                         "(an '=', a blank at either end, or a line break); give the choice another word in the lesson");
    }
  }
  const std::string text = setup_text(setup);
  try {
    files::OutputFile file(path, is_setup_file);
    file.write(text);
    file.commit();
  } catch (const std::runtime_error& error) {
    throw InvalidInput(error.what());
  }
}

std::string setup_lesson_path(const PreparedSetup& setup, const std::string& setup_path) {
  const bool a_name = !names_a_script_file(setup.lesson);
  const fs::path script(setup.lesson);
  try {
    if (a_name) return lessons::resolve_lesson(setup.lesson);
    // Without "folder/../": the window, its Lesson menu and the page's editor know a script by
    // its plain path (the page's links sit in /link, its student's lessons in the home folder).
    const fs::path from_setup = script.is_absolute() ? script : fs::path(setup_path).parent_path() / script;
    return lessons::resolve_lesson(from_setup.lexically_normal().string());
  } catch (const InvalidInput& error) {
    At{setup_path, setup.lesson_line}.fail(error.what());
  }
}

std::string setup_lesson_name(const std::string& script_path, const std::string& setup_path) {
  std::error_code error;
  const fs::path script = fs::weakly_canonical(script_path, error);
  const fs::path builtins = fs::weakly_canonical(lessons::lessons_directory(), error);
  const std::string name = script.stem().string();
  if (script.parent_path() == builtins && lessons::is_builtin_lesson(name)) return name;
  const fs::path folder = fs::weakly_canonical(fs::absolute(setup_path).parent_path(), error);
  const fs::path relative = script.lexically_relative(folder);
  return relative.empty() ? script.string() : relative.string();
}

void check_setup(const PreparedSetup& setup, const std::string& setup_path, lessons::Lesson& lesson) {
  std::pair<std::string, std::string> mystery_names;
  if (setup.mystery) {
    // Found in the lesson at its script's values: a value set below may not be one of them.
    try {
      mystery_names = mystery_parameters(lesson, setup.mystery->pair, "mystery");
    } catch (const InvalidInput&) {
      // Said below, once the values (which may change the materials) are set.
    }
  }
  for (const PreparedSetup::Value& value : setup.values) {
    const At at{setup_path, value.line};
    if (value.name == mystery_names.first || value.name == mystery_names.second) {
      at.fail("set " + value.name + ": " + value.name + " is the mystery's (line " + std::to_string(setup.mystery_line) +
              "); leave it out");
    }
    try {
      lesson.set(value.name, value.text);
    } catch (const InvalidInput& error) {
      at.fail(error.what());
    }
  }
  for (const std::string& name : setup.lock) {
    bool known = std::find(std::begin(lockable_settings), std::end(lockable_settings), name) != std::end(lockable_settings);
    std::string controls;
    for (const lessons::Parameter& parameter : lesson.parameters()) {
      known = known || parameter.name == name;
      controls += parameter.name + ", ";
    }
    if (!known) {
      At{setup_path, setup.lock_line}.fail("lock " + name + ": " + lesson.path() + " has no control of that name; its controls: " +
                                           controls + "hz, substeps, friction");
    }
  }
  if (setup.mystery) {
    try {
      mystery_parameters(lesson, setup.mystery->pair, "mystery");
    } catch (const InvalidInput& error) {
      At{setup_path, setup.mystery_line}.fail(error.what());
    }
  }
  for (const PreparedSetup::Answer& answer : setup.answers) {
    const std::string problem = prediction_problem(lesson, answer.row, answer.text);
    if (!problem.empty()) At{setup_path, answer.line}.fail("predict " + answer.row + " = " + answer.text + ": " + problem);
  }
}

std::string prediction_problem(const lessons::Lesson& lesson, const std::string& row, const std::string& answer) {
  const std::vector<lessons::Prediction>& predictions = lesson.predictions();
  const auto asked = std::find_if(predictions.begin(), predictions.end(),
                                  [&](const lessons::Prediction& prediction) { return prediction.expectation == row; });
  if (asked == predictions.end()) {
    if (predictions.empty()) return lesson.path() + " asks the class for no predictions";
    return lesson.path() + " asks for no prediction of that name; its predictions: " + predictions_listed(lesson);
  }
  if (asked->is_choice()) {
    if (std::find(asked->choices.begin(), asked->choices.end(), answer) != asked->choices.end()) return "";
    return "not one of its choices: " + quoted_list(asked->choices);
  }
  std::string why;
  if (!read_answer(answer, why)) return why;
  return "";
}

}  // namespace frictionlab::classroom_state
