// The options table, the reading of a command's arguments through it, and the help and manual
// page written from it.
#include "app/command_line.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "app/options.h"
#include "classroom_state/mystery.h"
#include "classroom_state/plain_words.h"
#include "classroom_state/window_keys.h"
#include "physics/materials.h"

namespace frictionlab {
namespace {

// The commands as the tables below name them: "for_run | for_check" (not "link", which would
// hide POSIX's link(), nor "run" and "check", which read as verbs).
constexpr Command for_window = Command::window, for_list = Command::list, for_run = Command::run,
                  for_check = Command::check, for_render = Command::render, for_link = Command::link,
                  for_bench = Command::bench;

// The one list of options. Where two commands read one name differently (--at is one time for
// the window, several for render; --seed is a mystery's seed or --random's), each reading has
// its row. The order is the help's: the lessons' values and step settings first, which most
// commands share (each command's unknown-option message has its own order, below). In the help
// and the manual's paragraphs, `backquotes` mark words typed as they stand (stick-slip, a
// setup's lines): bold in the manual page, the quotes left out in the help.
const Option table[] = {
    {.name = "--lock", .commands = for_window, .value = "NAME[,NAME...]", .kind = ValueKind::text,
     .help = "shows only the named controls (parameters, or `friction`, `hz`, `substeps`) and keeps the class on this lesson",
     .example = "mu_s,mu_k", .held_by_setup = true},
    {.name = "--set", .commands = for_window | for_run | for_check | for_render | for_bench, .value = "NAME=VALUE", .kind = ValueKind::text,
     .help = "sets a lesson parameter, as in `--set mu_s=0.5`; may be given several times; a value out of the "
             "parameter's range is refused with the range",
     .example = "mu_s=0.5", .repeatable = true, .held_by_setup = true},
    {.name = "--hz", .commands = for_window | for_run | for_check | for_render, .value = "N", .kind = ValueKind::number,
     .range = {1.0, 100000.0, false, " steps per second"}, .help = "steps per simulated second, {range} (default 240)",
     .example = "480", .held_by_setup = true},
    {.name = "--substeps", .commands = for_window | for_run | for_check | for_render, .value = "N", .kind = ValueKind::whole_number,
     .range = {1.0, 1000.0, false, ""}, .help = "physics steps inside each step, a whole number {range} (default 1)",
     .example = "2", .held_by_setup = true},
    {.name = "--friction", .commands = for_window | for_run | for_check | for_render, .value = "T", .kind = ValueKind::text,
     .help = "the friction treatment: `stick-slip` (the default, converges to Coulomb), `threshold`, `regularized` or "
             "`box2d`",
     .manual = "the friction treatment: `stick-slip` (converges to Coulomb), `threshold` (the games' speed switch), "
               "`regularized` (smooth, creeps) or `box2d` (Box2D's own single coefficient); `stick-slip` when not "
               "given",
     .example = "threshold", .held_by_setup = true},
    {.name = "--theme", .commands = for_window | for_render, .value = "light|dark", .kind = ValueKind::text,
     .help = "the colour theme", .example = "dark"},
    {.name = "--projector", .commands = for_window, .kind = ValueKind::none,
     .help = "fills the screen with larger text and thicker lines, for the back of a classroom"},
    {.name = "--at", .commands = for_window, .value = "S", .kind = ValueKind::number, .range = {0.0, 3600.0, false, " s"},
     .help = "with --screenshot: the time in seconds, {range}, at which the window is saved", .example = "0.5"},
    {.name = "--screenshot", .commands = for_window, .value = "FILE.png", .kind = ValueKind::text,
     .help = "saves the window as a PNG file at the time --at gives, then closes it", .example = "window.png"},
    {.name = "--reveal", .commands = for_window, .kind = ValueKind::none,
     .help = "with --screenshot: the theory revealed, as T reveals it after the class's predictions, before the picture"},
    {.name = "--duration", .commands = for_run, .value = "S", .kind = ValueKind::number, .range = {0.0, 86400.0, true, " s"},
     .help = "how long to run, in seconds, {range} (the lesson's own duration when not given)", .example = "1.5"},
    {.name = "--csv", .commands = for_run, .value = "FILE", .kind = ValueKind::text,
     .help = "also writes the run's history, one row per step, to FILE (`-` for the standard output)",
     .manual = "also writes the run's history, one row per step, to FILE (a `.csv` file, or `-` for the standard output; "
               "a `.lua` file is refused so that no script is overwritten)",
     .example = "run.csv"},
    {.name = "--at", .commands = for_render, .value = "S[,S...]", .kind = ValueKind::numbers, .range = {0.0, 3600.0, false, " s"},
     .help = "the times to draw, in seconds, each {range}, at most 100 of them; without --at or --moment, halfway "
             "through the run (as the window draws without a display)",
     .example = "0.5,2",
     .twice_hint = " (several times go in one --at, as in --at 1,2)"},
    {.name = "--moment", .commands = for_render, .value = "NAME", .kind = ValueKind::text,
     .help = "instead of --at: one of the lesson's teaching moments (see list), with its time, values and theme",
     .example = "above_critical_angle"},
    {.name = "--size", .commands = for_render, .value = "WxH", .kind = ValueKind::size, .range = {320.0, 7680.0, false, " pixels"},
     .height_range = {240.0, 4320.0, false, " pixels"},
     .help = "the picture's size in pixels, {range}, landscape from 4:3 to 2.4:1 (default 1280x720)", .example = "1920x1080"},
    {.name = "--out", .commands = for_render, .value = "PATH", .kind = ValueKind::text,
     .help = "a `.png` file for one picture, or a folder for several (LESSON`_t`S`.png`, or LESSON`_`MOMENT`.png`)",
     .manual = "a `.png` file for one picture, or a folder (made if missing, inside one that exists) for several: each "
               "file there is named LESSON`_t`TIME`.png`, or LESSON`_`MOMENT`.png` with --moment",
     .example = "picture.png"},
    {.name = "--random", .commands = for_check, .value = "N", .kind = ValueKind::whole_number, .range = {1.0, 100000.0, false, ""},
     .help = "checks each lesson at N settings, {range}, drawn inside its sliders' ranges, ends included, and prints "
             "each failing one as the command line that reproduces it",
     .manual = "checks each lesson at N settings (a whole number {range}) drawn inside its own sliders' ranges: the "
               "first with every slider at its minimum, the second at its maximum, then each slider at one end or the "
               "other two times in five and anywhere between (to four significant figures) otherwise; a value given "
               "with --set is kept in every setting. Each setting that misses an expectation is printed as the command "
               "line that reproduces it (`frictionlab check` LESSON --set NAME=VALUE ...), with the rows it missed; the "
               "exit status is 1 if any does",
     .example = "3"},
    {.name = "--seed", .commands = for_check, .value = "S", .kind = ValueKind::whole_number,
     .range = {0.0, static_cast<double>(classroom_state::mystery_seed_max), false, ""},
     .help = "with --random: the seed of the draws, a whole number {range} (default {default}); the same seed draws "
             "the same settings on every machine",
     .default_value = static_cast<double>(default_random_seed),
     .example = "4"},
    {.name = "--mystery", .commands = for_window | for_run | for_render, .value = "MATERIAL/MATERIAL", .kind = ValueKind::text,
     .help = "hides a friction pair's mu_s and mu_k, drawn from the seed, until the teacher reveals them",
     .manual = "makes a friction pair of the lesson (one whose μs and μk are sliders, named either way round) a "
               "mystery: both drawn from the seed, μs from 0.20 to 0.90 and μk from 50 % to 90 % of μs, in "
               "hundredths, and hidden (sliders, values, the theory's predictions and curves, CSV, title) until the "
               "teacher reveals them; needs --seed",
     .example = "aluminium/wood", .held_by_setup = true},
    {.name = "--seed", .commands = for_window | for_run | for_render, .value = "N", .kind = ValueKind::whole_number,
     .range = {0.0, static_cast<double>(classroom_state::mystery_seed_max), false, ""},
     .help = "the mystery's seed, a whole number {range}: the same seed draws the same values on every machine",
     .example = "42",
     .beside = Beside::together, .held_by_setup = true},
    {.name = "--setup", .commands = for_window, .value = "FILE", .kind = ValueKind::text,
     .help = "the window on a prepared setup (Lesson > Save as a setup), which holds the lesson, its values, the lock, "
             "the mystery and the step settings: not with a lesson or the options for those",
     .manual = "opens a prepared setup, saved from the window's Lesson menu (Save as a setup): a small text file with "
               "the lesson (`lesson` NAME, or a script's path from the file's folder), its values (`set` NAME = "
               "VALUE), the lock (`lock` NAME, ...), a mystery (`mystery` MATERIAL/MATERIAL `seed` N), the step "
               "settings (`hz`, `substeps`, `friction`) and the class's predictions (`predictions on`|`off`, "
               "`predict` ROW = ANSWER, `theory revealed`), one a line. A line it cannot use is named as FILE:LINE and nothing opens. Not with a "
               "lesson, {held}, which the file holds; a link to the web page (see link) opens as its setup does",
     .example = "class.setup"},
    {.name = "--tsv", .commands = for_list, .kind = ValueKind::none,
     .help = "for scripts: one lesson a line, its name, title, README moment and moments, tab-separated"},
    {.name = "--page", .commands = for_link, .value = "ADDRESS", .kind = ValueKind::text,
     .help = "the web page's address, for a whole link (without it, the part to put after the address)",
     .example = "https://school.example/frictionlab/"},
    {.name = "--quick", .commands = for_bench, .kind = ValueKind::none,
     .help = "fewer sizes and repeats: a rough run in seconds instead of minutes"},
    {.name = "--out", .commands = for_bench, .value = "DIR", .kind = ValueKind::text,
     .help = "the folder for the CSV files and charts (required without --recommend)", .example = "figures"},
    {.name = "--recommend", .commands = for_bench, .value = "LESSON", .kind = ValueKind::text,
     .help = "prints the cheapest step setting whose run of the lesson meets its table within --tol times the rows' "
             "tolerances at 240 Hz, measured now; exit 1 if none does",
     .example = "incline"},
    {.name = "--tol", .commands = for_bench, .value = "X", .kind = ValueKind::number,
     .range = {0.0, 1e6, true, " × the lesson's tolerances"},
     .help = "with --recommend: the factor on the tolerances, {range} (1: the table passes; 0.1: ten times tighter)",
     .example = "1"},
};

// How each command that reads its options through read_options() words its refusals. They
// differ as they always have: the window's messages name no command (the window is what a
// command line without one opens) and end with the commands, for a mistyped one.
struct Refusals {
  Command command;
  const char* prefix;         // before every message: "run: "
  const char* options_are;    // "options", before the list of those it takes
  const char* after_list;     // after it
  const char* give_it_once;   // after "given twice"
};
const Refusals refusals[] = {
    {for_window, "", "the window's options", " (commands: list, run, check, render, demo, bench, link, help, --version)", ""},
    {for_run, "run: ", "options", "", "; give it once"},
    {for_check, "check: ", "options", "", "; give it once"},
    {for_render, "render: ", "options", "", "; give it once"},
    {for_list, "list: ", "options", "", "; give it once"},
    {for_link, "link: ", "options", "", "; give it once"},
    {for_bench, "bench: ", "options", "", "; give it once"},
};

// The order each command lists its options in when it refuses one it does not take: as each
// listed them before the table (scripts and tests/CMakeLists.txt know these messages), which no
// one order of the table gives (run lists --hz before --set, check --set before --hz). An option
// a command takes that its list leaves out goes at the end, in the table's order.
struct Listing {
  Command command;
  std::string_view names;  // separated by spaces
};
const Listing listings[] = {
    {for_window, "--lock --set --hz --substeps --friction --theme --projector --at --screenshot --reveal --mystery --seed --setup"},
    {for_run, "--duration --hz --substeps --friction --set --csv --mystery --seed"},
    {for_check, "--set --hz --substeps --friction --random --seed"},
    {for_render, "--at --moment --size --theme --set --out --hz --substeps --friction --mystery --seed"},
    {for_list, "--tsv"},
    {for_link, "--page"},
    {for_bench, "--quick --out --recommend --tol --set"},
};

const Refusals& refusals_of(Command command) {
  for (const Refusals& words : refusals) {
    if (words.command == command) return words;
  }
  throw std::logic_error("frictionlab: " + std::string(command_name(command)) + " does not read its options from the table");
}

// 100000, 0.5, 1000000: as a person writes them.
std::string number_words(double value) {
  char text[32];
  if (value == std::floor(value) && std::fabs(value) < 1e15) {
    std::snprintf(text, sizeof text, "%.0f", value);
  } else {
    std::snprintf(text, sizeof text, "%g", value);
  }
  return text;
}

std::string range_of(const Range& range) {
  return range.low_open ? "above " + number_words(range.low) + ", at most " + number_words(range.high)
                        : "from " + number_words(range.low) + " to " + number_words(range.high);
}

// "--hz N", "--projector".
std::string written(const Option& option) {
  std::string text(option.name);
  if (!option.value.empty()) text.append(" ").append(option.value);
  return text;
}

// `words` broken into lines of at most `width` characters, each after `indent` spaces but the
// first, which continues a line already `column` characters long (after words of its own when
// `after_words`, so that a space goes first).
std::string wrapped(const std::vector<std::string>& words, std::size_t column, std::size_t indent, std::size_t width,
                    bool after_words) {
  std::string text;
  for (const std::string& word : words) {
    if (after_words && column + 1 + word.size() > width) {
      text.append(1, '\n').append(indent, ' ');
      column = indent;
    } else if (after_words) {
      text += ' ';
      ++column;
    }
    text += word;
    column += word.size();
    after_words = true;
  }
  return text;
}

std::vector<std::string> split_words(std::string_view text) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    if (end > start) words.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

// One form of a command in the usage: what follows the program's name, and what it does. In
// `form`, each option is named alone ("--hz") and written from the table with its value ("--hz
// N"); the brackets, "..." and the other words are the usage's own. A command given in two
// ways (the window on a lesson or on a setup, render at times or at a moment, bench's figures
// or its recommendation) has a form for each, as the usage always had.
struct Usage {
  Command command;         // whose options the form names; none for the forms that name none
  std::string_view form;
  std::string_view what;
  bool on_node;            // in the command line built for node
};
constexpr Command no_options{};
const Usage usages[] = {
    {for_window,
     "[LESSON] [--lock] [--set ...] [--hz] [--substeps] [--friction] [--theme] [--projector] [--at --screenshot] "
     "[--reveal] [--mystery --seed]",
     "the classroom window on a lesson (the first one if none is named; a name from list, or a .lua file); "
     "without a display it draws the lesson to a PNG instead",
     false},
    {for_window, "--setup [--theme] [--projector] [--at --screenshot] [--reveal]",
     "the window on a prepared setup (Lesson > Save as a setup): its lesson, values, lock, mystery and step settings",
     false},
    {for_list, "list [--tsv]", "the built-in lessons with their titles and moments", true},
    {for_run, "run LESSON [--duration] [--hz] [--substeps] [--friction] [--set ...] [--csv] [--mystery --seed]",
     "run a lesson without a window and print its table of theory against simulation", true},
    {for_check, "check [LESSON ...] [--set ...] [--hz] [--substeps] [--friction] [--random [--seed]]",
     "run lessons (every built-in one if none is named) and check their expectations; exit 1 if any fails", true},
    {for_render, "render LESSON [--at] [--size] [--theme] [--set ...] [--hz] [--substeps] [--friction] [--mystery --seed] --out",
     "draw the lesson at each time to PNG files, with no display", false},
    {for_render, "render LESSON --moment [--size] --out", "draw one of the lesson's moments (its time, values and theme)",
     false},
    {no_options, "demo", "theory beside simulation for every situation", true},
    {for_link, "link FILE.setup [--page]", "a setup file as a link to the web page (ADDRESS#setup=...)", true},
    {no_options, "link LINK | -",
     "the setup file a link holds, printed (- reads the link from the standard input); a lesson the link carries "
     "is kept among your lessons, and the setup names it",
     true},
    {for_bench, "bench [--quick] --out", "speed and accuracy figures, CSV files and charts", false},
    {for_bench, "bench --recommend --tol [--set ...]",
     "the cheapest step setting whose run of the lesson meets its table within X times the rows' tolerances at "
     "240 Hz (exit 1 if none does)",
     false},
    {no_options, "help | --help | -h", "this text", true},
    {no_options, "--version", "the version", true},
};

// A usage form as the help writes it (and the manual's synopsis), in the parts a line may break between: "run", "LESSON",
// "[--hz N]", "[--at S --screenshot FILE.png]", "--out PATH". Throws std::logic_error for an
// option the table does not give the command (option_for).
std::vector<std::string> form_parts(const Usage& usage) {
  std::vector<std::string> parts;
  int depth = 0;  // the brackets open before the word
  for (const std::string& word : split_words(usage.form)) {
    std::size_t open = 0, close = word.size();  // the word is word[open, close) inside its brackets
    while (open < close && word[open] == '[') ++open;
    while (close > open && word[close - 1] == ']') --close;
    const std::string_view core = std::string_view(word).substr(open, close - open);
    std::string text(open, '[');
    if (usage.command != no_options && core.rfind("--", 0) == 0) {
      text += written(option_for(usage.command, core));
    } else {
      text += core;
    }
    text.append(word.size() - close, ']');
    if (depth > 0 && !parts.empty()) {
      parts.back().append(" ").append(text);
    } else {
      parts.push_back(text);
    }
    depth += static_cast<int>(open) - static_cast<int>(word.size() - close);
  }
  return parts;
}

// "run, check and render": the names joined as a sentence joins them, with `last` before the last.
std::string sentence_list(const std::vector<std::string>& names, const char* last = " and ") {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == names.size() ? last : ", ") + names[i];
  }
  return text;
}

