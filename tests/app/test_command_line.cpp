// The options table (app/command_line.h), which the window, run, check and render read their
// options through: each command's own parser reads every option the table gives it, and each
// command refuses the others with its usual message; the numbers keep to the table's ranges;
// the help names every option with its range; and the manual page the build wrote holds the
// SYNOPSIS and OPTIONS the usage and the table write now.
#include "app/command_line.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/modes.h"
#include "app/options.h"
#include "physics/materials.h"

namespace frictionlab {
namespace {

// The commands whose parsers read the table; list, link and bench read their few options
// themselves, so only the help and the manual page are held to the table for them.
constexpr Command parsed[] = {Command::window, Command::run,  Command::check, Command::render,
                               Command::list,   Command::link, Command::bench};

struct Reading {
  const Option* option = nullptr;  // the last option taken
  std::string value;
  std::vector<std::string> operands;
  std::string refusal;  // InvalidInput's message, when the arguments were refused
};

Reading read(Command command, const std::vector<std::string>& args) {
  Reading reading;
  try {
    read_options(
        command, args, [&](const std::string& word) { reading.operands.push_back(word); },
        [&](const Option& option, const std::string& value) {
          reading.option = &option;
          reading.value = value;
        });
  } catch (const InvalidInput& error) {
    reading.refusal = error.what();
  }
  return reading;
}

std::vector<std::string> given(const Option& option) {
  std::vector<std::string> args{"incline", std::string(option.name)};
  if (option.kind != ValueKind::none) args.emplace_back(option.example);
  return args;
}

// The row of the table for `name` that `command` reads, if any.
const Option* row_for(Command command, std::string_view name) {
  for (const Option& option : options_table()) {
    if (option.name == name && includes(option.commands, command)) return &option;
  }
  return nullptr;
}

TEST(OptionsTable, EveryRowIsComplete) {
  for (const Option& option : options_table()) {
    SCOPED_TRACE(std::string(option.name));
    EXPECT_EQ(option.name.rfind("--", 0), 0u);
    EXPECT_NE(static_cast<unsigned>(option.commands), 0u);
    EXPECT_FALSE(option.help.empty());
    EXPECT_EQ(option.value.empty(), option.kind == ValueKind::none);
    EXPECT_EQ(option.example.empty(), option.kind == ValueKind::none);
    // A ranged value says its range in the help, from the table's numbers.
    const bool ranged = option.kind == ValueKind::number || option.kind == ValueKind::whole_number ||
                        option.kind == ValueKind::numbers || option.kind == ValueKind::size;
    EXPECT_EQ(option.help.find("{range}") != std::string_view::npos, ranged);
    if (ranged) {
      EXPECT_LT(option.range.low, option.range.high);
    }
    EXPECT_EQ(option.help_line().find('{'), std::string::npos);
    // `typed words` are closed where they open.
    EXPECT_EQ(std::count(option.help.begin(), option.help.end(), '`') % 2, 0);
    EXPECT_EQ(std::count(option.manual.begin(), option.manual.end(), '`') % 2, 0);
  }
}

TEST(OptionsTable, NoCommandHasTwoRowsOfOneName) {
  for (const Option& option : options_table()) {
    for (const Option& other : options_table()) {
      if (&option == &other || option.name != other.name) continue;
      EXPECT_EQ(static_cast<unsigned>(option.commands) & static_cast<unsigned>(other.commands), 0u) << option.name;
    }
  }
}

TEST(OptionsTable, EachCommandTakesItsOptionsAndRefusesTheOthersWithItsMessage) {
  for (const Option& option : options_table()) {
    for (const Command command : parsed) {
      SCOPED_TRACE(std::string(option.name) + " for " + std::string(command_name(command)));
      const Reading reading = read(command, given(option));
      const Option* row = row_for(command, option.name);
      if (row != nullptr) {
        EXPECT_EQ(reading.refusal, "");
        EXPECT_EQ(reading.option, row);
        EXPECT_EQ(reading.operands, std::vector<std::string>{"incline"});
        if (row == &option) {
          EXPECT_EQ(reading.value, std::string(option.example));
        }
      } else {
        EXPECT_EQ(reading.refusal, unknown_option_message(command, std::string(option.name)));
        EXPECT_NE(reading.refusal.find("unknown option '" + std::string(option.name) + "'; "), std::string::npos);
      }
    }
  }
}

// A whole command line for `command` with `option` in it: a lesson (but beside --setup, which
// holds one), and the options the command cannot go without.
std::vector<std::string> whole_line(Command command, const Option& option) {
  std::vector<std::string> args;
  if (option.name != "--setup") args.emplace_back("incline");
  args.emplace_back(option.name);
  if (option.kind != ValueKind::none) args.emplace_back(option.example);
  const auto add = [&](std::initializer_list<const char*> words) { args.insert(args.end(), words.begin(), words.end()); };
  if (option.name == "--mystery") add({"--seed", "42"});
  if (option.name == "--reveal") add({"--screenshot", "window.png"});  // a picture's option only
  if (option.name == "--seed") {
    if (command == Command::check) {
      add({"--random", "3"});
    } else {
      add({"--mystery", "aluminium/wood"});
    }
  }
  if (command == Command::render) {
    if (option.name != "--at" && option.name != "--moment") add({"--at", "1"});
    if (option.name != "--out") add({"--out", "picture.png"});
  }
  return args;
}

// The commands' own parsers, each given every option the table says its command takes: a row
// a parser does not read would be a std::logic_error when someone gives it, not a refusal.
TEST(OptionsTable, EachCommandsParserReadsEveryOptionTheTableGivesIt) {
  const std::pair<Command, void (*)(const std::vector<std::string>&)> parsers[] = {
      {Command::run, parse_run_arguments},
      {Command::check, parse_check_arguments},
      {Command::render, parse_render_arguments},
      {Command::window, parse_window_arguments},
  };
  for (const auto& [command, parse] : parsers) {
    int taken = 0;
    for (const Option& option : options_table()) {
      if (!includes(option.commands, command)) continue;
      const std::vector<std::string> args = whole_line(command, option);
      std::string line;
      for (const std::string& arg : args) line += " " + arg;
      SCOPED_TRACE(std::string(command_name(command)) + ":" + line);
      try {
        parse(args);
        ++taken;
      } catch (const std::exception& error) {
        ADD_FAILURE() << error.what();
      }
    }
    EXPECT_GT(taken, 3);
  }
  // And each refuses another command's option with its message, not a logic_error.
  EXPECT_THROW(parse_run_arguments({"incline", "--lock", "mu_s"}), InvalidInput);
  EXPECT_THROW(parse_check_arguments({"incline", "--duration", "1"}), InvalidInput);
  EXPECT_THROW(parse_render_arguments({"incline", "--at", "1", "--out", "x.png", "--csv", "x.csv"}), InvalidInput);
  EXPECT_THROW(parse_window_arguments({"incline", "--random", "3"}), InvalidInput);
}

// check --random's count keeps to the table's range, whatever its number of digits; its seed's
// default is said in the help from the constant check uses.
TEST(OptionsTable, ChecksRandomKeepsToTheTable) {
  const Option& random = option_for(Command::check, "--random");
  const auto whole = [](double value) { return std::to_string(static_cast<long long>(value)); };
  EXPECT_NO_THROW(parse_check_arguments({"incline", "--random", whole(random.range.high)}));
  EXPECT_NO_THROW(parse_check_arguments({"incline", "--random", whole(random.range.low)}));
  for (const std::string& refused : {whole(random.range.high + 1), whole(random.range.high * 10), whole(random.range.low - 1),
                                     std::string("99999999999999999999"), std::string("2.5"), std::string("")}) {
    SCOPED_TRACE(refused);
    try {
      parse_check_arguments({"incline", "--random", refused});
      ADD_FAILURE() << "taken";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(std::string(error.what()), "check: --random " + refused + ": give a whole number of settings " +
                                               random.range_words());
    }
  }
  EXPECT_NE(option_for(Command::check, "--seed").help_line().find("(default " + std::to_string(default_random_seed) + ")"),
            std::string::npos);
}

// A value left out is not taken from the next option: run --csv --set would write a file named
// --set. A value that only starts with a hyphen is a value.
TEST(OptionsTable, AnOptionIsNotTakenAsTheValueBeforeIt) {
  EXPECT_EQ(read(Command::run, {"push", "--duration", "0.01", "--csv", "--set"}).refusal,
            "run: --csv needs a value (FILE); got the option --set");
  EXPECT_EQ(read(Command::window, {"--lock", "--projector"}).refusal, "--lock needs a value (NAME[,NAME...]); got the option --projector");
  EXPECT_EQ(read(Command::render, {"incline", "--out", "--at", "1"}).refusal, "render: --out needs a value (PATH); got the option --at");
  for (const Option& option : options_table()) {
    for (const Command command : parsed) {
      if (!includes(option.commands, command) || option.kind == ValueKind::none) continue;
      SCOPED_TRACE(std::string(option.name) + " for " + std::string(command_name(command)));
      // Another option of the command's (or the same one) where the value should be.
      const Option* next = &option;
      for (const Option& other : options_table()) {
        if (&other != &option && includes(other.commands, command)) next = &other;
      }
      const std::string refusal = read(command, {"incline", std::string(option.name), std::string(next->name)}).refusal;
      const std::string prefix = command == Command::window ? "" : std::string(command_name(command)) + ": ";
      EXPECT_EQ(refusal, prefix + std::string(option.name) + " needs a value (" + std::string(option.value) +
                             "); got the option " + std::string(next->name));
    }
  }
  // Negative numbers, - and another command's option are values, for the command to judge.
  Reading at = read(Command::window, {"--at", "-1"});
  EXPECT_EQ(at.refusal, "");
  EXPECT_EQ(at.value, "-1");
  Reading set = read(Command::run, {"push", "--set", "a_x=-3"});
  EXPECT_EQ(set.refusal, "");
  EXPECT_EQ(set.value, "a_x=-3");
  EXPECT_EQ(read(Command::run, {"push", "--csv", "-"}).value, "-");
  EXPECT_EQ(read(Command::run, {"push", "--csv", "--lock"}).value, "--lock");
}

// The messages as they were before the table (copied from 734510b's app/lesson_commands.cpp,
// app/render_command.cpp and app/window_command.cpp), which tests/CMakeLists.txt's command-line
// tests and people's scripts know: the options each command lists, in its own order.
TEST(OptionsTable, UnknownOptionMessagesAreAsBeforeTheTable) {
  EXPECT_EQ(unknown_option_message(Command::run, "--frobnicate"),
            "run: unknown option '--frobnicate'; options: --duration S, --hz N, --substeps N, --friction T, "
            "--set NAME=VALUE, --csv FILE, --mystery MATERIAL/MATERIAL --seed N");
  EXPECT_EQ(unknown_option_message(Command::check, "--fast"),
            "check: unknown option '--fast'; options: --set NAME=VALUE, --hz N, --substeps N, --friction T, --random N, "
            "--seed S");
  EXPECT_EQ(unknown_option_message(Command::render, "--width"),
            "render: unknown option '--width'; options: --at S[,S...], --moment NAME, --size WxH, --theme light|dark, "
            "--set NAME=VALUE, --out PATH, --hz N, --substeps N, --friction T, --mystery MATERIAL/MATERIAL --seed N");
  EXPECT_EQ(unknown_option_message(Command::window, "--fullscreen"),
            "unknown option '--fullscreen'; the window's options: --lock NAME[,NAME...], --set NAME=VALUE, --hz N, "
            "--substeps N, --friction T, --theme light|dark, --projector, --at S, --screenshot FILE.png, --reveal, "
            "--mystery MATERIAL/MATERIAL --seed N, --setup FILE (commands: list, run, check, render, demo, bench, link, help, --version)");
}

// list, link and bench read their options through the table too, and refuse an unknown one
// with the options they take.
TEST(OptionsTable, ListLinkAndBenchListTheirOptionsWhenRefusingOne) {
  EXPECT_EQ(unknown_option_message(Command::list, "--csv"), "list: unknown option '--csv'; options: --tsv");
  EXPECT_EQ(unknown_option_message(Command::link, "--site"), "link: unknown option '--site'; options: --page ADDRESS");
  EXPECT_EQ(unknown_option_message(Command::bench, "--fast"),
            "bench: unknown option '--fast'; options: --quick, --out DIR, --recommend LESSON, --tol X, --set NAME=VALUE");
}

TEST(OptionsTable, AValueMissingOrGivenTwiceIsRefused) {
  for (const Option& option : options_table()) {
    for (const Command command : parsed) {
      if (!includes(option.commands, command) || option.kind == ValueKind::none) continue;
      SCOPED_TRACE(std::string(option.name) + " for " + std::string(command_name(command)));
      const std::string prefix = command == Command::window ? "" : std::string(command_name(command)) + ": ";
      EXPECT_EQ(read(command, {"incline", std::string(option.name)}).refusal,
                prefix + std::string(option.name) + " needs a value; see frictionlab help");
      std::vector<std::string> twice = given(option);
      twice.insert(twice.end(), {std::string(option.name), std::string(option.example)});
      const std::string refusal = read(command, twice).refusal;
      if (option.repeatable) {
        EXPECT_EQ(refusal, "");
      } else {
        EXPECT_EQ(refusal.rfind(prefix + std::string(option.name) + " given twice", 0), 0u) << refusal;
      }
    }
  }
  // A switch given twice asks for the same thing twice.
  EXPECT_EQ(read(Command::window, {"--projector", "--projector"}).refusal, "");
  EXPECT_EQ(read(Command::render, {"--at", "1", "--at", "2"}).refusal,
            "render: --at given twice; give it once (several times go in one --at, as in --at 1,2)");
  EXPECT_EQ(read(Command::window, {"--hz", "240", "--hz", "480"}).refusal, "--hz given twice");
}

TEST(OptionsTable, NumbersKeepToTheTablesRanges) {
  for (const Option& option : options_table()) {
    if (option.kind != ValueKind::number && option.kind != ValueKind::whole_number) continue;
    SCOPED_TRACE(std::string(option.name));
    const Range& range = option.range;
    const auto text = [](double value) {
      std::string written = std::to_string(value);
      written.erase(written.find_last_not_of('0') + 1);
      if (written.back() == '.') written.pop_back();
      return written;
    };
    EXPECT_EQ(option.number(text(range.high)), range.high);
    if (range.low_open) {
      EXPECT_THROW(option.number(text(range.low)), InvalidInput);
    } else {
      EXPECT_EQ(option.number(text(range.low)), range.low);
    }
    try {
      option.number(text(range.high + 1));
      ADD_FAILURE() << "above the range, taken";
    } catch (const InvalidInput& error) {
      // The message names the option and the allowed range.
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(std::string(option.name) + " = ", 0), 0u) << message;
      EXPECT_NE(message.find("is outside the allowed range"), std::string::npos) << message;
      std::ostringstream high;  // as the message writes it: 1e+06
      high << range.high << "]";
      EXPECT_NE(message.find(high.str()), std::string::npos) << message;
    }
  }
  const Option& substeps = option_for(Command::run, "--substeps");
  EXPECT_EQ(substeps.whole_number("8"), 8);
  try {
    substeps.whole_number("2.5");
    ADD_FAILURE() << "--substeps 2.5 taken";
  } catch (const InvalidInput& error) {
    EXPECT_STREQ(error.what(), "--substeps 2.5: a whole number from 1 to 1000");
  }
  EXPECT_EQ(option_for(Command::run, "--duration").range_words(), "above 0, at most 86400");
  EXPECT_EQ(option_for(Command::render, "--size").range_words(), "width from 320 to 7680, height from 240 to 4320");
  EXPECT_THROW(option_for(Command::check, "--lock"), std::logic_error);
}

// The help with each run of spaces and line breaks as one space: its lines are wrapped at spaces.
std::string one_line(const std::string& text) {
  std::string line;
  for (const char c : text) {
    const bool space = c == ' ' || c == '\n';
    if (!space || (!line.empty() && line.back() != ' ')) line += space ? ' ' : c;
  }
  return line;
}

TEST(OptionsTable, TheHelpNamesEveryOptionWithItsRangeAndCommands) {
  const std::string help = usage_text(Program::desktop);
  const std::string flat = one_line(help);
  for (const Option& option : options_table()) {
    SCOPED_TRACE(std::string(option.name));
    const std::string written = std::string(option.name) + (option.value.empty() ? "" : " " + std::string(option.value));
    const std::size_t line = help.find("\n  " + written);
    ASSERT_NE(line, std::string::npos) << "no line of its own";
    const char after = help[line + 3 + written.size()];
    EXPECT_TRUE(after == ' ' || after == '\n') << help.substr(line, 80);
    EXPECT_NE(flat.find(option.help_line()), std::string::npos);
  }
  EXPECT_NE(help.find("[--random N [--seed S]]"), std::string::npos) << help;
  EXPECT_NE(help.find("[--mystery MATERIAL/MATERIAL --seed N]"), std::string::npos) << help;
  EXPECT_NE(help.find("[--set NAME=VALUE ...]"), std::string::npos) << help;
  EXPECT_NE(help.find(" --out PATH"), std::string::npos) << help;  // required, so not in brackets
  EXPECT_NE(flat.find(" --hz N (the window, run, check, render) steps per simulated second, from 1 to 100000 (default 240)"),
            std::string::npos)
      << help;
  for (const char* line : {"usage: frictionlab [LESSON] ", "\n       frictionlab run LESSON ",
                           "\n       frictionlab render LESSON ", "\n       frictionlab --version "}) {
    EXPECT_NE(help.find(line), std::string::npos) << line;
  }
}

// The usage's forms, one a line as the help writes them: "frictionlab run LESSON [--duration S] ...".
std::vector<std::string> usage_forms(const std::string& help, const std::string& name) {
  const std::string usage = one_line(help.substr(0, help.find("\nOptions, with the commands")));
  std::vector<std::string> forms;
  for (std::size_t at = usage.find(" " + name + " "); at != std::string::npos;) {
    const std::size_t next = usage.find(" " + name + " ", at + 1);
    forms.push_back(usage.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
    at = next;
  }
  return forms;
}

// Every option a command takes is in one of its usage forms (the window's forms start with
// "[LESSON]" or "--setup", the others with the command's name).
TEST(OptionsTable, TheUsageFormsNameEveryOptionOfTheirCommand) {
  const std::vector<std::string> forms = usage_forms(usage_text(Program::desktop), "frictionlab");
  ASSERT_GE(forms.size(), 14u);
  for (const Option& option : options_table()) {
    for (const Command command : {Command::window, Command::list, Command::run, Command::check, Command::render,
                                  Command::link, Command::bench}) {
      if (!includes(option.commands, command)) continue;
      SCOPED_TRACE(std::string(option.name) + " for " + std::string(command_name(command)));
      const std::string written = std::string(option.name) + (option.value.empty() ? "" : " " + std::string(option.value));
      const bool in_a_form = std::any_of(forms.begin(), forms.end(), [&](const std::string& form) {
        const std::string first = form.substr(12, form.find(' ', 12) - 12);  // after "frictionlab "
        const bool its = command == Command::window ? first == "[LESSON]" || first == "--setup"
                                                    : first == command_name(command);
        for (std::size_t at = form.find(written); its && at != std::string::npos; at = form.find(written, at + 1)) {
          const std::size_t end = at + written.size();
          const bool starts = form[at - 1] == ' ' || form[at - 1] == '[';
          if (starts && (end == form.size() || form[end] == ' ' || form[end] == ']')) return true;
        }
        return false;
      });
      EXPECT_TRUE(in_a_form);
    }
  }
}

// The forms the usage had before the table (734510b's app/main.cpp), where a command is given
// in two ways or an option goes only with another: --setup stands apart from a lesson and what
// a setup holds; --at goes with --screenshot; render takes --at or --moment; bench makes its
// figures or a recommendation.
TEST(OptionsTable, TheUsageKeepsTheFormsItHad) {
  const std::vector<std::string> forms = usage_forms(usage_text(Program::desktop), "frictionlab");
  for (const char* form :
       {"frictionlab [LESSON] [--lock NAME[,NAME...]] [--set NAME=VALUE ...] [--hz N] [--substeps N] [--friction T] "
        "[--theme light|dark] [--projector] [--at S --screenshot FILE.png] [--reveal] [--mystery MATERIAL/MATERIAL --seed N] "
        "the classroom window",
        "frictionlab --setup FILE [--theme light|dark] [--projector] [--at S --screenshot FILE.png] [--reveal] the window "
        "on a prepared setup",
        "frictionlab list [--tsv] the built-in lessons",
        "frictionlab run LESSON [--duration S] [--hz N] [--substeps N] [--friction T] [--set NAME=VALUE ...] "
        "[--csv FILE] [--mystery MATERIAL/MATERIAL --seed N] run a lesson",
        "frictionlab check [LESSON ...] [--set NAME=VALUE ...] [--hz N] [--substeps N] [--friction T] "
        "[--random N [--seed S]] run lessons",
        "frictionlab render LESSON [--at S[,S...]] [--size WxH] [--theme light|dark] [--set NAME=VALUE ...] [--hz N] "
        "[--substeps N] [--friction T] [--mystery MATERIAL/MATERIAL --seed N] --out PATH draw the lesson at each time",
        "frictionlab render LESSON --moment NAME [--size WxH] --out PATH draw one of the lesson's moments",
        "frictionlab link FILE.setup [--page ADDRESS] a setup file as a link",
        "frictionlab bench [--quick] --out DIR speed and accuracy figures",
        "frictionlab bench --recommend LESSON --tol X [--set NAME=VALUE ...] the cheapest step setting"}) {
    const bool found = std::any_of(forms.begin(), forms.end(), [&](const std::string& line) { return line.rfind(form, 0) == 0; });
    EXPECT_TRUE(found) << form;
  }
}

TEST(OptionsTable, NodesHelpHasOnlyNodesCommands) {
  const std::string help = usage_text(Program::node);
  EXPECT_EQ(help.rfind("usage: node frictionlab-cli.js list [--tsv]", 0), 0u) << help;
  EXPECT_NE(help.find("--hz N"), std::string::npos);
  EXPECT_NE(help.find("(run, check) sets a lesson parameter"), std::string::npos) << help;
  for (const char* desktop_only : {"--lock", "--size", "--quick", "--projector", "frictionlab-cli.js render",
                                   "frictionlab-cli.js bench", "[LESSON]"}) {
    EXPECT_EQ(help.find(desktop_only), std::string::npos) << desktop_only;
  }
}

// --- The manual page ----------------------------------------------------------------------

TEST(ManualPage, OptionsAreRoffFromTheTable) {
  const std::string options = manual_options();
  // A tag's option in bold, the words of its value to replace in italics, those typed as they
  // stand in bold, the signs between in roman.
  EXPECT_EQ(options.rfind(".SS The window\n.TP\n\\fB\\-\\-lock\\fR \\fINAME\\fR[,\\fINAME\\fR...]\n", 0), 0u) << options;
  EXPECT_NE(options.find("\n.TP\n\\fB\\-\\-projector\\fR\n"), std::string::npos);
  EXPECT_NE(options.find("\n.TP\n\\fB\\-\\-theme\\fR \\fBlight\\fR|\\fBdark\\fR\n"), std::string::npos);
  EXPECT_NE(options.find("\n.TP\n\\fB\\-\\-hz\\fR \\fIN\\fR\nSteps per simulated second, from 1 to 100000 (default 240). "
                         "Also taken by \\fBrun\\fR, \\fBcheck\\fR and \\fBrender\\fR.\n"),
            std::string::npos)
      << options;
  // Values typed as they stand are bold, with their hyphens as \- (not hyphens, which man may
  // print as another character); the backquotes that mark them in the table are not printed.
  EXPECT_NE(options.find("The friction treatment: \\fBstick\\-slip\\fR (converges to Coulomb), \\fBthreshold\\fR"),
            std::string::npos)
      << options;
  EXPECT_EQ(options.find('`'), std::string::npos);
  EXPECT_NE(options.find("to \\fIFILE\\fR (a \\fB.csv\\fR file, or \\fB\\-\\fR for the standard output"), std::string::npos)
      << options;
  EXPECT_NE(one_line(usage_text(Program::desktop)).find("the friction treatment: stick-slip (the default"), std::string::npos);
  EXPECT_EQ(usage_text(Program::desktop).find('`'), std::string::npos);
  // Options named in a paragraph are bold, μ is roff's.
  EXPECT_NE(options.find("hidden (sliders, values, the theory's predictions and curves, CSV, title) until the teacher "
                         "reveals them; needs \\fB\\-\\-seed\\fR."),
            std::string::npos)
      << options;
  EXPECT_NE(options.find("one whose \\(*ms and \\(*mk are sliders"), std::string::npos);
  // --setup names the options a setup file holds, from the table.
  EXPECT_NE(options.find("Not with a lesson, \\fB\\-\\-lock\\fR, \\fB\\-\\-set\\fR, \\fB\\-\\-hz\\fR, "
                         "\\fB\\-\\-substeps\\fR, \\fB\\-\\-friction\\fR, \\fB\\-\\-mystery\\fR or "
                         "\\fB\\-\\-seed\\fR, which the file holds"),
            std::string::npos)
      << options;
  for (const char* section : {"\n.SS run\n", "\n.SS check\n", "\n.SS render\n", "\n.SS list\n", "\n.SS link\n",
                              "\n.SS bench\n"}) {
    EXPECT_NE(options.find(section), std::string::npos) << section;
  }
}

// The synopsis is the usage's forms in roff: one .SY block a form, the command's name beside the
// program's, options in bold, the words to replace in italics, and each bracketed group held
// together by unbreakable spaces (\ ), so that a line breaks only where the help's may.
TEST(ManualPage, SynopsisIsRoffOfTheUsagesForms) {
  const std::string synopsis = manual_synopsis();
  const std::vector<std::string> forms = usage_forms(usage_text(Program::desktop), "frictionlab");
  std::size_t blocks = 0;
  for (std::size_t at = synopsis.find(".SY "); at != std::string::npos; at = synopsis.find(".SY ", at + 1)) ++blocks;
  EXPECT_EQ(blocks, forms.size()) << synopsis;
  EXPECT_EQ(std::count(synopsis.begin(), synopsis.end(), '\n'),
            static_cast<std::ptrdiff_t>(3 * forms.size() - 1))  // .SY, the form's line, .YS; demo has no line
      << synopsis;
  EXPECT_EQ(synopsis.rfind(".SY frictionlab\n[\\fILESSON\\fR] [\\fB\\-\\-lock\\fR\\ \\fINAME\\fR[,\\fINAME\\fR...]] ", 0), 0u)
      << synopsis;
  EXPECT_NE(synopsis.find("\n.SY \"frictionlab run\"\n\\fILESSON\\fR [\\fB\\-\\-duration\\fR\\ \\fIS\\fR] "), std::string::npos)
      << synopsis;
  EXPECT_NE(synopsis.find(" [\\fB\\-\\-mystery\\fR\\ \\fIMATERIAL\\fR/\\fIMATERIAL\\fR\\ \\fB\\-\\-seed\\fR\\ \\fIN\\fR]"),
            std::string::npos)
      << synopsis;
  EXPECT_NE(synopsis.find(" [\\fB\\-\\-theme\\fR\\ \\fBlight\\fR|\\fBdark\\fR] "), std::string::npos) << synopsis;
  EXPECT_NE(synopsis.find("\n.SY \"frictionlab demo\"\n.YS\n"), std::string::npos) << synopsis;
  EXPECT_NE(synopsis.find("\n.SY \"frictionlab link\"\n\\fILINK\\fR | \\-\n.YS\n"), std::string::npos) << synopsis;
  EXPECT_NE(synopsis.find("\n.SY \"frictionlab help\"\n| \\fB\\-\\-help\\fR | \\fB\\-h\\fR\n.YS\n"), std::string::npos)
      << synopsis;
  EXPECT_TRUE(synopsis.ends_with("\n.SY frictionlab\n\\fB\\-\\-version\\fR\n.YS\n")) << synopsis;
  // A hyphen is \- throughout, never a bare one, which man may print as another character.
  for (std::size_t at = synopsis.find('-'); at != std::string::npos; at = synopsis.find('-', at + 1)) {
    EXPECT_EQ(synopsis[at - 1], '\\') << synopsis.substr(at - std::min<std::size_t>(at, 20), 40);
  }
}

// The page the build wrote holds the SYNOPSIS the usage writes now.
TEST(ManualPage, TheBuiltPageHasTheUsagesSynopsis) {
  std::ifstream page(FRICTIONLAB_MAN_PAGE);
  ASSERT_TRUE(page) << FRICTIONLAB_MAN_PAGE;
  std::stringstream text;
  text << page.rdbuf();
  EXPECT_NE(text.str().find(".SH SYNOPSIS\n.nh\n.ad l\n" + manual_synopsis()), std::string::npos);
  EXPECT_EQ(text.str().find("@FRICTIONLAB_MAN_SYNOPSIS@"), std::string::npos);
}

// The page the build wrote holds the OPTIONS the table writes now: a page from before a change
// to the table would fail here.
TEST(ManualPage, TheBuiltPageHasTheTablesOptions) {
  std::ifstream page(FRICTIONLAB_MAN_PAGE);
  ASSERT_TRUE(page) << FRICTIONLAB_MAN_PAGE;
  std::stringstream text;
  text << page.rdbuf();
  EXPECT_NE(text.str().find(".SH OPTIONS\n" + manual_options() + ".SH KEYS IN THE WINDOW\n"), std::string::npos);
  EXPECT_EQ(text.str().find("@FRICTIONLAB_MAN_OPTIONS@"), std::string::npos);
}

}  // namespace
}  // namespace frictionlab
