// The options table (app/command_line.h), which the window, run, check and render read their
// options through: each command takes exactly the options the table gives it and refuses the
// others with its usual message; the numbers keep to the table's ranges; the help names every
// option with its range; and the manual page, as the build writes it, describes every option
// the table has, under its command, with its value and range, and no other.
#include "app/command_line.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "physics/materials.h"

namespace frictionlab {
namespace {

// The commands whose parsers read the table; list, link and bench read their few options
// themselves, so only the help and the manual page are held to the table for them.
constexpr Command parsed[] = {Command::window, Command::run, Command::check, Command::render};

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
            "--substeps N, --friction T, --theme light|dark, --projector, --at S, --screenshot FILE.png, "
            "--mystery MATERIAL/MATERIAL --seed N, --setup FILE (commands: list, run, check, render, demo, bench, help)");
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
  EXPECT_EQ(options.rfind(".SS The window\n.TP\n.BI \\-\\-lock \" NAME[,NAME...]\"\n", 0), 0u) << options;
  EXPECT_NE(options.find("\n.TP\n.B \\-\\-projector\n"), std::string::npos);
  EXPECT_NE(options.find("\n.TP\n.BI \\-\\-hz \" N\"\nSteps per simulated second, from 1 to 100000 (default 240). "
                         "Also taken by run, check and render.\n"),
            std::string::npos)
      << options;
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

// An entry of the manual page's OPTIONS section: its subsection (.SS), its tag (the line after
// .TP) and its paragraph, in plain text.
struct ManualEntry {
  std::string section, tag, paragraph;
};

// roff as words: no macro name, no font changes, \- as -, no quotes.
std::string plain(std::string line) {
  if (!line.empty() && line[0] == '.') line.erase(0, std::min(line.size(), line.find(' ') + 1));
  std::string text;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == 'f') {
      i += 2;  // \fB, \fI, \fR, \fP
    } else if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '-') {
      text += '-';
      ++i;
    } else if (line[i] != '"') {
      text += line[i];
    }
  }
  return text;
}

std::string without_spaces(std::string text) {
  text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
  return text;
}

std::vector<ManualEntry> manual_options() {
  std::ifstream page(FRICTIONLAB_MAN_PAGE);
  EXPECT_TRUE(page) << FRICTIONLAB_MAN_PAGE;
  std::vector<ManualEntry> entries;
  std::string line, section;
  bool in_options = false, tag_next = false, in_entry = false;
  while (std::getline(page, line)) {
    if (line.rfind(".SH ", 0) == 0) {
      in_options = line == ".SH OPTIONS";
      in_entry = false;
    } else if (!in_options || line.rfind(".\\\"", 0) == 0) {
      continue;
    } else if (line.rfind(".SS ", 0) == 0) {
      section = line.substr(4);
      in_entry = false;
    } else if (line == ".TP") {
      tag_next = true;
    } else if (tag_next) {
      entries.push_back({section, without_spaces(plain(line)), ""});
      tag_next = false;
      in_entry = true;
    } else if (line.rfind(".PP", 0) == 0) {
      in_entry = false;  // a paragraph of the section's own
    } else if (in_entry) {
      entries.back().paragraph += plain(line) + " ";
    }
  }
  return entries;
}

// Whether the subsection's title names the command: "Lessons and steps (window, run, render)".
bool section_names(const std::string& section, Command command) {
  std::string word = std::string(command_name(command));
  word = word.substr(word.rfind(' ') + 1);  // "the window": window
  std::string lower = section;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (std::size_t at = lower.find(word); at != std::string::npos; at = lower.find(word, at + 1)) {
    const bool starts = at == 0 || !std::isalpha(static_cast<unsigned char>(lower[at - 1]));
    const std::size_t end = at + word.size();
    if (starts && (end == lower.size() || !std::isalpha(static_cast<unsigned char>(lower[end])))) return true;
  }
  return false;
}

bool section_names_one_of(const std::string& section, Command commands) {
  for (const Command command : {Command::window, Command::list, Command::run, Command::check, Command::render,
                                Command::link, Command::bench}) {
    if (includes(commands, command) && section_names(section, command)) return true;
  }
  return false;
}

std::string tag_of(const Option& option) { return without_spaces(std::string(option.name) + std::string(option.value)); }

TEST(ManualPage, DescribesEveryOptionUnderItsCommandWithItsValueAndRange) {
  const std::vector<ManualEntry> entries = manual_options();
  ASSERT_GT(entries.size(), 10u);
  for (const Option& option : options_table()) {
    SCOPED_TRACE(std::string(option.name) + " " + std::string(option.value));
    const auto entry = std::find_if(entries.begin(), entries.end(), [&](const ManualEntry& candidate) {
      return candidate.tag == tag_of(option) && section_names_one_of(candidate.section, option.commands);
    });
    ASSERT_NE(entry, entries.end()) << "not in the manual page's OPTIONS, under a section naming one of its commands";
    if (option.help.find("{range}") == std::string_view::npos) continue;
    // The range as the table gives it: "from 1 to 100000".
    EXPECT_NE(entry->paragraph.find(option.range_words()), std::string::npos) << entry->paragraph;
  }
}

TEST(ManualPage, DescribesNoOptionTheTableLacks) {
  for (const ManualEntry& entry : manual_options()) {
    SCOPED_TRACE(entry.section + ": " + entry.tag);
    const bool known = std::any_of(options_table().begin(), options_table().end(), [&](const Option& option) {
      return tag_of(option) == entry.tag && section_names_one_of(entry.section, option.commands);
    });
    EXPECT_TRUE(known) << "in the manual page's OPTIONS but not in the table (app/command_line.cpp), or under "
                          "another command";
  }
}

}  // namespace
}  // namespace frictionlab