constexpr Command manual_order[] = {Command::window, Command::list,   Command::run,  Command::check,
                                    Command::render, Command::link, Command::bench};

// Whether `word` is one a value is written with in the table (NAME, FILE, N, ...) or one of the
// few more the manual's paragraphs use: a word to replace, in italics in the manual page.
bool placeholder(std::string_view word) {
  static const std::vector<std::string> words = [] {
    std::vector<std::string> found{"LESSON", "LINE", "ROW", "ANSWER", "TIME", "MOMENT"};
    for (const Option& option : table) {
      const std::string_view value = option.value;
      for (std::size_t i = 0; i < value.size();) {
        std::size_t end = i;
        while (end < value.size() && std::isupper(static_cast<unsigned char>(value[end]))) ++end;
        if (end > i) found.emplace_back(value.substr(i, end - i));
        i = std::max(end, i + 1);
      }
    }
    return found;
  }();
  return std::find(words.begin(), words.end(), word) != words.end();
}

// A value as the manual's tags write it: the words to replace in italics (NAME, FILE), the words
// typed as they stand in bold (light, png), the signs between in roman: "S[,S...]", "FILE.png".
std::string roff_value(std::string_view value) {
  std::string out;
  for (std::size_t i = 0; i < value.size();) {
    const auto upper = [&](std::size_t at) { return std::isupper(static_cast<unsigned char>(value[at])) != 0; };
    const auto lower = [&](std::size_t at) {
      return std::islower(static_cast<unsigned char>(value[at])) != 0 || std::isdigit(static_cast<unsigned char>(value[at])) != 0;
    };
    std::size_t end = i;
    if (upper(i) || lower(i)) {
      const bool italic = upper(i);
      while (end < value.size() && (italic ? upper(end) : lower(end))) ++end;
      out.append(italic ? "\\fI" : "\\fB").append(value.substr(i, end - i)).append("\\fR");
    } else {
      out += value[i] == '-' ? std::string("\\-") : std::string(1, value[i]);
      end = i + 1;
    }
    i = end;
  }
  return out;
}

// Plain words as roff: an option's name in bold with its hyphens as \-, a `typed word` in bold
// with its hyphens as \- (without the quotes), a word to replace (placeholder()) in italics, μ as
// \(*m, a backslash as \e, and a line that would start with a control character kept as text.
std::string roff(std::string_view text) {
  std::string out;
  const auto letter = [&](std::size_t i) { return i < text.size() && text[i] >= 'a' && text[i] <= 'z'; };
  bool typed = false;  // inside `backquotes`
  for (std::size_t i = 0; i < text.size();) {
    const bool word_start = i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1]));
    std::size_t caps = i;  // the end of the capitals from i
    while (caps < text.size() && std::isupper(static_cast<unsigned char>(text[caps]))) ++caps;
    if (text[i] == '`') {
      out += typed ? "\\fR" : "\\fB";
      typed = !typed;
      ++i;
    } else if (typed) {
      out += text[i] == '-' ? std::string("\\-") : text[i] == '\\' ? std::string("\\e") : std::string(1, text[i]);
      ++i;
    } else if (word_start && text.compare(i, 2, "--") == 0 && letter(i + 2)) {
      out += "\\fB\\-\\-";
      for (i += 2; letter(i) || (i < text.size() && text[i] == '-'); ++i) out += text[i] == '-' ? "\\-" : std::string(1, text[i]);
      out += "\\fR";
    } else if (word_start && caps > i && (caps == text.size() || !std::isalnum(static_cast<unsigned char>(text[caps]))) &&
               placeholder(text.substr(i, caps - i))) {
      out.append("\\fI").append(text.substr(i, caps - i)).append("\\fR");
      i = caps;
    } else if (text.compare(i, 2, "\xCE\xBC") == 0) {  // μ in UTF-8
      out += "\\(*m";
      i += 2;
    } else {
      out += text[i] == '\\' ? std::string("\\e") : std::string(1, text[i]);
      ++i;
    }
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out.insert(0, "\\&");
  return out;
}

// A word of a usage form as the manual's synopsis writes it: an option in bold with its hyphens
// as \-, the rest as the tags write values (roff_value: LESSON in italics, a command or a word
// typed as it stands in bold, signs such as | and ... in roman), its brackets in roman.
std::string roff_form_word(std::string_view word) {
  std::size_t open = 0, close = word.size();
  while (open < close && word[open] == '[') ++open;
  while (close > open && word[close - 1] == ']') --close;
  const std::string_view core = word.substr(open, close - open);
  std::string out(open, '[');
  if (core.size() > 1 && core[0] == '-' && std::isalpha(static_cast<unsigned char>(core.back())) != 0) {
    out += "\\fB";
    for (const char c : core) out += c == '-' ? std::string("\\-") : std::string(1, c);
    out += "\\fR";
  } else {
    out += roff_value(core);
  }
  return out.append(word.size() - close, ']');
}

std::string commands_of(const Option& option, bool node) {
  std::string names;
  for (const Command command : manual_order) {
    if (!includes(option.commands, command)) continue;
    if (node && (command == Command::window || command == Command::render || command == Command::bench)) continue;
    names += (names.empty() ? "" : ", ") + std::string(command_name(command));
  }
  return names;
}

}  // namespace

std::string_view command_name(Command command) {
  switch (command) {
    case Command::window: return "the window";
    case Command::list: return "list";
    case Command::run: return "run";
    case Command::check: return "check";
    case Command::render: return "render";
    case Command::link: return "link";
    case Command::bench: return "bench";
  }
  return "?";
}

double Option::number(const std::string& text) const {
  return option_number(std::string(name), text, range.low, range.high, range.low_open, range.unit);
}

int Option::whole_number(const std::string& text) const {
  const int whole = static_cast<int>(number(text));
  if (std::to_string(whole) != text) throw InvalidInput(std::string(name) + " " + text + ": a whole number " + range_words());
  return whole;
}

std::string Option::range_words() const {
  if (kind == ValueKind::size) return "width " + range_of(range) + ", height " + range_of(height_range);
  return range_of(range);
}

std::string Option::filled_in(std::string_view text) const {
  std::string line(text);
  const std::size_t at = line.find("{range}");
  if (at != std::string::npos) line.replace(at, 7, range_words());
  const std::size_t default_at = line.find("{default}");
  if (default_at != std::string::npos) line.replace(default_at, 9, number_words(default_value));
  const std::size_t held_at = line.find("{held}");
  if (held_at != std::string::npos) {
    std::vector<std::string> held;
    for (const Option& option : table) {
      if (option.held_by_setup && includes(option.commands, Command::window)) held.emplace_back(option.name);
    }
    line.replace(held_at, 6, sentence_list(held, " or "));
  }
  return line;
}

std::string Option::help_line() const {
  std::string line = filled_in(help);
  std::erase(line, '`');  // the marks of typed words, which the manual page sets in bold
  return line;
}

std::span<const Option> options_table() { return table; }

const Option& option_for(Command command, std::string_view name) {
  for (const Option& option : table) {
    if (option.name == name && includes(option.commands, command)) return option;
  }
  throw std::logic_error("frictionlab: the options table gives " + std::string(command_name(command)) + " no " +
                         std::string(name));
}

std::string unknown_option_message(Command command, const std::string& option) {
  const Refusals& words = refusals_of(command);
  std::vector<const Option*> order;
  for (const Listing& listing : listings) {
    if (listing.command != command) continue;
    for (const std::string& name : split_words(listing.names)) order.push_back(&option_for(command, name));
  }
  for (const Option& known : table) {
    if (includes(known.commands, command) && std::find(order.begin(), order.end(), &known) == order.end()) {
      order.push_back(&known);
    }
  }
  std::string listed;
  for (const Option* known : order) {
    // One needing the other is written as one: "--mystery MATERIAL/MATERIAL --seed N".
    const bool together = known->beside == Beside::together && !listed.empty();
    listed += (listed.empty() ? "" : together ? " " : ", ") + written(*known);
  }
  return std::string(words.prefix) + "unknown option '" + option + "'; " + words.options_are + ": " + listed + words.after_list;
}

void read_options(Command command, const std::vector<std::string>& args,
                  const std::function<void(const std::string&)>& operand,
                  const std::function<void(const Option&, const std::string&)>& take) {
  const Refusals& words = refusals_of(command);
  std::vector<std::string_view> seen;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      operand(arg);
      continue;
    }
    const auto known = std::find_if(std::begin(table), std::end(table), [&](const Option& option) {
      return option.name == arg && includes(option.commands, command);
    });
    if (known == std::end(table)) throw InvalidInput(unknown_option_message(command, arg));
    if (known->kind == ValueKind::none) {
      take(*known, "");  // a switch given twice asks for the same thing twice
      continue;
    }
    if (i + 1 >= args.size()) throw InvalidInput(words.prefix + arg + " needs a value; see frictionlab help");
    // The next word is the value, unless it is one of this command's options: then the value was
    // left out (run --csv --set a=1 would write a file named --set). A value that only starts
    // with a hyphen, -1 or -, is a value.
    const std::string& value = args[i + 1];
    const bool an_option = std::any_of(std::begin(table), std::end(table), [&](const Option& option) {
      return option.name == value && includes(option.commands, command);
    });
    if (an_option) {
      throw InvalidInput(words.prefix + arg + " needs a value (" + std::string(known->value) + "); got the option " + value);
    }
    // Given twice, which one was meant is not for the program to guess; --set is repeatable,
    // one parameter each time, and says itself when one parameter is given two values.
    if (!known->repeatable) {
      if (std::find(seen.begin(), seen.end(), known->name) != seen.end()) {
        throw InvalidInput(words.prefix + arg + " given twice" + words.give_it_once + std::string(known->twice_hint));
      }
      seen.push_back(known->name);
    }
    take(*known, value);
    ++i;
  }
}

std::string usage_text(Program program) {
  const bool node = program == Program::node;
  const std::string name = node ? "node frictionlab-cli.js" : "frictionlab";
  constexpr std::size_t width = 100, what_column = 44;
  std::string text;
  bool first = true;
  for (const Usage& usage : usages) {
    if (node && !usage.on_node) continue;
    std::string line = (first ? "usage: " : "       ") + name;
    first = false;
    // Continued lines start under the command's first word after its name.
    const std::vector<std::string> parts = form_parts(usage);
    const bool named = usage.command != Command::window && usage.command != no_options;
    const std::size_t indent = line.size() + 1 + (named ? parts.front().size() + 1 : 0);
    line += wrapped(parts, line.size(), indent, width, true);
    const std::size_t last_line = line.size() - std::min(line.size(), line.rfind('\n') + 1);
    text += line;
    if (last_line + 2 <= what_column) {
      text += std::string(what_column - last_line, ' ');
    } else {
      text += "\n" + std::string(what_column, ' ');
    }
    text += wrapped(split_words(usage.what), what_column, what_column, width, false) + "\n";
  }
  text += "Options, with the commands that take them:\n";
  constexpr std::size_t help_column = 30;
  for (const Option& option : table) {
    const std::string commands = commands_of(option, node);
    if (commands.empty()) continue;
    std::string line = "  " + written(option);
    line += line.size() + 2 <= help_column ? std::string(help_column - line.size(), ' ') : "\n" + std::string(help_column, ' ');
    std::vector<std::string> words = split_words(option.help_line());
    words.insert(words.begin(), "(" + commands + ")");
    text += line + wrapped(words, help_column, help_column, width, false) + "\n";
  }
  // The window's keys, from the list its help panel shows; node has no window.
  if (!node) {
    text += "Keys in the window:\n";
    constexpr std::size_t key_column = 16;
    for (const classroom_state::WindowKey& key : classroom_state::window_keys()) {
      std::string line = "  " + std::string(key.key);
      // Columns count characters: the arrows are three bytes each in UTF-8.
      const std::size_t shown = line.size() - 2 * static_cast<std::size_t>(std::count(key.key.begin(), key.key.end(), '\xe2'));
      line += std::string(key_column - std::min(key_column - 1, shown), ' ');
      text += line + wrapped(split_words(std::string(key.does)), key_column, key_column, width, false) + "\n";
    }
  }
  if (node) {
    text +=
        "Exit status: 0 done; 1 check or demo found simulation and theory disagreeing; 2 bad input (the\n"
        "message names what and where) or the program could not finish.\n"
        "This is FrictionLab's WebAssembly build for node: the classroom is the web page, and render and\n"
        "bench are the desktop program's.\n";
  } else {
    text +=
        "Exit status: 0 done; 1 check or demo found simulation and theory disagreeing, or\n"
        "bench --recommend found no setting; 2 bad input (the message names what and where) or the\n"
        "program could not finish.\n"
        "The built-in lessons are in $FRICTIONLAB_LESSONS if set, else installed beside the program.\n"
        "More in the manual: man frictionlab\n";
  }
  return text;
}

std::string manual_synopsis() {
  std::string text;
  for (const Usage& usage : usages) {
    std::vector<std::string> parts = form_parts(usage);
    // A command's name goes into .SY with the program's, so that its form's lines wrap under
    // its first operand; the window's forms and --version start with an operand or an option.
    std::string name = "frictionlab";
    const auto is_command = [](const std::string& part) {
      return std::all_of(part.begin(), part.end(), [](char c) { return c >= 'a' && c <= 'z'; });
    };
    if (!parts.empty() && is_command(parts.front())) {
      name = "\"frictionlab " + parts.front() + "\"";
      parts.erase(parts.begin());
    }
    text += ".SY " + name + "\n";
    std::string line;
    for (const std::string& part : parts) {
      if (!line.empty()) line += ' ';
      // The words of one part joined by roff's unbreakable space: a line breaks between parts only.
      const std::vector<std::string> words = split_words(part);
      for (std::size_t i = 0; i < words.size(); ++i) line += (i == 0 ? "" : "\\ ") + roff_form_word(words[i]);
    }
    if (!line.empty()) text += line + "\n";
    text += ".YS\n";
  }
  return text;
}

std::string manual_options() {
  std::string text;
  for (const Command section : manual_order) {
    std::string entries;
    for (const Option& option : table) {
      const Command* first = std::find_if(std::begin(manual_order), std::end(manual_order),
                                          [&](Command command) { return includes(option.commands, command); });
      if (*first != section) continue;
      std::string tag = "\\fB";
      for (const char c : option.name) tag += c == '-' ? std::string("\\-") : std::string(1, c);
      tag += "\\fR";
      if (!option.value.empty()) tag.append(1, ' ').append(roff_value(option.value));
      std::string paragraph = option.filled_in(option.manual.empty() ? option.help : option.manual);
      paragraph[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(paragraph[0])));
      if (paragraph.back() != '.') paragraph += '.';
      std::vector<std::string> others;
      for (const Command command : manual_order) {
        if (command != section && includes(option.commands, command)) {
          others.emplace_back(1, '`');
          others.back().append(command_name(command)).append(1, '`');
        }
      }
      if (!others.empty()) paragraph += " Also taken by " + sentence_list(others) + ".";
      entries += ".TP\n" + tag + "\n" + roff(paragraph) + "\n";
    }
    if (!entries.empty()) text += ".SS " + std::string(section == Command::window ? "The window" : command_name(section)) + "\n" + entries;
  }
  return text;
}

void say_bad_input(std::ostream& err, const std::string& context, const std::string& message) {
  err << "frictionlab: " << context << message << '\n';
  if (const std::string plain = classroom_state::plain_words(message); !plain.empty()) err << plain << '\n';
}

}  // namespace frictionlab
